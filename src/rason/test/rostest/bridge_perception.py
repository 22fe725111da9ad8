#!/usr/bin/python3
"""Perception semantics: per-source replacement, clearing, TTL expiry, malformed literals
dropped alone, and an idle agent woken by new perceptions."""
import os
import sys
import threading
import time
import unittest

import rason_rospy

import rospy
import rostest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), 'nodes'))
from rason_testing import LogWatcher, wait_for_subscribers  # noqa: E402
from rason_msgs.msg import Perception  # noqa: E402


class TestPerception(unittest.TestCase):
    """Each test publishes from sources of its own, so no test sees another's percepts."""

    @classmethod
    def setUpClass(cls):
        rason_rospy.init_node('test_bridge_perception')
        cls.log = LogWatcher()
        assert cls.log.wait_ready()
        cls.pub = rospy.Publisher('jason/perception', Perception, queue_size=100)
        assert wait_for_subscribers(cls.pub)

    def send(self, source, *literals):
        self.pub.publish(Perception(source=source, perception=list(literals)))

    def expect(self, line, timeout=5.0):
        found = self.log.wait_for(r'^\[watcher\] %s$' % line, timeout=timeout)
        self.assertTrue(found, 'agent never printed %r' % line)
        return found[0][0]

    def test_each_source_replaces_and_clears_only_its_own_percepts(self):
        self.send('a', 'temp(a,1)')
        self.expect(r'\+temp a 1')
        self.send('b', 'temp(b,1)')
        self.expect(r'\+temp b 1')
        self.send('a', 'temp(a,2)')
        self.expect(r'\+temp a 2')
        self.expect(r'-temp a 1')
        self.send('a')
        self.expect(r'-temp a 2')
        self.send('b')
        self.expect(r'-temp b 1')

    def test_a_malformed_literal_is_dropped_alone(self):
        self.send('c', 'temp(c,1)', 'temp(', 'temp(c,X)', 'temp(c,3)')
        self.expect(r'\+temp c 1')
        self.expect(r'\+temp c 3')
        self.assertTrue(self.log.wait_for(r"dropped perception 'temp\(' from source 'c'"))
        self.assertTrue(self.log.wait_for(r"dropped perception 'temp\(c,X\)' from source 'c': .*ground"))
        self.send('c')
        self.expect(r'-temp c 3')

    def test_a_silent_source_expires_after_the_ttl_but_a_live_one_stays(self):
        stop = threading.Event()

        def keep_publishing():  # at 5 Hz, well inside the TTL
            while True:
                self.send('live', 'temp(live,1)')
                if stop.wait(0.2):
                    return
        threading.Thread(target=keep_publishing, daemon=True).start()
        try:
            self.send('silent', 'temp(silent,1)')
            self.expect(r'\+temp live 1')
            added = self.expect(r'\+temp silent 1')
            removed = self.expect(r'-temp silent 1', timeout=10)
            self.assertGreater(removed - added, 0.8)  # TTL is 1 s
            # A second silent source, sent after the first one expired: when it expires
            # too, live has been there longer than a TTL, and the agent would have printed
            # live's removal before this one's.
            self.send('silent2', 'temp(silent2,1)')
            self.expect(r'\+temp silent2 1')
            self.expect(r'-temp silent2 1', timeout=10)
            self.assertFalse(self.log.lines(r'-temp live 1'), 'a source still publishing expired')
        finally:
            stop.set()
        self.expect(r'-temp live 1', timeout=10)

    def test_an_idle_agent_reacts_without_waiting_for_its_sleep(self):
        # the agent must be idle: nothing printed for longer than an idle Jason agent
        # sleeps at most (1 s), so that without the bridge's wake-up it would be asleep
        self.log.wait_quiet(3.0, pattern=r'^\[watcher\] ')
        sent = time.monotonic()
        self.send('d', 'temp(d,1)')
        seen = self.expect(r'\+temp d 1')
        # Woken by the bridge, the agent reacts in milliseconds; without the wake-up it
        # would notice only at the end of its idle sleep, up to 1 s. A loose bound (the
        # latency itself is measured by make bench): reacting within that longest sleep.
        self.assertLess(seen - sent, 1.0)
        self.send('d')

if __name__ == '__main__':
    rostest.rosrun('rason', 'bridge_perception', TestPerception)
