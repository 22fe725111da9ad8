#!/usr/bin/python3
"""Events for other agents, of unknown types, with unknown ids or malformed are ignored
with a log line; the pending action still completes on its own feedback."""
import os
import sys
import unittest

import rason_rospy

import rospy
import rostest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), 'nodes'))
from rason_testing import LogWatcher, feedback, start_agents, wait_for, wait_for_subscribers  # noqa: E402
from rason_msgs.msg import Action, Event  # noqa: E402


class TestEventFiltering(unittest.TestCase):

    def setUp(self):
        rason_rospy.init_node('test_bridge_event_filtering')
        self.log = LogWatcher()
        self.actions = []
        # this test is the decomposer of hold(1)
        rospy.Subscriber('jason/action', Action,
                         lambda a: a.action == Action.CANCEL or self.actions.append(a))
        self.events = rospy.Publisher('jason/event', Event, queue_size=10)
        self.go = start_agents(self.log)

    def test_only_well_formed_feedback_for_this_agent_and_action_counts(self):
        self.assertTrue(wait_for_subscribers(self.events))
        wait_for(lambda: self.actions, 20, 'hold(1) to be published')
        action_id = self.actions[0].action_id

        # Each event to ignore carries a failure reason of its own: had one reached the
        # pending action, the agent's one line about hold would name it.
        self.events.publish(feedback('someone_else', 'wrong_agent', action_id))
        self.events.publish(feedback('holder', 'wrong_type', action_id, event_type='status'))
        self.events.publish(Event(agent='holder', event_type=Event.ACTION_FEEDBACK, parameters=['no_id']))
        self.events.publish(feedback('holder', 'bad_id', 'seven'))
        self.events.publish(feedback('holder', 'unknown_id', action_id + 1000))

        self.assertTrue(self.log.wait_for(r'ignoring events for agent .someone_else.'))
        self.assertTrue(self.log.wait_for(r'unknown event type .status.'))
        self.assertTrue(self.log.wait_for(r'needs parameters \[result, action_id\]'))
        self.assertTrue(self.log.wait_for(r'non-integer action id .seven.'))
        self.assertTrue(self.log.wait_for(r'ignored feedback .unknown_id. for action id %d' % (action_id + 1000)))

        # the right feedback, on the same topic after the others: the bridge handles the
        # events in order, so the first line about hold tells which event ended it
        self.events.publish(feedback('holder', Event.OK, action_id))
        ended = self.log.wait_for(r'^\[holder\] hold (finished|failed|timed out|stopped|has no)', timeout=10)
        self.assertTrue(ended, 'hold never ended')
        self.assertEqual([l[3] for l in ended], ['[holder] hold finished'])


if __name__ == '__main__':
    rostest.rosrun('rason', 'bridge_event_filtering', TestEventFiltering)
