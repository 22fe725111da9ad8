#!/usr/bin/python3
"""An action suspends only its own intention; .print reaches rosout with the agent's name."""
import os
import sys
import unittest

import rason_rospy

import rospy
import rostest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), 'nodes'))
from rason_testing import LogWatcher, poll, start_agents  # noqa: E402
from rason_msgs.msg import Action, Event  # noqa: E402


class TestIntentions(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        rason_rospy.init_node('test_bridge_intentions')
        cls.log = LogWatcher()
        cls.actions = []
        rospy.Subscriber('jason/action', Action, cls.actions.append)
        cls.go = start_agents(cls.log)

    def test_other_intention_runs_while_an_action_is_pending(self):
        done = self.log.wait_for(r'^\[worker\] slow done$', timeout=30)
        self.assertTrue(done, 'the slow action never completed')
        started = self.log.lines(r'^\[worker\] slow started$')[0][0]
        ticks_while_pending = [l for l in self.log.lines(r'^\[worker\] tick$')
                               if started < l[0] < done[0][0]]
        # 2 s pending at one tick per 200 ms: about 10; 5 proves the agent kept running
        self.assertGreaterEqual(len(ticks_while_pending), 5)
        self.assertFalse(self.log.lines(r'slow failed'))

    def test_action_is_published_in_the_namespace_with_its_parameters(self):
        self.assertTrue(self.log.wait_for(r'slow started', timeout=30))
        poll(lambda: len(self.actions) >= 2, 5)  # the list is checked whole below
        self.assertEqual(rospy.resolve_name('jason/action'), '/robot1/jason/action')
        # a (re)started bridge first stops whatever an earlier run of it left, then acts
        self.assertEqual([(a.agent, a.action, list(a.parameters)) for a in self.actions],
                         [('worker', Action.CANCEL, [Event.RESTART]), ('worker', 'slow', ['2'])])
        self.assertEqual(self.actions[0].action_id, 0)
        self.assertGreater(self.actions[1].action_id, 0)

    def test_hosted_agents_are_listed_on_a_parameter(self):
        self.assertTrue(self.log.wait_for(r'slow started', timeout=30))
        self.assertEqual(rospy.get_param('/robot1/rason_mas/agents'), ['worker'])


if __name__ == '__main__':
    rostest.rosrun('rason', 'bridge_intentions', TestIntentions)
