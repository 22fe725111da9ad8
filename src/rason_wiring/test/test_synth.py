"""Unit tests of rason_wiring.synth: ~perceptions checked into syntheses, literals made of
messages (paths, conversions, conditions), and the gate (rate limit, only when changed,
refresh). No ROS master: real message classes."""
import copy
import math

import pytest
from nav_msgs.msg import Odometry
from sensor_msgs.msg import BatteryState
from std_msgs.msg import String

from rason_wiring import synth
from rason_wiring.config import ConfigError
from rason_wiring.ros_types import Resolver

ODOM = {
    'topic': 'odom', 'type': 'nav_msgs/Odometry',
    'literals': {
        'pos(X, Y, Yaw)': {'X': 'pose.pose.position.x',
                           'Y': {'field': 'pose.pose.position.y', 'round': 2},
                           'Yaw': {'field': 'pose.pose.orientation', 'convert': 'yaw_deg', 'round': 1}},
        'moving': {'when': {'field': 'twist.twist.linear.x', 'gt': 0.01}},
    },
}


def parse(perceptions, **kw):
    return synth.parse(copy.deepcopy(perceptions), Resolver(), **kw)


def one(spec, entry='odometry'):
    return parse({entry: spec})[0]


def refused(spec, entry='odometry'):
    with pytest.raises(ConfigError) as e:
        parse({entry: spec})
    text = str(e.value)
    assert text.startswith(entry + ': '), 'the error names the entry: ' + text
    return text


def odometry(x=0.0, y=0.0, yaw=0.0, speed=0.0):
    msg = Odometry()
    msg.pose.pose.position.x, msg.pose.pose.position.y = x, y
    msg.pose.pose.orientation.z, msg.pose.pose.orientation.w = math.sin(yaw / 2), math.cos(yaw / 2)
    msg.twist.twist.linear.x = speed
    return msg


# ---------------------------------------------------------------- literals

def test_an_entry_gets_its_class_source_and_defaults():
    s = one(ODOM)
    assert (s.topic, s.msg_class, s.source) == ('odom', Odometry, 'odometry')
    assert (s.max_rate, s.only_changed, s.refresh) == (synth.DEFAULT_MAX_RATE, True, synth.DEFAULT_REFRESH)
    assert one(ODOM, 'odometry').source == 'odometry'
    assert parse({'odometry': ODOM}, default_source=lambda e: 'synth_' + e)[0].source == 'synth_odometry'
    assert one(dict(ODOM, source='odom')).source == 'odom'


def test_literals_from_paths_with_rounding_and_the_yaw_of_a_quaternion():
    s = one(ODOM)
    assert s.literals(odometry(1.5, -0.333, math.radians(90))) == ['pos(1.5,-0.33,90.0)']
    assert s.literals(odometry(2.0, 0.5, math.radians(-45), speed=0.2)) == ['pos(2.0,0.5,-45.0)', 'moving']


@pytest.mark.parametrize('reader, expected', [
    ({'field': 'pose.pose.orientation', 'convert': 'yaw'}, math.pi / 2),
    ({'field': 'twist.twist.angular.z', 'convert': 'rad_to_deg'}, 180.0),
    ({'field': 'twist.twist.angular.z', 'convert': 'rad_to_deg', 'scale': 2, 'offset': -1}, 359.0),
    ({'field': 'twist.twist.angular.z', 'scale': 100, 'round': 0}, 314),
    ({'field': 'twist.twist.angular.z', 'convert': 'deg_to_rad', 'round': 4}, 0.0548),
    ({'value': 'base'}, 'base'),
    ({'field': 'child_frame_id'}, 'robot/base'),
])
def test_each_reader(reader, expected):
    s = one({'topic': 'odom', 'type': 'nav_msgs/Odometry', 'literals': {'v(A)': {'A': reader}}})
    msg = odometry(yaw=math.pi / 2)
    msg.twist.twist.angular.z = math.pi
    msg.child_frame_id = 'robot/base'
    (literal,) = s.literals(msg)
    value = literal[2:-1]
    if isinstance(expected, str):
        assert value == '"%s"' % expected
    elif isinstance(expected, int):
        assert value == str(expected)
    else:
        assert float(value) == pytest.approx(expected, abs=1e-9)


@pytest.mark.parametrize('condition, holds', [
    ({'field': 'percentage', 'lt': 0.2}, True),
    ({'field': 'percentage', 'ge': 0.2}, False),
    ({'field': 'percentage', 'scale': 100, 'le': 15}, True),
    ({'field': 'power_supply_status', 'eq': 3}, True),     # a uint8 against an int
    ({'field': 'power_supply_status', 'ne': 3}, False),
    ({'field': 'present', 'eq': True}, True),
    ({'field': 'location', 'eq': 'dock'}, False),
    ([{'field': 'percentage', 'lt': 0.2}, {'field': 'present', 'eq': True}], True),
    ([{'field': 'percentage', 'lt': 0.2}, {'field': 'present', 'eq': False}], False),
])
def test_conditions(condition, holds):
    s = one({'topic': 'battery', 'type': 'sensor_msgs/BatteryState',
             'literals': {'battery_low': {'when': condition}}})
    msg = BatteryState(percentage=0.125, power_supply_status=3, present=True, location='shelf')
    assert s.literals(msg) == (['battery_low'] if holds else [])


def test_a_literal_without_arguments_or_condition_is_always_there():
    s = one({'topic': 'speech', 'type': 'std_msgs/String', 'literals': {'heard': None, 'said(T)': {'T': 'data'}}})
    assert s.literals(String('hi "you"')) == ['heard', 'said("hi \\"you\\"")']


def test_two_entries_with_one_source_are_refused():
    with pytest.raises(ConfigError, match=r'^b: source s is also the source of a'):
        parse({'a': dict(ODOM, source='s'), 'b': dict(ODOM, source='s')})


# ---------------------------------------------------------------- malformed entries

@pytest.mark.parametrize('change, message', [
    ({'type': 'nav_msgs/Odometri'}, "unknown message type 'nav_msgs/Odometri'"),
    ({'topic': ''}, 'topic is missing'),
    ({'rate': 5}, 'unknown key rate'),
    ({'source': 'Odom'}, "source 'Odom' is not a Jason atom"),
    ({'max_rate': -1}, 'max_rate: a number >= 0 is needed'),
    ({'refresh': 'often'}, 'refresh: a number >= 0 is needed'),
    ({'only_changed': 'yes'}, 'only_changed: true or false is needed'),
    ({'literals': {}}, 'literals: a dict'),
    ({'literals': {'Pos(X)': {'X': 'pose.pose.position.x'}}}, "odometry: literal Pos(X): functor 'Pos' is not a Jason atom"),
    ({'literals': {'pos(X, Y)': {'X': 'pose.pose.position.x'}}}, 'literal pos(X, Y): argument Y is read from no field'),
    ({'literals': {'pos(X)': {'X': 'pose.pose.position.x', 'Z': 'pose.pose.position.z'}}}, 'unknown key Z'),
    ({'literals': {'pos(X)': {'X': 'pose.pose.postion.x'}}}, "argument X: bad field path pose.pose.postion.x: pose.pose has no field 'postion'"),
    ({'literals': {'pos(X)': {'X': 'pose.pose'}}}, 'pose.pose is a message (geometry_msgs/Pose)'),
    ({'literals': {'pos(X)': {'X': {'field': 'pose.pose.position.x', 'convert': 'furlongs'}}}}, "unknown conversion 'furlongs'"),
    ({'literals': {'pos(X)': {'X': {'field': 'pose.pose.position', 'convert': 'yaw'}}}},
     'conversion yaw reads a geometry_msgs/Quaternion, and pose.pose.position is a geometry_msgs/Point'),
    ({'literals': {'pos(X)': {'X': {'field': 'child_frame_id', 'convert': 'rad_to_deg'}}}}, 'conversion rad_to_deg reads a number'),
    ({'literals': {'pos(X)': {'X': {'field': 'child_frame_id', 'scale': 2}}}}, 'scale, offset and round need a number'),
    ({'literals': {'pos(X)': {'X': {'field': 'pose.pose.position.x', 'round': 1.5}}}}, 'round: a number of decimals'),
    ({'literals': {'pos(X)': {'X': {'field': 'pose.pose.position.x', 'scale': 'big'}}}}, 'scale: a number is needed'),
    ({'literals': {'pos(X)': {'X': {'fild': 'pose.pose.position.x'}}}}, 'unknown key fild'),
    ({'literals': {'moving': {'when': {'field': 'twist.twist.linear.x'}}}}, 'with one OP of eq, ge, gt, le, lt, ne'),
    ({'literals': {'moving': {'when': {'field': 'twist.twist.linear.x', 'gt': 'fast'}}}}, 'when: gt: a number is needed'),
    ({'literals': {'moving': {'when': {'field': 'child_frame_id', 'gt': 1}}}}, 'when: gt compares numbers'),
    ({'literals': {'moving': {'when': {'value': 1, 'gt': 0}}}}, 'when: a field to compare is needed'),
    ({'literals': {'moving': {True: 'pose.pose.position.x'}}}, 'quote an argument named On, Off, Yes or No'),
])
def test_each_error_names_the_entry_and_what_is_wrong(change, message):
    assert message in refused(dict(ODOM, **change))


def test_no_perceptions_at_all_is_refused():
    with pytest.raises(ConfigError, match=r'^~perceptions'):
        synth.parse({}, Resolver())


# ---------------------------------------------------------------- gate

def test_the_gate_limits_the_rate_and_publishes_the_newest_held_list_when_the_interval_is_over():
    gate = synth.Gate(max_rate=2, only_changed=False, refresh=0)
    assert gate.offer(['a'], 10.0) == ['a']
    assert gate.offer(['b'], 10.1) is None
    assert gate.offer(['c'], 10.2) is None
    assert gate.poll(10.4) is None
    assert gate.poll(10.5) == ['c']          # the newest, not b
    assert gate.poll(10.6) is None           # nothing held
    assert gate.offer(['d'], 11.0) == ['d']  # the interval is over again


def test_without_only_changed_an_equal_list_counts_as_new():
    gate = synth.Gate(max_rate=0, only_changed=False, refresh=0)
    assert gate.offer(['a'], 1.0) == ['a']
    assert gate.offer(['a'], 1.0) == ['a']


def test_only_changed_drops_equal_lists_and_a_held_list_that_went_back():
    gate = synth.Gate(max_rate=0, only_changed=True, refresh=0)
    assert gate.offer(['a'], 1.0) == ['a']
    assert gate.offer(['a'], 1.1) is None
    assert gate.offer([], 1.2) == []          # an empty list is a change too (it clears)
    limited = synth.Gate(max_rate=1, only_changed=True, refresh=0)
    assert limited.offer(['a'], 1.0) == ['a']
    assert limited.offer(['b'], 1.5) is None  # held...
    assert limited.offer(['a'], 1.7) is None  # ...and back to what was published
    assert limited.poll(2.5) is None


def test_refresh_republishes_an_unchanged_list_only_while_the_topic_goes_on():
    gate = synth.Gate(max_rate=0, only_changed=True, refresh=1.0)
    assert gate.offer(['a'], 1.0) == ['a']
    assert gate.poll(2.5) is None             # nothing heard since: the topic may be gone
    assert gate.offer(['a'], 2.6) is None
    assert gate.poll(2.7) == ['a']            # heard, and over a second since
    assert gate.poll(4.0) is None


def test_a_clock_that_jumps_back_counts_as_every_interval_over():
    gate = synth.Gate(max_rate=1, only_changed=False, refresh=0)
    assert gate.offer(['a'], 100.0) == ['a']
    assert gate.offer(['b'], 3.0) == ['b']
