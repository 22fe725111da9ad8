"""A bag as the dashboard's timeline: the records of jason/mind, the dialogue and the
rason/* statuses at their recorded times; other topics and statuses left out (no ROS master)."""
import os
import sys

import pytest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from dashboard_data import case_study_bag  # noqa: E402
from rason_dashboard.replay import load_bag  # noqa: E402


@pytest.fixture
def bag(tmp_path):
    path = str(tmp_path / 'run.bag')
    case_study_bag(path)
    return path


def test_counts_and_span(bag):
    timeline, counts = load_bag(bag)
    assert counts == {'minds': 3, 'messages': 2, 'statuses': 1}
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
