#!/usr/bin/python3
"""jason/mind: an agent's beliefs, goals, intentions and pending actions as they change,
latched for a late subscriber, bounded by ~mind_max_items, absent with ~mind_period 0."""
import os
import sys
import threading
import time
import unittest

import rosgraph
import rason_rospy
import rospy
import rostest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), 'nodes'))
from rason_testing import feedback, wait_for, wait_for_subscribers  # noqa: E402
from rason_msgs.msg import Action, Event, MindState, Perception  # noqa: E402

WAIT = 20.0


class Minds(object):
    """The MindState messages of one topic, with a wait for one that satisfies a test."""

    def __init__(self, topic):
        self._cond = threading.Condition()
        self.received = []
        self.sub = rospy.Subscriber(topic, MindState, self._on, queue_size=100)

    def _on(self, msg):
        with self._cond:
            self.received.append(msg)
            self._cond.notify_all()

    def wait_for(self, test, timeout=WAIT):
        """The first agent mind (AgentMind) of a message received so far or later for which test holds."""
        deadline = time.monotonic() + timeout
        with self._cond:
            seen = 0
            while True:
                for msg in self.received[seen:]:
                    for agent in msg.agents:
                        if test(agent):
                            return msg, agent
                seen = len(self.received)
                left = deadline - time.monotonic()
                if left <= 0:
                    return None, None
                self._cond.wait(min(left, 0.1))


class Courier(object):
    """The courier agent of one rason_mas (in namespace ns): its actions, and publishers
    for its events and percepts."""

    def __init__(self, ns=''):
        topic = (lambda name: '/%s/jason/%s' % (ns, name)) if ns else (lambda name: 'jason/' + name)
        self.mind_topic = topic('mind')
        self.actions = []
        self.action_cond = threading.Condition()
        rospy.Subscriber(topic('action'), Action, self._on_action, queue_size=100)
        self.events = rospy.Publisher(topic('event'), Event, queue_size=10)
        self.percepts = rospy.Publisher(topic('perception'), Perception, queue_size=10, latch=True)
        assert wait_for_subscribers(self.events, timeout=WAIT)
        assert wait_for_subscribers(self.percepts, timeout=WAIT)

    def _on_action(self, msg):
        with self.action_cond:
            self.actions.append(msg)
            self.action_cond.notify_all()

    def next_action(self, name):
        """The first action called name not taken yet (None after WAIT s)."""
        deadline = time.monotonic() + WAIT
        with self.action_cond:
            while True:
                for a in self.actions:
                    if a.action == name:
                        self.actions.remove(a)
                        return a
                left = deadline - time.monotonic()
                if left <= 0:
                    return None
                self.action_cond.wait(min(left, 0.1))


class TestMindState(unittest.TestCase):
    """The state-following test has a rason_mas of its own (namespace follow), so the
    deliveries of the bounding test do not fill the lists it reads."""

    @classmethod
    def setUpClass(cls):
        rason_rospy.init_node('test_mind_state')
        cls.follow = Courier('follow')
        cls.busy = Courier()

    def test_the_state_follows_the_agent_through_an_action(self):
        minds = Minds(self.follow.mind_topic)
        _, start = minds.wait_for(lambda a: 'charge(90)[source(self)]' in a.beliefs)
        self.assertIsNotNone(start, 'no jason/mind with the initial belief')
        self.assertEqual(start.name, 'follow_courier')

        self.follow.percepts.publish(Perception(source='test', perception=['go(p1)']))
        action = self.follow.next_action('deliver')
        self.assertIsNotNone(action, 'no deliver action')
        self.assertEqual(action.agent, 'follow_courier')
        msg, waiting = minds.wait_for(lambda a: len(a.actions) == 1)
        self.assertIsNotNone(waiting, 'no jason/mind with the pending deliver')
        self.assertEqual(msg.mas_id, '/follow/rason_mas')
        self.assertEqual((waiting.actions[0].id, waiting.actions[0].action),
                         (action.action_id, 'deliver(p1)'))
        self.assertGreater(waiting.actions[0].started.to_sec(), 0)
        self.assertEqual(waiting.goals, ['!deliver(p1)[source(self)]', '!carry(p1)[source(self)]'])
        (intention,) = waiting.intentions
        self.assertEqual(intention.state, 'waiting')
        self.assertTrue(intention.plans[0].endswith('<- deliver(p1)'), intention.plans)
        self.assertTrue(any(e.startswith('+go(p1)') for e in waiting.events), waiting.events)

        self.follow.events.publish(feedback(action.agent, 'OK', action.action_id))
        _, done = minds.wait_for(lambda a: 'delivered(p1)[source(self)]' in a.beliefs and not a.intentions)
        self.assertIsNotNone(done, 'no jason/mind after the delivery')
        self.assertEqual((done.actions, done.goals), ([], []))
        self.assertGreater(done.cycle, waiting.cycle)
        minds.sub.unregister()

    def test_a_late_subscriber_gets_the_latest_state_at_once(self):
        minds = Minds(self.busy.mind_topic)
        msg, agent = minds.wait_for(lambda a: a.name == 'courier', timeout=5.0)
        self.assertIsNotNone(agent, 'jason/mind is not latched')
        minds.sub.unregister()

    def test_lists_are_bounded_by_mind_max_items(self):
        minds = Minds(self.busy.mind_topic)
        self.busy.percepts.publish(Perception(source='test', perception=['go(p%d)' % i for i in range(2, 12)]))
        for _ in range(10):
            action = self.busy.next_action('deliver')
            self.assertIsNotNone(action, 'no deliver action')
            self.busy.events.publish(feedback('courier', 'OK', action.action_id))
        _, full = minds.wait_for(lambda a: 'delivered(p11)[source(self)]' in a.beliefs or a.omitted > 0)
        self.assertIsNotNone(full)
        _, bounded = minds.wait_for(lambda a: a.omitted > 0)
        self.assertIsNotNone(bounded, 'nothing omitted although the agent believes more than 5 things')
        for field in ('beliefs', 'goals', 'intentions', 'actions', 'events', 'messages'):
            self.assertLessEqual(len(getattr(bounded, field)), 5, field)
        minds.sub.unregister()

    def test_no_topic_when_mind_period_is_zero(self):
        # its ~agents parameter is set once it has started and made its publishers
        wait_for(lambda: rospy.has_param('/quiet/rason_mas/agents'), WAIT, '/quiet/rason_mas to start', interval=0.1)
        published = [t for t, _ in rosgraph.Master('/test_mind_state').getPublishedTopics('/')]
        self.assertIn('/jason/mind', published)
        self.assertNotIn('/quiet/jason/mind', published)


if __name__ == '__main__':
    rostest.rosrun('rason', 'mind_state', TestMindState)
