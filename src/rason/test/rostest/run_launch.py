#!/usr/bin/python3
"""``rosrun rason run_launch``: a launch whose required node finishes cleanly ends with status 0
and without roslaunch's "REQUIRED process has died!" banner; one whose required node fails
ends with a non-zero status that names the node. demo.launch is the launch: the example agent
on the scripted robot, then the same with a .mas2j that does not exist."""
import signal
import subprocess
import unittest

import rospy
import rostest

BANNER = 'REQUIRED process'


def run_launch(*args, timeout=60.0):
    """(exit status, output) of ``rosrun rason run_launch rason ARGS``."""
    launch = subprocess.Popen(['rosrun', 'rason', 'run_launch', 'rason'] + list(args),
                              stdout=subprocess.PIPE, stderr=subprocess.STDOUT, universal_newlines=True)
    try:
        output, _ = launch.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        launch.send_signal(signal.SIGINT)    # roslaunch's own shutdown: no node left behind
        output, _ = launch.communicate(timeout=60)
        output += '\n(the launch did not end within %.0f s: interrupted)' % timeout
    return launch.returncode, output


class TestRunLaunch(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        rospy.init_node('test_run_launch')

    def test_a_run_that_ends_well_ends_quietly_with_status_0(self):
        status, output = run_launch('demo.launch')
        self.assertEqual(status, 0, output[-3000:])
        self.assertNotIn(BANNER, output)
        self.assertIn('[explorer] driving a square of 1 m sides', output)
        self.assertIn('run_launch: rason_mas finished: the launch is shut down', output)

    def test_a_run_whose_required_node_fails_ends_non_zero(self):
        status, output = run_launch('demo.launch', 'mas:=/nonexistent/nothing.mas2j')
        self.assertNotEqual(status, 0, output[-3000:])
        self.assertNotIn(BANNER, output)
        self.assertRegex(output, r'run_launch: rason_mas failed \(exit status %d\): the launch is shut down' % status)


if __name__ == '__main__':
    rostest.rosrun('rason', 'run_launch', TestRunLaunch)
