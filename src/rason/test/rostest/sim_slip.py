#!/usr/bin/python3
"""Wheel slip (rason_sim ~<robot>/left_slip, right_slip; sim_slip.test sets 0.06 and 0.02):
odometry, from the encoders, overestimates the travel, and unequal slip curves a path
that odometry calls straight."""
import math
import os
import sys
import unittest

import rason_rospy

import rospy
import rostest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), 'nodes'))
from sim_testing import SimRobot, wrap_degrees  # noqa: E402
from rason_msgs.msg import Event  # noqa: E402

LEFT_SLIP, RIGHT_SLIP = 0.06, 0.02
WHEEL_SEPARATION = 0.230  # m, rason_sim's Kobuki base
START = (-1.0, -0.75, 0.0)


class TestSimSlip(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        rason_rospy.init_node('test_sim_slip')
        cls.robot = SimRobot('faulty')
        assert cls.robot.wait_connected(), 'decomposer or simulator not listening'

    def setUp(self):
        self.robot.teleport(*START)

    def test_a_move_goes_short_and_veers_to_the_side_that_slips_more(self):
        start = self.robot.pose()
        self.assertEqual(self.robot.act('move', 1), Event.OK)  # odometry: 1 m, straight
        end = self.robot.pose()
        travelled = math.hypot(end[0] - start[0], end[1] - start[1])
        turned = wrap_degrees(math.degrees(end[2] - start[2]))
        rospy.loginfo('move(1) with slip %.2f/%.2f: %.3f m, turned %.2f deg', LEFT_SLIP,
                      RIGHT_SLIP, travelled, turned)
        mean_slip = (LEFT_SLIP + RIGHT_SLIP) / 2
        self.assertAlmostEqual(travelled, 1.0 - mean_slip, delta=0.02)
        # the encoders rolled 1 m each; the floor saw (1 - slip) of it under each wheel
        expected_turn = math.degrees((LEFT_SLIP - RIGHT_SLIP) * 1.0 / WHEEL_SEPARATION)
        self.assertAlmostEqual(turned, expected_turn, delta=2.0)  # counter-clockwise: left


if __name__ == '__main__':
    rostest.rosrun('rason', 'sim_slip', TestSimSlip)
