#!/usr/bin/python3
"""robot_guide on the simulator, with the helper's camera and vision_synth: ``located/faulty``
against the faulty robot's true pose mapped into the helper's odometry frame (0.05 m, 5 deg);
``guide(faulty, 5)`` keeping the faulty robot within 5 deg of the camera's centre while it
drives sideways, ending OK with nothing on cmd_vel afterwards; lost, cancelled, busy and bad
arguments."""
import bisect
import math
import os
import re
import sys
import threading
import time
import unittest

import rason_rospy

import rospy
import rostest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), 'nodes'))
from sim_testing import SimRobot, camera_truth, relative, yaw_of  # noqa: E402
from geometry_msgs.msg import PoseStamped, Twist  # noqa: E402
from nav_msgs.msg import Odometry  # noqa: E402
from rason_msgs.msg import Action, Event, Perception  # noqa: E402

AGENT = 'helper'
LOCATED = re.compile(r'^located\(faulty,(-?[\d.]+),(-?[\d.]+),(-?[\d.]+)\)$')
HELPER = (-2.0, 0.0, 0.0)


def compose(a, b):
    """Pose ``b`` given in the frame of pose ``a`` (x, y, yaw), in ``a``'s parent frame."""
    x, y, yaw = a
    return (x + b[0] * math.cos(yaw) - b[1] * math.sin(yaw),
            y + b[0] * math.sin(yaw) + b[1] * math.cos(yaw), yaw + b[2])


def inverse(a):
    x, y, yaw = a
    return (-x * math.cos(yaw) - y * math.sin(yaw), x * math.sin(yaw) - y * math.cos(yaw), -yaw)


def angle_diff(a, b):
    return math.remainder(a - b, 2 * math.pi)


class Stamped(object):
    """(sim stamp, x, y, yaw) of a topic, kept in stamp order, looked up by nearest stamp."""

    def __init__(self, topic, msg_class, pose_of):
        self._cond = threading.Condition()
        self._stamps, self._poses = [], []
        self._pose_of = pose_of
        rospy.Subscriber(topic, msg_class, self._on_msg, queue_size=200)

    def _on_msg(self, msg):
        with self._cond:
            self._stamps.append(msg.header.stamp.to_sec())
            self._poses.append(self._pose_of(msg))
            del self._stamps[:-5000], self._poses[:-5000]
            self._cond.notify_all()

    def at(self, stamp, within=0.011):
        """The pose stamped nearest to ``stamp`` (waits for it), or None."""
        deadline = time.monotonic() + 10.0
        with self._cond:
            while (not self._stamps or self._stamps[-1] < stamp) and time.monotonic() < deadline:
                self._cond.wait(0.1)
            i = bisect.bisect_left(self._stamps, stamp)
            near = [j for j in (i - 1, i) if 0 <= j < len(self._stamps)]
            if not near:
                return None
            j = min(near, key=lambda k: abs(self._stamps[k] - stamp))
            return self._poses[j] if abs(self._stamps[j] - stamp) <= within else None

    def since(self, stamp, until=float('inf')):
        with self._cond:
            return [(s, p) for s, p in zip(self._stamps, self._poses) if stamp <= s <= until]

    def wait_for(self, stamp, count=1, timeout=20.0):
        """The first ``count`` entries stamped ``stamp`` or later (the first one alone for 1)."""
        deadline = time.monotonic() + timeout
        with self._cond:
            while time.monotonic() < deadline:
                i = bisect.bisect_left(self._stamps, stamp)
                if i + count <= len(self._stamps):
                    found = list(zip(self._stamps[i:i + count], self._poses[i:i + count]))
                    return found[0] if count == 1 else found
                self._cond.wait(0.1)
        raise AssertionError('not %d stamped %.2f s or later' % (count, stamp))


def pose_of_stamped(msg):
    return (msg.pose.position.x, msg.pose.position.y, yaw_of(msg.pose.orientation))


def pose_of_odometry(msg):
    return pose_of_stamped(msg.pose)


class Twists(object):
    """Every twist on /helper/cmd_vel: (sim time heard, linear x, angular z), and the wall
    clock (monotonic) when each was heard."""

    def __init__(self):
        self._lock = threading.Lock()
        self.heard, self.wall = [], []
        rospy.Subscriber('/helper/cmd_vel', Twist, self._on_msg, queue_size=200)

    def _on_msg(self, msg):
        with self._lock:
            self.heard.append((rospy.get_time(), msg.linear.x, msg.angular.z))
            self.wall.append(time.monotonic())

    def since(self, stamp):
        with self._lock:
            return [h for h in self.heard if h[0] >= stamp]

    def first_zero_after(self, wall_time, timeout=5.0):
        """Seconds (wall) from ``wall_time`` to the first zero twist heard after it, or None."""
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            with self._lock:
                for heard, at in zip(self.heard, self.wall):
                    if at >= wall_time and heard[1:] == (0.0, 0.0):
                        return at - wall_time
            time.sleep(0.005)
        return None


class Guide(object):
    """guide actions on /helper/jason/action and their answers on /helper/jason/event."""

    def __init__(self):
        self._cond = threading.Condition()
        self._next = 5000
        self.events = {}     # action_id -> [(event_type, result, sim time)]
        self._pub = rospy.Publisher('/helper/jason/action', Action, queue_size=10)
        rospy.Subscriber('/helper/jason/event', Event, self._on_event, queue_size=100)

    def _on_event(self, msg):
        if msg.agent != AGENT:
            return
        if msg.event_type == Event.ACTION_FEEDBACK and len(msg.parameters) == 2:
            key, value = msg.parameters[1], msg.parameters[0]
        elif msg.event_type == Event.ACTION_STARTED and len(msg.parameters) == 1:
            key, value = msg.parameters[0], None
        else:
            return
        with self._cond:
            self.events.setdefault(int(key), []).append((msg.event_type, value, rospy.get_time()))
            self._cond.notify_all()

    def connected(self, timeout=20.0):
        deadline = time.monotonic() + timeout
        while not self._pub.get_num_connections() and time.monotonic() < deadline:
            time.sleep(0.05)
        return self._pub.get_num_connections() > 0

    def send(self, *parameters):
        self._next += 1
        self._pub.publish(Action(agent=AGENT, action_id=self._next, action='guide',
                                 parameters=[str(p) for p in parameters]))
        return self._next

    def cancel(self, action_id, reason=Event.DROPPED):
        self._pub.publish(Action(agent=AGENT, action_id=action_id, action=Action.CANCEL,
                                 parameters=[reason]))

    def started(self, action_id, timeout=10.0):
        return self._wait(action_id, Event.ACTION_STARTED, timeout)

    def result(self, action_id, timeout=30.0):
        """(result, sim time) of the action's feedback, or None."""
        return self._wait(action_id, Event.ACTION_FEEDBACK, timeout)

    def _wait(self, action_id, event_type, timeout):
        deadline = time.monotonic() + timeout
        with self._cond:
            while time.monotonic() < deadline:
                for kind, value, stamp in self.events.get(action_id, []):
                    if kind == event_type:
                        return value, stamp
                self._cond.wait(0.1)
        return None


class TestSimGuide(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        rason_rospy.init_node('test_sim_guide')
        cls.helper = SimRobot('helper')
        cls.faulty = SimRobot('faulty')
        cls.helper_odom = Stamped('/helper/odom', Odometry, pose_of_odometry)
        cls.helper_true = Stamped('/helper/true_pose', PoseStamped, pose_of_stamped)
        cls.faulty_true = Stamped('/faulty/true_pose', PoseStamped, pose_of_stamped)
        cls.located = Stamped('/helper/located/faulty', PoseStamped, pose_of_stamped)
        cls.twists = Twists()
        cls.guide = Guide()
        cls.drive = rospy.Publisher('/faulty/cmd_vel', Twist, queue_size=10)
        cls.perception_lock = threading.Lock()
        cls.perceptions = []    # (sim time, literals) of robot_guide's source
        rospy.Subscriber('/helper/jason/perception', Perception, cls._on_perception, queue_size=100)
        assert cls.guide.connected(), 'robot_guide does not listen to /helper/jason/action'

    @classmethod
    def _on_perception(cls, msg):
        if msg.source == 'robot_guide_located':
            with cls.perception_lock:
                cls.perceptions.append((rospy.get_time(), list(msg.perception)))

    def setUp(self):
        self.drive.publish(Twist())

    def place(self, helper, ahead, left, heading):
        """Helper at ``helper`` (world); the faulty robot ``ahead`` and ``left`` of it, turned
        ``heading`` from the helper's heading. Returns the sim time once both are still, after
        robot_guide has located the faulty robot in a frame rendered since (so a test starts
        with the camera, vision_synth and robot_guide all running, however loaded the machine)."""
        self.helper.teleport(*helper, settle=0.0)
        x, y = relative(helper, ahead, left)
        self.faulty.teleport(x, y, helper[2] + heading, settle=0.3)
        settled = rospy.get_time()
        self.located.wait_for(settled, timeout=30.0)
        return settled

    def truth_in_helper_odom(self, stamp):
        """The faulty robot's true pose at ``stamp`` in the helper's odometry frame: world ->
        odom from the helper's true pose and its odometry at the same stamp (its odom frame
        is where it started, and a teleport does not move its odometry)."""
        base_world, base_odom = self.helper_true.at(stamp), self.helper_odom.at(stamp)
        faulty = self.faulty_true.at(stamp)
        self.assertTrue(None not in (base_world, base_odom, faulty), 'no poses at %.2f' % stamp)
        world_from_odom = compose(base_world, inverse(base_odom))
        return compose(inverse(world_from_odom), faulty)

    def test_located_agrees_with_the_true_pose_in_the_helpers_odom_frame(self):
        cases = [  # helper's world pose; faulty ahead, left (m), heading from the helper's (rad)
            (HELPER, 1.5, 0.0, 0.0),                     # straight ahead, facing away
            (HELPER, 2.0, -0.5, math.pi / 2),            # to the right, facing left
            (HELPER, 1.2, 0.35, -math.pi / 2),           # to the left, facing right
            (HELPER, 2.5, 0.3, math.pi - 0.3),           # facing the camera
            ((-2.0, 0.5, 0.6), 1.8, 0.2, 0.4),           # the helper turned in its odom frame
            ((-1.0, -1.0, -2.2), 1.6, -0.3, -1.0),
        ]
        started = rospy.get_time()
        worst = [0.0, 0.0]
        for helper, ahead, left, heading in cases:
            settled = self.place(helper, ahead, left, heading)
            where = 'helper %s, faulty %.1f ahead %.2f left heading %.2f' % (helper, ahead, left,
                                                                             heading)
            samples = self.located.wait_for(settled + 0.2, count=3)
            # robot_guide offers a frame's list to its rate gate after publishing its poses: a
            # list heard from now on is of one of these frames or a newer one
            heard_after = rospy.get_time()
            for stamp, seen in samples:
                truth = self.truth_in_helper_odom(stamp)
                dist = math.hypot(seen[0] - truth[0], seen[1] - truth[1])
                turn = abs(math.degrees(angle_diff(seen[2], truth[2])))
                worst = [max(worst[0], dist), max(worst[1], turn)]
                self.assertLess(dist, 0.05, '%s: seen %s, truth %s' % (where, seen, truth))
                self.assertLess(turn, 5.0, '%s: seen %s, truth %s' % (where, seen, truth))
            # the perception says the same, rounded to 3 decimals
            literal = self.perception_after(heard_after)
            match = LOCATED.match(literal)
            self.assertIsNotNone(match, literal)
            x, y, yaw = (float(g) for g in match.groups())
            truth = self.truth_in_helper_odom(stamp)
            self.assertLess(math.hypot(x - truth[0], y - truth[1]), 0.05, literal)
            self.assertLess(abs(math.degrees(angle_diff(yaw, truth[2]))), 5.0, literal)
        rospy.loginfo('located/faulty over %d poses: worst %.3f m, %.2f deg', len(cases), *worst)
        # no guide ran: robot_guide commanded nothing (the located poses above came after)
        self.assertEqual(self.twists.since(started), [])

    def perception_after(self, stamp, located=True, timeout=10.0):
        """The first literal of robot_guide's first perception heard at ``stamp`` or later
        (with ``located``: the first one that locates a robot)."""
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            with self.perception_lock:
                for heard, literals in self.perceptions:
                    if heard >= stamp and (literals or not located):
                        return literals[0] if literals else None
            time.sleep(0.05)
        self.fail('no robot_guide perception%s after %.2f' % (' locating a robot' if located else '',
                                                               stamp))

    def test_guide_keeps_the_robot_centred_while_it_drives_sideways(self):
        # 1.5 m ahead, 6 deg to the right, turned 55 deg to the helper's left: driving forward
        # at 0.2 m/s moves it across the view (about 6 deg/s of bearing) and away. (Not 90 deg:
        # a robot crossing the line of sight side-on shows one cylinder behind the other, and
        # vision_synth, rightly, sees no robot then.)
        self.place(HELPER, 1.5, -1.5 * math.tan(math.radians(6)), math.radians(55))
        action = self.guide.send('faulty', 5)
        self.assertIsNotNone(self.guide.started(action), 'guide not taken')
        start = rospy.get_time()
        result = None
        while result is None and rospy.get_time() < start + 10.0:
            drive = Twist()
            drive.linear.x = 0.2
            self.drive.publish(drive)
            result = self.guide.result(action, timeout=0.05)
        self.drive.publish(Twist())
        self.assertIsNotNone(result, 'guide(faulty, 5) did not end')
        self.assertEqual(result[0], Event.OK)
        ended = result[1]
        self.assertAlmostEqual(ended - start, 5.0, delta=0.5)
        # the faulty robot's bearing in the helper's camera, from the true poses, after the
        # first second (the helper turning toward it from 6 deg)
        off = []
        for stamp, helper in self.helper_true.since(start + 1.0, ended):
            faulty = self.faulty_true.at(stamp)
            if faulty is not None:
                off.append(abs(camera_truth(helper, faulty)[0]))
        # how far it crossed the view: its bearing from where the helper started, start to end
        helper_start = self.helper_true.at(start)
        crossed = abs(camera_truth(helper_start, self.faulty_true.at(ended))[0]
                      - camera_truth(helper_start, self.faulty_true.at(start))[0])
        turned = math.degrees(abs(angle_diff(self.helper_true.at(ended)[2], helper_start[2])))
        rospy.loginfo('guide: faulty crossed %.1f deg of the view, helper turned %.1f deg, faulty '
                      'within %.2f deg of the centre (mean %.2f) over %d poses', crossed, turned,
                      max(off), sum(off) / len(off), len(off))
        self.assertGreater(len(off), 100)
        self.assertGreater(crossed, 20.0)
        self.assertGreater(turned, 5.0)
        self.assertLess(max(off), 5.0)
        twists = self.twists.since(start - 0.5)
        self.assertTrue(twists and all(t[1] == 0.0 for t in twists), 'angular only: %s' % twists)
        self.assert_silent_after(ended)

    def assert_silent_after(self, ended):
        """The guide's last twist is a zero one, and nothing follows it: checked once robot_guide
        has published its perception for frames a second after the end (a second in which its
        timer would have turned the base twenty times)."""
        self.perception_after(ended + 1.0, located=False)
        after = self.twists.since(ended - 0.2)
        self.assertTrue(after, 'no zero twist at the end')
        self.assertEqual(after[-1][1:], (0.0, 0.0))
        self.assertEqual([t for t in after if t[0] > ended + 0.1], [],
                         'cmd_vel after the guide ended')

    def test_guide_fails_lost_when_the_robot_leaves_the_view(self):
        self.place(HELPER, 1.5, 0.0, 0.0)
        action = self.guide.send('faulty', 20)
        self.assertIsNotNone(self.guide.started(action))
        start = rospy.get_time()
        self.faulty.teleport(HELPER[0] - 1.5, HELPER[1], 0.0, settle=0.0)   # behind the helper
        hidden = rospy.get_time()
        result = self.guide.result(action)
        self.assertIsNotNone(result)
        self.assertEqual(result[0], Event.LOST)
        rospy.loginfo('lost %.2f s after the robot left the view', result[1] - hidden)
        self.assertGreater(result[1] - start, 1.9)
        self.assertLess(result[1] - hidden, 3.0)
        self.assert_silent_after(result[1])

    def test_a_cancelled_guide_stops_at_once(self):
        # 20 deg to the right: the helper turns for most of a second before it is centred, so
        # the first zero twist after the cancel is the cancel's
        self.place(HELPER, 1.5, -1.5 * math.tan(math.radians(20)), 0.0)
        action = self.guide.send('faulty', 20)
        self.assertIsNotNone(self.guide.started(action))
        deadline = time.monotonic() + 10.0
        while not any(t[2] != 0.0 for t in self.twists.since(rospy.get_time() - 1.0)):
            self.assertLess(time.monotonic(), deadline, 'the guide never turned')
            time.sleep(0.02)
        sent = time.monotonic()
        self.guide.cancel(action)
        result = self.guide.result(action, timeout=5.0)
        self.assertEqual(result and result[0], Event.CANCELLED)
        stopped = self.twists.first_zero_after(sent)
        rospy.loginfo('cancel -> zero twist on cmd_vel in %.1f ms', stopped * 1e3)
        self.assertLess(stopped, 0.5)
        self.assert_silent_after(result[1])

    def test_one_guide_at_a_time_and_bad_arguments(self):
        self.place(HELPER, 1.5, 0.0, 0.0)
        first = self.guide.send('faulty', 20)
        self.assertIsNotNone(self.guide.started(first))
        second = self.guide.send('faulty', 2)
        self.assertEqual((self.guide.result(second, timeout=5.0) or [None])[0], Event.BUSY)
        for bad in (('Faulty', 5), ('faulty', 0), ('faulty', 'inf'), ('faulty',)):
            action = self.guide.send(*bad)
            self.assertEqual((self.guide.result(action, timeout=5.0) or [None])[0],
                             Event.BAD_PARAMETERS, bad)
            self.assertIsNone(self.guide.started(action, timeout=0.0), 'refused without starting')
        self.assertIsNone(self.guide.result(first, timeout=0.0), 'the first guide goes on')
        self.guide.cancel(first)
        result = self.guide.result(first, timeout=5.0)
        self.assertEqual(result and result[0], Event.CANCELLED)
        self.assert_silent_after(result[1])


if __name__ == '__main__':
    rostest.rosrun('rason', 'sim_guide', TestSimGuide)
