#!/usr/bin/python3
"""motion_decomp's recovery actions (issue 15) on the simulated base, judged by the
simulator's true pose: compensate + goto under the left and right actuator faults (the
second with a gain 20 % off), pose_source(guided) under the odometry fault with a guided pose
made here from the true pose (late and at 10 Hz, like another robot's view), and the commanded
odometry."""
import math
import os
import sys
import threading
import unittest

import rason_rospy

import rospy
import rostest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), 'nodes'))
from rason_testing import wait_for  # noqa: E402
from sim_testing import BaseWatch, SimRobot, relative  # noqa: E402
from geometry_msgs.msg import PoseStamped  # noqa: E402
from nav_msgs.msg import Odometry  # noqa: E402
from rason_msgs.msg import Event  # noqa: E402
from rason_msgs.srv import FaultInjector  # noqa: E402

START = (-1.0, -0.75, 0.0)
GOAL_AHEAD, GOAL_LEFT = 1.0, 0.3     # the goal, relative to the start pose
REACHED = 0.1                        # m, true pose to goal (goto's own tolerance is 0.05)


class GuidedPoses(object):
    """Publishes /faulty/guided_pose as another robot would: the true pose expressed in the
    robot's odometry frame, ``latency`` s late, every ``period`` s (ROS time)."""

    def __init__(self, latency=0.2, period=0.1):
        self.latency = latency
        self._lock = threading.Lock()
        self._history = []          # (stamp, x, y, yaw) true poses
        self._to_odom = None        # (true pose, odometry pose) taken at rest
        self._pub = rospy.Publisher('/faulty/guided_pose', PoseStamped, queue_size=10)
        rospy.Subscriber('/faulty/true_pose', PoseStamped, self._on_truth, queue_size=100)
        rospy.Timer(rospy.Duration(period), self._publish)

    def _on_truth(self, msg):
        q = msg.pose.orientation
        with self._lock:
            self._history.append((msg.header.stamp.to_sec(), msg.pose.position.x,
                                  msg.pose.position.y, 2.0 * math.atan2(q.z, q.w)))
            del self._history[:-200]

    def start(self, truth, odom):
        """Begin publishing, with the world -> odometry transform of these two poses."""
        with self._lock:
            self._to_odom = (truth, odom)

    def stop(self):
        with self._lock:
            self._to_odom = None

    def _publish(self, _event):
        with self._lock:
            if self._to_odom is None:
                return
            seen_at = rospy.get_time() - self.latency
            old = [p for p in self._history if p[0] <= seen_at]
            if not old:
                return
            stamp, x, y, yaw = old[-1]
            (tx, ty, tyaw), (ox, oy, oyaw) = self._to_odom
        turn = oyaw - tyaw
        dx, dy = x - tx, y - ty
        msg = PoseStamped()
        msg.header.stamp = rospy.Time.from_sec(stamp)
        msg.header.frame_id = 'helper/odom'
        msg.pose.position.x = ox + dx * math.cos(turn) - dy * math.sin(turn)
        msg.pose.position.y = oy + dx * math.sin(turn) + dy * math.cos(turn)
        msg.pose.orientation.z, msg.pose.orientation.w = math.sin((yaw + turn) / 2), math.cos((yaw + turn) / 2)
        self._pub.publish(msg)


class CommandedWatch(object):
    """The latest odom_commanded message."""

    def __init__(self):
        self.last = None
        rospy.Subscriber('/faulty/odom_commanded', Odometry, self._on_msg, queue_size=10)

    def _on_msg(self, msg):
        self.last = msg


class TestSimGoto(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        rason_rospy.init_node('test_sim_goto')
        cls.robot = SimRobot('faulty')
        cls.watch = BaseWatch('faulty')
        cls.guided = GuidedPoses()
        cls.commanded = CommandedWatch()
        rospy.wait_for_service('/faulty/inject_fault', timeout=30)
        cls.inject_fault = rospy.ServiceProxy('/faulty/inject_fault', FaultInjector)
        assert cls.robot.wait_connected(), 'decomposer or simulator not listening'

    def setUp(self):
        self.guided.stop()
        self.inject_fault('cancel')
        # back to normal driving on odometry (a setting waits in the FIFO: answered in turn)
        self.assertEqual(self.robot.act('compensate', 'none', 0), Event.OK)
        self.assertEqual(self.robot.act('pose_source', 'odom'), Event.OK)
        self.robot.teleport(*START)
        wait_for(lambda: self.watch.odom is not None, 10, 'odometry')
        # at rest: the goal in the odometry frame and where it truly is
        self.odom_start, self.true_start = self.watch.odom, self.robot.pose()
        self.goal_odom = relative(self.odom_start, GOAL_AHEAD, GOAL_LEFT)
        self.goal_true = relative(self.true_start, GOAL_AHEAD, GOAL_LEFT)

    def goto(self):
        """goto the goal; returns (result, sim seconds, true metres from the goal, largest
        true distance from the straight line start -> goal)."""
        began = rospy.get_time()
        result = self.robot.act('goto', '%.4f' % self.goal_odom[0], '%.4f' % self.goal_odom[1])
        took = rospy.get_time() - began
        pose = self.robot.wait_at_rest()
        error = math.hypot(pose[0] - self.goal_true[0], pose[1] - self.goal_true[1])
        (sx, sy), (gx, gy) = self.true_start[:2], self.goal_true
        length = math.hypot(gx - sx, gy - sy)
        path = [(x, y) for _, x, y, _ in self.watch.wait_sim_time(began)]
        off = max(abs((x - sx) * (gy - sy) - (y - sy) * (gx - sx)) / length for x, y in path)
        return result, took, error, off

    def compensated_goto(self, fault, side, gain):
        self.assertIn(fault, self.inject_fault(fault).return_message)
        self.assertEqual(self.robot.act('compensate', side, gain), Event.OK)
        result, took, error, off = self.last = self.goto()
        rospy.loginfo('%s, compensate(%s, %s), goto: %s in %.1f s (sim), %.3f m from the goal, '
                      'path at most %.3f m off the straight line', fault, side, gain, result, took,
                      error, off)
        self.assertEqual(result, Event.OK)
        self.assertLess(error, REACHED)

    def test_left_actuator_compensate_then_goto_reaches_the_goal(self):
        self.compensated_goto('left_actuator', 'left', 2)

    def test_right_actuator_with_a_gain_20_percent_low_still_reaches_the_goal(self):
        self.compensated_goto('right_actuator', 'right', 1.6)

    def test_without_compensation_the_same_fault_winds_off_the_line(self):
        """The measurement behind compensate, on the simulator: the same goal under the left
        fault, with compensation and without (goto steering as for a healthy base)."""
        self.compensated_goto('left_actuator', 'left', 2)
        compensated_off = self.last[3]
        self.setUp()
        self.assertIn('left_actuator', self.inject_fault('left_actuator').return_message)
        result, took, error, off = self.goto()
        rospy.loginfo('left_actuator, no compensation, goto: %s in %.1f s (sim), %.3f m from the '
                      'goal, path at most %.3f m off the straight line', result, took, error, off)
        self.assertGreater(off, 2 * compensated_off)

    def test_guided_pose_source_reaches_the_goal_with_frozen_odometry(self):
        self.guided.start(self.true_start, self.odom_start)
        self.assertIn('odometry', self.inject_fault('odometry').return_message)
        self.assertEqual(self.robot.act('pose_source', 'guided'), Event.OK)
        result, took, error, _ = self.goto()
        rospy.loginfo('odometry fault, pose_source(guided), goto: %s in %.1f s (sim), %.3f m from '
                      'the goal', result, took, error)
        self.assertEqual(result, Event.OK)
        self.assertLess(error, REACHED)
        # and without guided poses the decomposer does not drive blind: it drives while the
        # last one is fresh (0.5 s from its stamp, 0.2 s late: 0.3 s at 0.1 m/s, 3 cm) and
        # then commands nothing until no_progress (blind, it would go 0.1 m in that second)
        self.guided.stop()
        before = self.robot.pose()
        self.assertEqual(self.robot.act('move', 0.5), Event.NO_PROGRESS)
        after = self.robot.wait_at_rest()
        went = math.hypot(after[0] - before[0], after[1] - before[1])
        rospy.loginfo('guided poses stopped: the move went %.3f m, then no_progress', went)
        self.assertLess(went, 0.06)

    def test_odom_commanded_keeps_counting_when_the_encoders_fail(self):
        self.assertIsNotNone(self.commanded.last, 'no odom_commanded (it comes at 1 Hz when idle)')
        self.assertEqual(self.commanded.last.header.frame_id, 'faulty/odom_commanded')
        self.assertEqual(self.commanded.last.child_frame_id, 'faulty/base_footprint')
        c0 = self.commanded.last.pose.pose.position
        t0 = self.robot.pose()
        self.inject_fault('odometry')
        # the odometry is frozen: the move drives on until no_progress, 1 s later
        self.assertEqual(self.robot.act('move', 0.5), Event.NO_PROGRESS)
        ended = rospy.get_time()
        # at rest, and an odom_commanded stamped after it (idle: 1 Hz)
        wait_for(lambda: self.commanded.last.header.stamp.to_sec() >= ended + 1.0, 10,
                 'an odom_commanded stamped after the move')
        c1, t1 = self.commanded.last.pose.pose.position, self.robot.pose()
        commanded = math.hypot(c1.x - c0.x, c1.y - c0.y)
        true = math.hypot(t1[0] - t0[0], t1[1] - t0[1])
        rospy.loginfo('odometry fault: the robot went %.3f m, odom_commanded says %.3f m', true, commanded)
        self.assertGreater(true, 0.15)
        self.assertLess(abs(commanded - true), 0.03)


if __name__ == '__main__':
    rostest.rosrun('rason', 'sim_goto', TestSimGoto)
