#!/usr/bin/python3
"""move/turn on the simulated base, healthy and with each injected fault, checked against
the simulator's true pose (thesis §6.3 faults, motion_decomp's OK/no_progress/bad_move)."""
import math
import os
import sys
import threading
import unittest

import rason_rospy

import rospy
import rostest
import tf2_ros

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), 'nodes'))
from sim_testing import SimRobot, wrap_degrees  # noqa: E402
from geometry_msgs.msg import PoseStamped  # noqa: E402
from rason_msgs.msg import Event  # noqa: E402
from rason_msgs.srv import FaultInjector  # noqa: E402

START = (-1.0, -0.75, 0.0)


class PathRecorder(object):
    """True poses of the faulty robot while a motion runs."""

    def __init__(self, robot):
        self.points = []
        self._lock = threading.Lock()
        rospy.Subscriber('/%s/true_pose' % robot, PoseStamped, self._on_pose, queue_size=100)

    def _on_pose(self, msg):
        with self._lock:
            self.points.append((msg.pose.position.x, msg.pose.position.y))

    def clear(self):
        with self._lock:
            del self.points[:]

    def max_lateral(self, start):
        """Largest signed sideways offset from the start heading (left positive)."""
        x0, y0, yaw = start
        with self._lock:
            offsets = [-(x - x0) * math.sin(yaw) + (y - y0) * math.cos(yaw) for x, y in self.points]
        return max(offsets, key=abs) if offsets else 0.0


class TestSimMotion(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        rason_rospy.init_node('test_sim_motion')
        cls.robot = SimRobot('faulty')
        cls.path = PathRecorder('faulty')
        rospy.wait_for_service('/faulty/inject_fault', timeout=30)
        cls.inject_fault = rospy.ServiceProxy('/faulty/inject_fault', FaultInjector)
        assert cls.robot.wait_connected(), 'decomposer or simulator not listening'
        cls.tf = tf2_ros.Buffer()
        cls.tf_listener = tf2_ros.TransformListener(cls.tf)

    def setUp(self):
        self.inject_fault('cancel')
        self.robot.teleport(*START)
        self.path.clear()

    def moved(self, start):
        p = self.robot.pose()
        return math.hypot(p[0] - start[0], p[1] - start[1])

    def test_healthy_move_there_and_back(self):
        start = self.robot.pose()
        self.assertEqual(self.robot.act('move', 1), Event.OK)
        self.assertAlmostEqual(self.moved(start), 1.0, delta=0.05)
        self.assertEqual(self.robot.act('move', -1), Event.OK)
        rospy.loginfo('move(1), move(-1): back within %.3f m of the start', self.moved(start))
        self.assertLess(self.moved(start), 0.05)

    def test_healthy_turn_right_90(self):
        start = self.robot.pose()
        self.assertEqual(self.robot.act('turn', 90), Event.OK)
        turned = wrap_degrees(math.degrees(self.robot.wait_at_rest()[2] - start[2]))
        rospy.loginfo('turn(90): turned %.2f deg', turned)
        self.assertAlmostEqual(turned, -90.0, delta=3.0)  # turn(+D) is clockwise
        self.assertLess(self.moved(start), 0.03)

    def test_world_frame_puts_the_odometry_where_the_robot_is(self):
        """world -> faulty/odom (tf_static, made again after a set_pose) and the odometry
        place the robot at its true pose: rviz shows both in the fixed frame world."""
        self.assertEqual(self.robot.act('move', 0.5), Event.OK)
        x, y, yaw = self.robot.pose()
        t = self.tf.lookup_transform('world', 'faulty/base_footprint', rospy.Time(0), rospy.Duration(5)).transform
        self.assertAlmostEqual(t.translation.x, x, delta=0.02)
        self.assertAlmostEqual(t.translation.y, y, delta=0.02)
        tf_yaw = 2 * math.atan2(t.rotation.z, t.rotation.w)
        self.assertLess(abs(wrap_degrees(math.degrees(tf_yaw - yaw))), 2.0)

    def test_both_actuators_no_progress_and_robot_still(self):
        self.assertIn('both_actuators', self.inject_fault('both_actuators').return_message)
        start = self.robot.pose()
        self.assertEqual(self.robot.act('move', 1), Event.NO_PROGRESS)
        self.assertLess(self.moved(start), 0.02)

    def test_odometry_fault_no_progress_while_robot_moves(self):
        self.inject_fault('odometry')
        start = self.robot.pose()
        self.assertEqual(self.robot.act('move', 1), Event.NO_PROGRESS)
        self.assertGreater(self.moved(start), 0.1)

    def test_left_actuator_bad_move_curving_left(self):
        self.inject_fault('left_actuator')
        start = self.robot.pose()
        self.assertEqual(self.robot.act('move', 1), Event.BAD_MOVE)
        self.assertGreater(self.path.max_lateral(start), 0.005)

    def test_right_actuator_bad_move_curving_right(self):
        self.inject_fault('right_actuator')
        start = self.robot.pose()
        self.assertEqual(self.robot.act('move', 1), Event.BAD_MOVE)
        self.assertLess(self.path.max_lateral(start), -0.005)


if __name__ == '__main__':
    rostest.rosrun('rason', 'sim_motion', TestSimMotion)
