#!/usr/bin/python3
"""A decomposer that takes the action and never answers: the action fails with timeout
after ~action_timeout; a late answer is then ignored with a log line."""
import os
import sys
import time
import unittest

import rospy
import rostest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), 'nodes'))
from rason_testing import LogWatcher, feedback, start_agents, wait_for_subscribers  # noqa: E402
from rason_msgs.msg import Action, Event  # noqa: E402


class TestTimeout(unittest.TestCase):

    def test_unanswered_action_times_out_and_late_feedback_is_ignored(self):
        rospy.init_node('test_bridge_timeout')
        log = LogWatcher()
        seen = []
        rospy.Subscriber('jason/action', Action,
                         lambda m: m.action == Action.CANCEL or seen.append((time.monotonic(), m)))
        events = rospy.Publisher('jason/event', Event, queue_size=10)
        go = start_agents(log)  # noqa: F841 (kept alive for its latch)

        timed_out = log.wait_for(r'^\[holder\] hold timed out$', timeout=30)
        self.assertTrue(timed_out)
        self.assertTrue(seen, 'hold(1) was never published')
        # timed from the agent's act (its "holding" line, logged just before, by the same
        # path as the timeout's line), as the bridge times it: when hold(1) reaches this
        # node's subscriber depends on rospy and the load
        holding = log.lines(r'^\[holder\] holding$')
        self.assertTrue(holding)
        waited = timed_out[0][0] - holding[0][0]
        self.assertGreater(waited, 1.3)  # not before the 1.5 s timeout
        self.assertLess(waited, 15.0)

        self.assertTrue(wait_for_subscribers(events))
        # the late feedback (ignored quietly: the bridge cancelled that action when it timed
        # out), then one for an id that never existed, whose log line proves the late one
        # was handled before it
        action_id = seen[0][1].action_id
        events.publish(feedback('holder', Event.OK, action_id))
        events.publish(feedback('holder', Event.OK, action_id + 1000))
        self.assertTrue(log.wait_for(r'ignored feedback .%s. for action id %d'
                                     % (Event.OK, action_id + 1000)))
        self.assertFalse(log.lines(r'hold finished'))


if __name__ == '__main__':
    rostest.rosrun('rason', 'bridge_timeout', TestTimeout)
