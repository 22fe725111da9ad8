#!/usr/bin/python3
"""SIGTERM and SIGINT stop the MAS and the JVM cleanly: the pending action fails with
reason shutdown (its -! plan runs), and the process exits 0 within a few seconds."""
import os
import signal
import subprocess
import sys
import time
import unittest

import rason_rospy

import rospy
import rostest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), 'nodes'))
from rason_testing import HERE, LogWatcher, node_command, wait_for, wait_for_subscribers  # noqa: E402
from rason_msgs.msg import Action, Perception  # noqa: E402



class TestShutdown(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        rason_rospy.init_node('test_bridge_shutdown')
        cls.log = LogWatcher()
        cls.actions = []
        # this test takes hold(1) and never answers, so it stays pending (the bridge's own
        # cancels, the restart one at start and the shutdown one, are not actions of the agent)
        rospy.Subscriber('jason/action', Action,
                         lambda a: a.action == Action.CANCEL or cls.actions.append(a))

    def run_and_signal(self, name, signum):
        # what an earlier method saw (even one that failed half-way) is not this one's
        del self.actions[:]
        self.log.clear()
        proc = subprocess.Popen(node_command('rason_bridge', 'rason_mas') + [
            os.path.join(HERE, 'agents', 'holder.mas2j'), '__name:=' + name])
        try:
            go = rospy.Publisher('jason/perception', Perception, queue_size=1, latch=True)
            self.assertTrue(wait_for_subscribers(go, timeout=30))
            self.assertTrue(self.log.wait_ready())
            go.publish(Perception(source='rostest_start', perception=['go']))
            wait_for(lambda: any(a.agent == 'holder' for a in self.actions), 20, 'hold(1) to be published')
            go.unregister()
            sent = time.monotonic()
            proc.send_signal(signum)
            code = proc.wait(timeout=20)
            self.assertEqual(code, 0)
            self.assertLess(time.monotonic() - sent, 10.0)
            self.assertTrue(self.log.wait_for(r'^\[holder\] hold stopped by shutdown$', timeout=5),
                            'the pending action did not fail with reason shutdown')
        finally:
            if proc.poll() is None:
                proc.kill()

    def test_sigterm(self):
        self.run_and_signal('mas_sigterm', signal.SIGTERM)

    def test_sigint(self):
        self.run_and_signal('mas_sigint', signal.SIGINT)


if __name__ == '__main__':
    rostest.rosrun('rason', 'bridge_shutdown', TestShutdown)
