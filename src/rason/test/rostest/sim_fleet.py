#!/usr/bin/python3
"""A fleet world (sim_fleet.test: four of fleet.yaml's eight robots, rate 0, lockstep): the
simulator publishes odometry and true pose for each of the four robots it was given, and
none for the world file's others; a velocity command moves its own robot and no other."""
import math
import os
import sys
import threading
import time
import unittest

import rason_rospy

import rospy
import rostest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), 'nodes'))
from sim_testing import SimRobot, yaw_of  # noqa: E402
from geometry_msgs.msg import Twist  # noqa: E402
from nav_msgs.msg import Odometry  # noqa: E402
from rason_testing import wait_for  # noqa: E402

RUNNING = ('r1', 'r2', 'r3', 'r4')
LEFT_OUT = ('r5', 'r6', 'r7', 'r8')
SPEED = 0.2          # m/s
DRIVE = 1.0          # s of simulated time
STILL_M, STILL_DEG = 0.002, 0.2


def start_of(robot):
    """The robot's start pose from the simulator's parameters (the world file)."""
    return tuple(float(rospy.get_param('/rason_sim/%s/%s' % (robot, k), 0.0)) for k in ('x', 'y', 'yaw'))


class LatestOdometry(object):
    def __init__(self, robot):
        self.lock = threading.Lock()
        self.msg = None
        self.sub = rospy.Subscriber('/%s/odom' % robot, Odometry, self._on_msg, queue_size=1)

    def _on_msg(self, msg):
        with self.lock:
            self.msg = msg

    def latest(self):
        with self.lock:
            return self.msg


def moved(a, b):
    """(metres, degrees) between two (x, y, yaw) poses."""
    return math.hypot(a[0] - b[0], a[1] - b[1]), abs(math.degrees(math.remainder(a[2] - b[2], 2 * math.pi)))


class TestSimFleet(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        rason_rospy.init_node('test_sim_fleet')
        cls.robots = {r: SimRobot(r) for r in RUNNING}
        cls.odometry = {r: LatestOdometry(r) for r in RUNNING}

    def test_every_robot_given_has_odometry_and_a_true_pose_and_no_other(self):
        for r in RUNNING:
            odom = wait_for(self.odometry[r].latest, 30.0, '/%s/odom' % r)
            self.assertEqual(odom.header.frame_id, '%s/odom' % r)
            self.assertEqual(odom.child_frame_id, '%s/base_footprint' % r)
            pose = self.robots[r].pose(timeout=30.0)
            self.assertIsNotNone(pose, 'no /%s/true_pose' % r)
            distance, turn = moved(pose, start_of(r))
            self.assertLess(distance, 0.01, '%s is not at its start pose: %s' % (r, pose))
            self.assertLess(turn, 0.5, '%s is not at its start heading: %s' % (r, pose))
        published = {t for t, _ in rospy.get_published_topics()}
        for r in LEFT_OUT:
            self.assertNotIn('/%s/true_pose' % r, published)
            self.assertNotIn('/%s/odom' % r, published)

    def test_a_velocity_command_moves_its_own_robot_only(self):
        for target in ('r2', 'r4'):
            for r in RUNNING:
                self.robots[r].wait_at_rest(still=0.3)
            before = {r: self.robots[r].pose() for r in RUNNING}
            odom_before = wait_for(self.odometry[target].latest, 30.0, '/%s/odom' % target).pose.pose.position
            drive = rospy.Publisher('/%s/cmd_vel' % target, Twist, queue_size=1)
            wait_for(lambda: drive.get_num_connections() > 0, 10.0, 'the simulator on /%s/cmd_vel' % target)
            command = Twist()
            command.linear.x = SPEED
            until = rospy.get_time() + DRIVE
            deadline = time.monotonic() + 30.0
            while rospy.get_time() < until and time.monotonic() < deadline:
                drive.publish(command)
                time.sleep(0.02)
            drive.unregister()
            after = {r: self.robots[r].wait_at_rest(still=0.3) for r in RUNNING}
            distance, _ = moved(after[target], before[target])
            self.assertGreater(distance, 0.5 * SPEED * DRIVE, '%s did not move: %s' % (target, after[target]))
            odom_after = self.odometry[target].latest().pose.pose.position
            self.assertAlmostEqual(math.hypot(odom_after.x - odom_before.x, odom_after.y - odom_before.y),
                                   distance, delta=0.02)
            for r in RUNNING:
                if r != target:
                    distance, turn = moved(after[r], before[r])
                    self.assertLess(distance, STILL_M, '%s moved with %s\'s command' % (r, target))
                    self.assertLess(turn, STILL_DEG, '%s turned with %s\'s command' % (r, target))
            # back where it started, so the other test finds it there whatever the order
            x, y, yaw = start_of(target)
            self.robots[target].teleport(x, y, yaw)


if __name__ == '__main__':
    rostest.rosrun('rason', 'sim_fleet', TestSimFleet)
