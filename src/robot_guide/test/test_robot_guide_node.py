"""The node adapter with rospy, tf2 and the Decomposer faked (no ROS master): what goes out
on located/<name>, jason/perception and cmd_vel, and how guide(Name, Seconds) answers."""
import math

import pytest
import rospy
import tf2_ros
from geometry_msgs.msg import TransformStamped
from rason_msgs.msg import Event, RobotSighting, RobotSightings

from robot_guide import node, settings

CAMERA = 'helper/camera_rgb_optical_frame'


class FakePublisher(object):
    def __init__(self, topic, msg_class, **_):
        self.topic, self.msg_class, self.sent = topic, msg_class, []

    def publish(self, msg):
        self.sent.append(msg)


class FakeDecomposer(object):
    def __init__(self, actions, on_start, on_cancel, **_):
        self.actions, self.on_start, self.on_cancel = actions, on_start, on_cancel
        self.answers = []      # (action_id, result, how)

    def refuse(self, action, reason):
        self.answers.append((action.action_id, reason, 'refuse'))

    def finish(self, action, result):
        self.answers.append((action.action_id, result, 'finish'))


class Action(object):
    def __init__(self, action_id, *parameters):
        self.agent, self.action_id, self.name = 'helper', action_id, 'guide'
        self.parameters = list(parameters)


class FakeTf(object):
    """The camera of a base at (x, y, yaw) in helper/odom, or no transform at all."""

    def __init__(self):
        self.base = (0.0, 0.0, 0.0)
        self.asked = []

    def lookup_transform(self, target, source, stamp, timeout=None):
        if timeout is not None:     # the tick's lookups (the newest, no wait) are not recorded
            self.asked.append((target, source, stamp.to_sec(), timeout.to_sec()))
        if self.base is None:
            raise tf2_ros.LookupException('"helper/odom" passed to lookupTransform does not exist')
        x, y, yaw = self.base
        t = TransformStamped()
        t.transform.translation.x = x + 0.08 * math.cos(yaw)
        t.transform.translation.y = y + 0.08 * math.sin(yaw)
        t.transform.translation.z = 0.3
        # base yaw, then the optical frame (z forward, x right, y down)
        c, s = math.cos(yaw / 2), math.sin(yaw / 2)
        ox, oy, oz, ow = -0.5, 0.5, -0.5, 0.5
        t.transform.rotation.x = c * ox - s * oy
        t.transform.rotation.y = c * oy + s * ox
        t.transform.rotation.z = c * oz + s * ow
        t.transform.rotation.w = c * ow - s * oz
        return t


class Ros(object):
    def __init__(self, monkeypatch):
        self.now = 100.0
        self.publishers, self.subscribers, self.warnings = {}, {}, []

        def publisher(topic, msg_class, **kw):
            self.publishers[topic] = FakePublisher(topic, msg_class, **kw)
            return self.publishers[topic]

        def subscriber(topic, msg_class, callback, **kw):
            self.subscribers[topic] = (callback, kw)

        monkeypatch.setattr(rospy, 'Publisher', publisher)
        monkeypatch.setattr(rospy, 'Subscriber', subscriber)
        monkeypatch.setattr(rospy, 'Timer', lambda period, callback: None)
        monkeypatch.setattr(rospy, 'get_time', lambda: self.now)
        monkeypatch.setattr(rospy, 'logwarn_throttle', lambda _p, text: self.warnings.append(text))
        monkeypatch.setattr(node, 'Decomposer', FakeDecomposer)
        self.tf = FakeTf()
        options = settings.check({}, '/helper/', '/helper/robot_guide')
        self.node = node.RobotGuideNode(options, self.tf)
        self.decomposer = self.node._decomposer

    def see(self, *robots, stamp=None):
        """One frame with robots (name, angle, depth, yaw), handled at self.now."""
        msg = RobotSightings(robots=[RobotSighting(*r) for r in robots])
        msg.header.stamp = rospy.Time.from_sec(self.now - 0.05 if stamp is None else stamp)
        msg.header.frame_id = CAMERA
        self.subscribers['robots_seen'][0](msg)

    def tick(self, now):
        self.now = now
        self.node._tick()

    def sent(self, topic):
        return self.publishers[topic].sent if topic in self.publishers else []

    def turns(self):
        return [m.angular.z for m in self.sent('cmd_vel')]

    def perceptions(self):
        return [list(m.perception) for m in self.sent('jason/perception')]


@pytest.fixture
def ros(monkeypatch):
    return Ros(monkeypatch)


def test_a_seen_robot_is_located_in_odom_at_the_clouds_stamp(ros):
    ros.tf.base = (1.0, 2.0, math.pi / 2)
    ros.see(('faulty', 20.0, 1.0, 110.0), stamp=99.9)
    assert ros.tf.asked == [('helper/odom', CAMERA, pytest.approx(99.9), 0.2)]
    pose, = ros.sent('located/faulty')
    assert pose.header.frame_id == 'helper/odom' and pose.header.stamp == rospy.Time.from_sec(99.9)
    assert pose.pose.position.x == pytest.approx(1.0 + math.tan(math.radians(20)))
    assert pose.pose.position.y == pytest.approx(3.08) and pose.pose.position.z == 0.0
    assert (pose.pose.orientation.z, pose.pose.orientation.w) == pytest.approx((0.0, 1.0))
    assert ros.perceptions() == [['located(faulty,1.364,3.08,0)']]
    assert ros.sent('jason/perception')[0].source == 'robot_guide_located'
    assert ros.sent('cmd_vel') == []      # no guide: nothing commanded


def test_the_perception_is_rate_limited_and_the_newest_list_goes_out_late(ros):
    ros.see(('faulty', 0.0, 2.0, 0.0))
    ros.now = 100.1
    ros.see(('faulty', 0.0, 1.5, 0.0))
    ros.now = 100.15
    ros.see()                                  # nobody: the empty list replaces the held one
    assert ros.perceptions() == [['located(faulty,2.08,0,0)']]
    ros.tick(100.19)
    assert len(ros.perceptions()) == 1
    ros.tick(100.2)                            # 5 Hz: 0.2 s after the last list
    assert ros.perceptions() == [['located(faulty,2.08,0,0)'], []]
    assert len(ros.sent('located/faulty')) == 2    # the poses go out with every frame


def test_without_the_cameras_pose_nobody_is_located(ros):
    ros.tf.base = None
    ros.see(('faulty', 0.0, 2.0, 0.0))
    assert ros.sent('located/faulty') == [] and ros.perceptions() == [[]]
    assert len(ros.warnings) == 1 and 'no pose of %s in helper/odom' % CAMERA in ros.warnings[0]


def test_bad_sightings_and_names_are_skipped_with_a_warning(ros):
    ros.see(('Faulty', 0.0, 2.0, 0.0), ('faulty', 0.0, -1.0, 0.0), ('other', 5.0, 2.0, 5.0))
    assert ros.perceptions() == [['located(other,2.08,-0.175,0)']]
    assert set(ros.publishers) >= {'located/other'} and 'located/faulty' not in ros.publishers
    assert len(ros.warnings) == 2


def test_guide_turns_toward_where_the_robot_was_seen_as_the_base_turns(ros):
    ros.decomposer.on_start(Action(7, 'faulty', '5'))
    assert ros.decomposer.answers == []
    ros.tick(100.05)
    assert ros.turns() == [0.0]                    # nothing seen yet
    ros.see(('faulty', 5.0, 2.0, 5.0))             # right: turn clockwise (negative)
    ros.tick(100.1)
    assert ros.turns()[-1] == pytest.approx(-3.0 * math.radians(5.0), rel=0.02)
    ros.tf.base = (0.0, 0.0, math.radians(-2.0))   # turned 2 deg toward it: 3 deg to go
    ros.tick(100.15)
    assert ros.turns()[-1] == pytest.approx(-3.0 * math.radians(3.0), rel=0.03)
    ros.tf.base = (0.0, 0.0, math.radians(-4.5))   # centred, without a new frame
    ros.tick(100.2)
    assert ros.turns()[-1] == 0.0


def test_guide_ends_ok_with_a_zero_twist_and_then_commands_nothing(ros):
    ros.decomposer.on_start(Action(7, 'faulty', '5'))
    for now in (100.1, 102.0, 104.0):
        ros.now = now
        ros.see(('faulty', 10.0, 2.0, 10.0))
        ros.tick(now + 0.05)
    ros.tick(104.99)
    assert ros.decomposer.answers == []
    assert all(t == pytest.approx(-0.4) for t in ros.turns())
    ros.tick(105.0)
    assert ros.decomposer.answers == [(7, Event.OK, 'finish')]
    assert ros.turns()[-1] == 0.0 and len(ros.turns()) == 5
    ros.see(('faulty', 20.0, 2.0, 20.0))           # after the end: nothing commanded
    ros.tick(105.05)
    assert len(ros.turns()) == 5


def test_guide_fails_lost_when_the_robot_is_not_seen_for_lost_after(ros):
    ros.decomposer.on_start(Action(8, 'faulty', '10'))
    ros.now = 101.0
    ros.see(('faulty', 0.0, 2.0, 0.0))
    ros.tick(102.9)
    ros.see(('other', 0.0, 2.0, 0.0))
    ros.tick(102.99)
    assert ros.decomposer.answers == []
    ros.tick(103.0)
    assert ros.decomposer.answers == [(8, Event.LOST, 'finish')]
    assert ros.turns() == [0.0, 0.0, 0.0]


def test_without_the_cameras_pose_it_turns_by_the_frames_angle(ros):
    ros.decomposer.on_start(Action(9, 'faulty', '10'))
    ros.tf.base = None
    ros.see(('faulty', -5.0, 2.0, -5.0))
    ros.tick(100.05)
    assert ros.turns() == [pytest.approx(3.0 * math.radians(5.0))]
    ros.see()
    ros.tick(100.1)
    assert ros.turns()[-1] == 0.0


def test_a_second_guide_is_refused_busy_and_the_first_goes_on(ros):
    ros.decomposer.on_start(Action(1, 'faulty', '5'))
    ros.decomposer.on_start(Action(2, 'faulty', '3'))
    assert ros.decomposer.answers == [(2, Event.BUSY, 'refuse')]
    ros.see(('faulty', -10.0, 2.0, -10.0))
    ros.tick(100.05)
    assert ros.turns() == [pytest.approx(0.4)]
    ros.tick(105.0)
    assert ros.decomposer.answers[-1] == (1, Event.OK, 'finish')


@pytest.mark.parametrize('parameters', [('Faulty', '5'), ('faulty', '0'), ('faulty', 'inf'),
                                        ('faulty',)])
def test_bad_arguments_are_refused_and_nothing_runs(ros, parameters):
    ros.decomposer.on_start(Action(3, *parameters))
    assert ros.decomposer.answers == [(3, Event.BAD_PARAMETERS, 'refuse')]
    ros.see(('faulty', 10.0, 2.0, 10.0))
    ros.tick(100.05)
    assert ros.turns() == []
    ros.decomposer.on_start(Action(4, 'faulty', '1'))   # not busy afterwards
    assert len(ros.decomposer.answers) == 1


def test_a_cancel_stops_at_once_with_a_zero_twist(ros):
    action = Action(5, 'faulty', '5')
    ros.decomposer.on_start(action)
    ros.see(('faulty', 15.0, 2.0, 15.0))
    ros.tick(100.05)
    ros.decomposer.on_cancel(action, Event.DROPPED)
    assert ros.turns() == [pytest.approx(-0.4), 0.0]
    ros.see(('faulty', 15.0, 2.0, 15.0))
    ros.tick(100.1)
    ros.tick(106.0)
    assert ros.turns() == [pytest.approx(-0.4), 0.0] and ros.decomposer.answers == []


def test_a_cancel_of_another_or_an_ended_guide_changes_nothing(ros):
    running = Action(5, 'faulty', '5')
    ros.decomposer.on_start(running)
    ros.decomposer.on_cancel(Action(6, 'faulty', '5'), Event.DROPPED)
    assert ros.turns() == []
    ros.tick(105.0)
    ros.decomposer.on_cancel(running, Event.DROPPED)     # finished a moment ago
    assert ros.turns() == [0.0]
