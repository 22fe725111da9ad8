"""A bag as the dashboard's timeline: the records of jason/mind, the dialogue and the
rason/* statuses at their recorded times; other topics and statuses left out; the bags of one
run recorded on several hosts as one timeline (no ROS master)."""
import os
import sys

import genpy
import pytest
import rosbag

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from dashboard_data import FLEET_STARTS, case_study_bag, diagnosis, fleet_bag, message, mind  # noqa: E402
from rason_dashboard.replay import load_bag, load_bags, merge_runs  # noqa: E402


@pytest.fixture
def bag(tmp_path):
    path = str(tmp_path / 'run.bag')
    case_study_bag(path)
    return path


def test_counts_and_span(bag):
    timeline, counts = load_bag(bag)
    assert counts == {'minds': 3, 'messages': 2, 'statuses': 1, 'poses': 0}
    assert timeline.mode == 'replay' and timeline.span() == pytest.approx((100.0, 109.0))


def test_view_at_times_of_the_run(bag):
    timeline, _ = load_bag(bag)
    early = timeline.view(101.0)
    helper = [r for r in early['robots'] if r['mas_id'] == '/helper/rason_mas'][0]['agents'][0]
    assert helper['beliefs'] == ['searching[source(self)]']
    assert helper['intentions'][0]['plans'] == ['p1: +!findRobot(faulty) <- turn(10)']
    assert helper['actions'][0]['action'] == 'turn(10)' and helper['actions'][0]['age'] == pytest.approx(1.4)
    assert [m['line'] for m in early['messages']] == ['faulty -> all: achieve helpme']
    assert early['statuses'] == []
    end = timeline.view()
    helper = [r for r in end['robots'] if r['mas_id'] == '/helper/rason_mas'][0]['agents'][0]
    assert helper['beliefs'] == ['found(faulty)[source(self)]']
    assert [m['line'] for m in end['messages']][-1] == 'helper -> faulty: tell found(faulty)'
    (status,) = end['statuses']
    assert (status['name'], status['level'], status['values']) == \
        ('rason/diagnosis', 'WARN', {'component': 'both_actuators'})


def test_a_file_that_is_not_a_bag_raises(tmp_path):
    junk = tmp_path / 'junk.bag'
    junk.write_bytes(b'not a bag at all')
    with pytest.raises(Exception):
        load_bag(str(junk))


def _host_bags(tmp_path, helper_offset=0.05):
    """A run recorded on two hosts: each robot's bag has its own mind and the dialogue as that
    robot saw it (the same messages, recorded helper_offset s apart); the diagnosis in Faulty's."""
    faulty_bag, helper_bag = str(tmp_path / 'faulty.bag'), str(tmp_path / 'helper.bag')
    with rosbag.Bag(faulty_bag, 'w') as bag:
        bag.write('/faulty/jason/mind', mind('/faulty/rason_mas', 100.0, 'faulty', ['stuck[source(self)]']),
                  genpy.Time.from_sec(100.0))
        bag.write('/rason/messages', message('faulty', '', 'achieve', 'helpme'), genpy.Time.from_sec(101.0))
        bag.write('/rason/messages', message('helper', 'faulty', 'tell', 'found(faulty)'), genpy.Time.from_sec(105.1))
        bag.write('/diagnostics', diagnosis('both_actuators'), genpy.Time.from_sec(109.0))
    with rosbag.Bag(helper_bag, 'w') as bag:
        bag.write('/helper/jason/mind', mind('/helper/rason_mas', 100.1, 'helper', ['searching[source(self)]']),
                  genpy.Time.from_sec(100.1))
        bag.write('/rason/messages', message('faulty', '', 'achieve', 'helpme'),
                  genpy.Time.from_sec(101.0 + helper_offset))
        bag.write('/helper/jason/mind', mind('/helper/rason_mas', 105.0, 'helper', ['found(faulty)[source(self)]']),
                  genpy.Time.from_sec(105.0))
        bag.write('/rason/messages', message('helper', 'faulty', 'tell', 'found(faulty)'),
                  genpy.Time.from_sec(105.1 + helper_offset))
    return faulty_bag, helper_bag


def test_bags_of_two_hosts_replay_as_one_run_with_each_message_once(tmp_path):
    faulty_bag, helper_bag = _host_bags(tmp_path)
    timeline, counts = load_bags([faulty_bag, helper_bag])
    assert counts == {'minds': 3, 'messages': 2, 'statuses': 1, 'poses': 0}
    end = timeline.view()
    assert [r['mas_id'] for r in end['robots']] == ['/faulty/rason_mas', '/helper/rason_mas']
    assert [m['line'] for m in end['messages']] == ['faulty -> all: achieve helpme', 'helper -> faulty: tell found(faulty)']
    early = timeline.view(102.0)
    helper = [r for r in early['robots'] if r['mas_id'] == '/helper/rason_mas'][0]['agents'][0]
    assert helper['beliefs'] == ['searching[source(self)]']
    assert load_bags([helper_bag, faulty_bag])[1] == counts


def test_a_bag_given_twice_is_the_run_once(tmp_path):
    path = str(tmp_path / 'run.bag')
    case_study_bag(path)
    assert load_bags([path, path])[1] == load_bag(path)[1]


def test_messages_repeated_in_one_bag_or_far_apart_are_not_merged(tmp_path):
    faulty_bag, helper_bag = _host_bags(tmp_path, helper_offset=5.0)
    _, counts = load_bags([faulty_bag, helper_bag])
    assert counts['messages'] == 4       # 5 s apart: other sends of the same content
    records = [('message', 1.0, {'sender_mas': '/a', 'sender': 'a', 'receiver': 'b', 'performative': 'tell',
                                 'content': 'ping'})]
    twice = records + [('message', 1.2, dict(records[0][2]))]
    assert len(merge_runs([twice, records])) == 2   # the second bag's copy matches one of the two
    assert len(merge_runs([twice])) == 2


def test_a_fleet_bag_has_every_robots_poses_and_who_helps_whom(tmp_path):
    path = str(tmp_path / 'fleet.bag')
    fleet_bag(path, t0=200.0)
    timeline, counts = load_bag(path)
    assert counts['minds'] == 4 and counts['messages'] == 10
    assert counts['poses'] == 4 * 2 * 101 + 4  # true and odometry at 10 Hz for 10 s, /tf_static
    before, during, after = timeline.view(202.0), timeline.view(205.0), timeline.view()
    assert before['helps'] == [] and after['helps'] == []  # awarded at 2.5 s, released at 9 s
    assert [(h['helper'], h['helped']) for h in during['helps']] == [('r1', 'r4')]
    assert sorted(during['poses']) == sorted(FLEET_STARTS)
    r1 = after['poses']['r1']
    assert (r1['true']['x'], r1['true']['y']) == pytest.approx((1.0, 0.0), abs=1e-3)  # drove 1 m to r4's side
    assert (r1['believed']['x'], r1['believed']['y']) == pytest.approx((0.9, 0.0), abs=1e-3)  # odometry 10 % long
