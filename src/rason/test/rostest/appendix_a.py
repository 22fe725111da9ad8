#!/usr/bin/python3
"""The thesis's Faulty and Helper programs run the whole exchange to the diagnosis
"fault in both actuators" on real Jason, through the bridge."""
import os
import sys
import unittest

import rason_rospy

import rospy
import rostest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), 'nodes'))
from rason_testing import LogWatcher  # noqa: E402

# the dialogue of thesis Fig. 6.8, in order
DIALOGUE = [
    r'^\[faulty\] Moving to Destination$',
    r'^\[faulty\] Cannot solve problem alone, asking for help\.$',
    r'^\[helper\] Finding faulty turning 5 degrees',
    r'^\[helper\] Found faulty$',
    r'^\[faulty\] helper found me, asking to track me$',
    r'^\[helper\] I\'m ready\.$',
    r'^\[faulty\] Trying to bit for helper$',
    r'^\[faulty\]  requesting some feedback from helper$',
    r'^\[helper\] reporting to faulty -> 0 1.5 0 / 0 1.5 0$',
    r'^\[faulty\] fault in both actuators, thanks helper$',
    r'^\[helper\] You\'re welcome, faulty$',
]


class TestAppendixA(unittest.TestCase):

    def test_both_actuators_diagnosed_in_the_thesis_order(self):
        rason_rospy.init_node('test_appendix_a')
        log = LogWatcher()
        self.assertTrue(log.wait_ready())  # the agents wait 4 s before anything
        self.assertTrue(log.wait_for(DIALOGUE[-1], timeout=60), 'the exchange did not finish')
        times = []
        for step in DIALOGUE:
            lines = log.lines(step)
            self.assertTrue(lines, 'missing step %r' % step)
            times.append(lines[0][0])
        self.assertEqual(times, sorted(times), 'steps out of order')
        self.assertFalse(log.lines(r'odometry|actuator has problems|false positive'))


if __name__ == '__main__':
    rostest.rosrun('rason', 'appendix_a', TestAppendixA)
