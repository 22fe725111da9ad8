#!/usr/bin/python3
"""Hostile input to a rason_mas (issue 13): deep and huge terms, many literals, non-finite
numbers, reserved annotations, malformed text, a flood, bad events, huge agent names, a
flood of source names. After each: a clear, rate-limited warning, nothing good lost, and
the agent still answers a ping. The input is rason_tools.hostile's, the same every run.

Each method starts a rason_mas of its own (its own namespace), so that its warnings are
not hidden by the rate limit spent by another method.
"""
import itertools
import os
import re
import sys
import threading
import time
import unittest

import rason_rospy

import rospy
import rostest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), 'nodes'))
from rason_testing import HERE, LogWatcher, start_mas, stop_mas, wait_for_subscribers  # noqa: E402
from rason_msgs.msg import Action, Event, Perception  # noqa: E402
from rason_tools import hostile  # noqa: E402

MAS2J = os.path.join(HERE, 'agents', 'hostile', 'target.mas2j')
AGENT = 'target'
#: A ping answered after hostile input: generous for a shared 2-core machine (make bench
#: measures the 100 ms goal).
PING_BOUND = 1.0
#: Lines of one kind the bridge logs per period (rason.core.RateLimitedLog).
LINES_PER_PERIOD = 10
#: ~warning_period of the method that waits for a period's summary (default 10 s): the bad
#: input arrives in one message, handled within milliseconds, well inside it.
WARNING_PERIOD = 2.0
#: Warnings of each kind (not their summaries, "dropped perception: … N more like this").
DROPPED = r'^dropped perception[^:]'
IGNORED = r'^(ignored event for|ignoring events for|\[target\] ignored feedback)'
#: Agent names of the huge-names method: fewer than the bench's 200 x 1 MB, same kind.
HUGE_NAMES, HUGE_NAME_CHARS = 20, 1 << 20


class TargetNode(object):
    """One rason_mas with the agent ``target`` in namespace ``ns``; this test is the
    decomposer of its ``pong`` actions (answered OK on the same topic as the hostile events)."""

    _namespaces = itertools.count(1)

    def __init__(self, log, name, **params):
        self.log = log
        self.ns = 'hostile%d_%s' % (next(self._namespaces), name)
        self.node = '/%s/rason_mas' % self.ns
        self.proc = start_mas(self.ns, MAS2J, **params)
        # large queues: rospy would drop the oldest of a burst we publish
        self.perceptions = rospy.Publisher('/%s/jason/perception' % self.ns, Perception, queue_size=100000)
        self.events = rospy.Publisher('/%s/jason/event' % self.ns, Event, queue_size=100000)
        self._cond = threading.Condition()
        self._pongs = {}  # N -> time.monotonic of arrival
        self._actions = rospy.Subscriber('/%s/jason/action' % self.ns, Action, self._on_action, queue_size=None)
        self._pings = itertools.count(1)
        self.last_ping = None

    def _on_action(self, msg):
        if msg.action != 'pong':
            return
        now = time.monotonic()
        self.events.publish(Event(agent=msg.agent, event_type=Event.ACTION_FEEDBACK,
                                  parameters=[Event.OK, str(msg.action_id)]))
        with self._cond:
            self._pongs[int(msg.parameters[0])] = now
            self._cond.notify_all()

    def start(self, timeout=60.0):
        """Wait until the node hears us, answers a ping and its log reaches us."""
        assert wait_for_subscribers(self.perceptions, timeout=timeout), '%s does not subscribe' % self.node
        assert wait_for_subscribers(self.events, timeout=timeout)
        deadline = time.monotonic() + timeout
        while self.ping(0.5) is None:
            assert time.monotonic() < deadline and self.proc.poll() is None, '%s never answered a ping' % self.node
        assert self.log.wait_ready()
        return self

    def stop(self):
        self._actions.unregister()
        self.perceptions.unregister()
        self.events.unregister()
        return stop_mas(self.proc)

    def ping(self, timeout=PING_BOUND):
        """Seconds from publishing ping(N) to the agent's pong(N) arriving; None if it did
        not within timeout. The agent prints ``pong N done`` once our OK reached it."""
        n = self.last_ping = next(self._pings)
        sent = time.monotonic()
        self.perceptions.publish(Perception(source='rostest_ping', perception=['ping(%d)' % n]))
        deadline = sent + timeout
        with self._cond:
            while n not in self._pongs:
                left = deadline - time.monotonic()
                if left <= 0:
                    return None
                self._cond.wait(left)
            return self._pongs[n] - sent

    def send(self, case):
        for source, literals in case.perceptions:
            self.perceptions.publish(Perception(source=source, perception=literals))
        for agent, event_type, parameters in case.events:
            self.events.publish(Event(agent=AGENT if agent is None else agent, event_type=event_type,
                                      parameters=parameters))

    def lines(self, pattern):
        return [l[3] for l in self.log.lines(pattern, node=self.node)]

    def wait_line(self, pattern, timeout=20.0):
        return self.log.wait_for(pattern, timeout=timeout, node=self.node)


class TestHostileInput(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        rason_rospy.init_node('test_hostile_input')
        cls.log = LogWatcher()

    def setUp(self):
        self.target = None

    def tearDown(self):
        if self.target is not None:
            self.assertEqual(0, self.target.stop(), 'rason_mas ended cleanly')

    def start(self, name, **params):
        self.target = TargetNode(self.log, name, **params).start()
        return self.target

    def survive(self, case_name, params=None, **case_args):
        """Send one case of rason_tools.hostile to a node of its own (with ~params), then
        check: a ping is answered within the bound, every good literal is believed, each
        reason is logged, and each kind of warning stays within the rate limit. Returns the node."""
        target = self.start(case_name, **(params or {}))
        case = hostile.case(case_name, **case_args)
        target.send(case)
        took = target.ping()
        self.assertIsNotNone(took, 'no pong within %.1f s after %s' % (PING_BOUND, case_name))
        # the agent printed this after our OK, which followed every hostile event on its
        # topic, and after it perceived the ping, which followed every hostile perception:
        # every warning about them is in the log before it
        self.assertTrue(target.wait_line(r'^\[%s\] pong %d done$' % (AGENT, target.last_ping)))
        for good in case.good:
            name = re.match(r'kept\((\w+)\)', good).group(1)
            self.assertTrue(target.wait_line(r'^\[%s\] kept %s$' % (AGENT, name), timeout=5.0),
                            '%s: the good literal %s was lost' % (case_name, good))
        for reason in case.reasons:
            self.assertTrue(target.lines(reason), '%s: no line says %r' % (case_name, reason))
        for kind in (DROPPED, IGNORED):
            self.assertLessEqual(len(target.lines(kind)), LINES_PER_PERIOD,
                                 '%s: more than %d lines of a kind' % (case_name, LINES_PER_PERIOD))
        self.assertIsNone(target.proc.poll(), 'rason_mas still runs')
        return target

    def test_deep_terms(self):
        self.survive('deep')

    def test_huge_literals(self):
        self.survive('huge')

    def test_too_many_literals_in_one_message(self):
        self.survive('many_literals')

    def test_numbers_that_are_not_finite(self):
        self.survive('non_finite')

    def test_a_perception_cannot_say_who_said_it(self):
        target = self.survive('reserved')
        self.assertEqual(5, len(target.lines(r'annotation source\(\.\.\.\) is reserved: Jason sets source\(percept\)')))
        # said/1 without annotations is believed (as the percept it is); sent after the
        # reserved ones, its line comes after any theirs would have
        target.perceptions.publish(Perception(source='rostest_said', perception=['said(7)']))
        self.assertTrue(target.wait_line(r'^\[%s\] said 7 from percept$' % AGENT))
        self.assertEqual([], target.lines(r'^\[%s\] said [1-5] ' % AGENT))

    def test_malformed_text_is_dropped_and_summarised(self):
        target = self.survive('malformed', params=dict(warning_period=WARNING_PERIOD))
        bad = len(hostile.case('malformed').perceptions[0][1]) - 1
        self.assertEqual(LINES_PER_PERIOD, len(target.lines(DROPPED)))
        # the rest are counted and summed up when the period (~warning_period) ends
        summary = target.wait_line(r'^dropped perception: … [0-9,]+ more like this', timeout=20.0)
        self.assertTrue(summary, 'no summary of the suppressed lines')
        self.assertIn('%d more like this' % (bad - LINES_PER_PERIOD), summary[0][3])
        seconds = int(re.search(r'in the last ([0-9]+) s$', summary[0][3]).group(1))
        self.assertLess(seconds, 10, 'the period is ~warning_period (%g s), not the default 10 s' % WARNING_PERIOD)

    def test_events_with_bad_agents_ids_and_types(self):
        self.survive('bad_events')

    def test_huge_agent_names_in_events(self):
        self.survive('huge_agent_names', huge_names=HUGE_NAMES, huge_name_chars=HUGE_NAME_CHARS)
        self.assertTrue(all(len(l) < 1000 for l in self.target.lines('')), 'a log line echoes a whole name')

    def test_a_flood_of_source_names(self):
        # A source heard within the TTL keeps being heard while new ones are refused; the
        # ping's source is one, so the TTL must outlast the flood here even on a slow machine.
        target = self.survive('many_sources', params=dict(perception_ttl=30.0))
        self.assertEqual(1, len(target.lines(r'^\[%s\] kept early$' % AGENT)), 'kept(early) was never lost')

    def test_a_flood_ends_with_the_newest_perception(self):
        """A few seconds of as many 50-literal messages as we can publish (up to 1000 Hz)
        from one source; the last one says ``kept(flood_end)`` and must reach the agent
        within the ping bound, and the agent answers pings."""
        target = self.start('flood')
        seconds, period = 3.0, 0.001
        start = next_time = time.monotonic()
        seq = 0
        while time.monotonic() - start < seconds:
            seq += 1
            target.perceptions.publish(Perception(
                source='hostile_flood', perception=['flood(%d)' % seq] + ['p%d(%d)' % (k, seq) for k in range(49)]))
            next_time += period
            time.sleep(max(0.0, next_time - time.monotonic()))
        sent = time.monotonic()
        target.perceptions.publish(Perception(source='hostile_flood', perception=['kept(flood_end)']))
        self.assertTrue(target.wait_line(r'^\[%s\] kept flood_end$' % AGENT, timeout=10.0))
        seen = target.log.lines(r'^\[%s\] kept flood_end$' % AGENT, node=target.node)[0][0]
        self.assertLess(seen - sent, PING_BOUND + 0.5, 'the newest perception came %.2f s late' % (seen - sent))
        took = target.ping()
        self.assertIsNotNone(took, 'no pong within %.1f s after the flood' % PING_BOUND)
        rospy.loginfo('flood: %d messages in %.1f s; newest seen after %.3f s; ping %.3f s',
                      seq, seconds, seen - sent, took)


if __name__ == '__main__':
    rostest.rosrun('rason', 'hostile_input', TestHostileInput)
