#!/usr/bin/python3
"""OK resumes the intention; any other feedback fails it with the reason among the annotations."""
import os
import sys
import unittest

import rason_rospy

import rospy
import rostest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), 'nodes'))
from rason_testing import LogWatcher, start_agents  # noqa: E402


class TestFailureReasons(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        rason_rospy.init_node('test_bridge_failure_reasons')
        cls.log = LogWatcher()
        cls.go = start_agents(cls.log)

    def wait_until_every_goal_ended(self):
        """Each of mover's four goals ends with exactly one line: once all four are in, no
        plan of mover can still print."""
        ends = self.log.wait_for(r'^\[mover\] (move|curve|jam|spin) (ok|failed)', count=4)
        self.assertEqual(len(ends), 4, 'not every goal ended: %r'
                         % [l[3] for l in self.log.lines(r'^\[mover\] ')])

    def test_reason_matches_a_failure_plan_annotation(self):
        self.assertTrue(self.log.wait_for(r'^\[mover\] move failed: no_progress matched$'))

    def test_reason_is_a_member_of_the_annotation_list(self):
        self.assertTrue(self.log.wait_for(r'^\[mover\] curve failed: member bad_move$'))

    def test_reason_that_is_not_an_atom_is_kept_as_text(self):
        self.assertTrue(self.log.wait_for(r'^\[mover\] jam failed: Motor stalled!$'))

    def test_ok_resumes_the_intention(self):
        self.assertTrue(self.log.wait_for(r'^\[mover\] spin ok$'))
        self.wait_until_every_goal_ended()
        self.assertFalse(self.log.lines(r'otherwise|spin failed'))

    def test_architecture_named_in_the_project_is_not_added_twice(self):
        self.assertTrue(self.log.wait_for(r'spin ok'))
        self.wait_until_every_goal_ended()
        self.assertEqual(rospy.get_param('/rason_mas/agents'), ['mover'])
        self.assertEqual(len(self.log.lines(r'^\[mover\] spin ok$')), 1)


if __name__ == '__main__':
    rostest.rosrun('rason', 'bridge_failure_reasons', TestFailureReasons)
