#!/usr/bin/python3
"""A decomposer that takes the action and never answers: the action fails with timeout
after ~action_timeout; a late answer is then ignored with a log line."""
import os
import re
import sys
import time
import unittest

import rason_rospy

import rospy
import rostest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), 'nodes'))
from rason_testing import LogWatcher, feedback, start_agents, wait_for_subscribers  # noqa: E402
from rason_msgs.msg import Action, Event  # noqa: E402


class TestTimeout(unittest.TestCase):

    def test_unanswered_action_times_out_and_late_feedback_is_ignored(self):
        rason_rospy.init_node('test_bridge_timeout')
        log = LogWatcher()
        seen = []
        rospy.Subscriber('jason/action', Action,
                         lambda m: m.action == Action.CANCEL or seen.append((time.monotonic(), m)))
        events = rospy.Publisher('jason/event', Event, queue_size=10)
        go = start_agents(log)  # noqa: F841 (kept alive for its latch)

        timed_out = log.wait_for(r'^\[holder\] hold timed out after [0-9.]+ ms$', timeout=30)
        self.assertTrue(timed_out)
        self.assertTrue(seen, 'hold(1) was never published')
        # timed by the agent on the bridge's clock (rason.ros_time_ms), as the bridge times
        # it: rosout stamps and this node's subscriber lag by however loaded the machine is
        waited = float(re.search(r'after ([0-9.]+) ms', timed_out[0][3]).group(1)) / 1000.0
        self.assertGreaterEqual(waited, 1.5)  # not before the 1.5 s timeout
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
