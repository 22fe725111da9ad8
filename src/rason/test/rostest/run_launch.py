#!/usr/bin/python3
"""``rosrun rason run_launch``: a launch whose required node finishes cleanly ends with status 0
and without roslaunch's "REQUIRED process has died!" banner; one whose required node fails
ends with a non-zero status that names the node. demo.launch is the launch: the example agent
on the scripted robot, then the same with a .mas2j that does not exist."""
import os
import re
import sys
import unittest

import rason_rospy

import rospy
import rostest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), 'nodes'))
from rason_testing import run_launch  # noqa: E402

BANNER = 'REQUIRED process'


class TestRunLaunch(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        rason_rospy.init_node('test_run_launch')

    def test_a_run_that_ends_well_ends_quietly_with_status_0(self):
        status, output = run_launch('demo.launch')
        self.assertEqual(status, 0, output[-3000:])
        self.assertNotIn(BANNER, output)
        # the lines docs/guides/agents.md shows; the perception's comes after the second turn,
        # in whichever order with that leg's line the agent gets the two
        lines = re.findall(r'\[explorer\] (.*?)\s*$', output, re.M)
        seen = 'buddy came into view'
        self.assertEqual(lines.count(seen), 1, output[-3000:])
        self.assertEqual([l for l in lines if l != seen],
                         ['driving a square of 1 m sides', 'leg 1 done', 'leg 2 done', 'leg 3 done', 'leg 4 done',
                          'square done', 'I can see buddy at -12.5 degrees and 2.1 m'], output[-3000:])
        self.assertGreater(lines.index(seen), lines.index('leg 1 done'))
        self.assertIn('run_launch: rason_mas finished: the launch is shut down', output)

    def test_a_run_whose_required_node_fails_ends_non_zero(self):
        status, output = run_launch('demo.launch', 'mas:=/nonexistent/nothing.mas2j')
        self.assertNotEqual(status, 0, output[-3000:])
        self.assertNotIn(BANNER, output)
        self.assertRegex(output, r'run_launch: rason_mas failed \(exit status %d\): the launch is shut down' % status)


if __name__ == '__main__':
    rostest.rosrun('rason', 'run_launch', TestRunLaunch)
