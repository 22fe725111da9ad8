#!/usr/bin/python3
""".stopMAS(3000) gives the agents 3 s before the node stops, as Jason's runner does: of two
plans started with it, the one that prints after 2 s prints, the one after 4 s does not; the
agents are told +jag_shutting_down(3000); the node exits 0."""
import os
import sys
import unittest

import rason_rospy

import rospy
import rostest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), 'nodes'))
from jason_runner import agent_lines, run_rason_mas  # noqa: E402

HERE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))  # the test folder
PROGRAM = os.path.join(HERE, 'agents', 'jason', 'stop_deadline.mas2j')


class TestStopMasDeadline(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        rason_rospy.init_node('test_stop_mas_deadline')

    def test_the_agents_run_until_the_deadline_and_no_longer(self):
        # no shutdown grace: what runs after the deadline would be the grace's, not the deadline's
        run = run_rason_mas(PROGRAM, 'stop_deadline', 90.0, shutdown_grace=0.0)
        self.assertEqual(run.returncode, 0, run.text())
        printed = agent_lines(run.output, 'stop_deadline')
        self.assertIn('[stop_deadline] shutting down in 3000 ms', printed, run.text())
        self.assertIn('[stop_deadline] printed after 2 s', printed, run.text())
        self.assertNotIn('[stop_deadline] printed after 4 s', printed, run.text())


if __name__ == '__main__':
    rostest.rosrun('rason', 'stop_mas_deadline', TestStopMasDeadline)
