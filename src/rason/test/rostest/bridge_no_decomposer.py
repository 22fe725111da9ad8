#!/usr/bin/python3
"""An action nobody subscribes to fails with no_decomposer well before the action timeout."""
import os
import sys
import unittest

import rason_rospy

import rospy
import rostest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), 'nodes'))
from rason_testing import LogWatcher, start_agents  # noqa: E402


class TestNoDecomposer(unittest.TestCase):

    def test_action_without_subscriber_fails_no_decomposer(self):
        rason_rospy.init_node('test_bridge_no_decomposer')
        log = LogWatcher()
        go = start_agents(log)  # noqa: F841 (kept alive for its latch)
        failed = log.wait_for(r'^\[holder\] hold has no decomposer$', timeout=30)
        self.assertTrue(failed)
        started = log.lines(r'^\[holder\] holding$')
        self.assertLess(failed[0][0] - started[0][0], 10.0)  # the timeout is 30 s
        self.assertTrue(log.lines(r'no node subscribes to /jason/action'))
        self.assertFalse(log.lines(r'hold (finished|timed out)'))


if __name__ == '__main__':
    rostest.rosrun('rason', 'bridge_no_decomposer', TestNoDecomposer)
