#!/usr/bin/python3
"""Perception managers chosen per agent: selective perception declared in the .mas2j and
changed by rason.perceive_only/perceive_all (also filtering present/1), a per-source rate
limit that ends a burst with the newest list, accumulate (also loaded by class name) next
to per-source replacement, and a bad option stopping the node with a clear message."""
import itertools
import os
import subprocess
import sys
import time
import unittest

import rospy
import rostest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), 'nodes'))
from rason_testing import LogWatcher, wait_for_subscribers  # noqa: E402
from rason_msgs.msg import Perception  # noqa: E402

AGENTS = os.path.join(os.path.dirname(os.path.abspath(__file__)), 'agents', 'perception')
_ids = itertools.count(1)


class TestPerceptionManagers(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        rospy.init_node('test_perception_managers')
        cls.log = LogWatcher()
        cls.pub = rospy.Publisher('jason/perception', Perception, queue_size=100)
        assert wait_for_subscribers(cls.pub, timeout=30)
        assert cls.log.wait_ready()
        assert cls.log.wait_for(r'^\[plain\] present plain$', timeout=30)

    def send(self, source, *literals):
        self.pub.publish(Perception(source=source, perception=list(literals)))

    def command(self, agent, text, expect):
        n = next(_ids)
        self.send('rostest_cmd_%d' % n, 'cmd(%d, %s, %s)' % (n, agent, text))
        found = self.log.wait_for(r'^\[%s\] %d (%s)$' % (agent, n, expect), timeout=10)
        self.assertTrue(found, '%s: %s gave no %r (got %r)' % (agent, text, expect,
                                                              [l[3] for l in self.log.lines(r'\[%s\] %d ' % (agent, n))]))
        return found[0][3].split(' ', 2)[2]

    def expect(self, line, timeout=10.0):
        found = self.log.wait_for(line, timeout=timeout)
        self.assertTrue(found, 'never saw %r' % line)
        return found[0][0]

    def test_1_selective_agent_gets_only_what_it_declared(self):
        self.send('cam', 'robot(r1,1,2,3)', 'battery(50)', 'temp(20)')
        self.expect(r'^\[plain\] \+robot r1$')
        self.expect(r'^\[plain\] \+battery 50$')
        self.expect(r'^\[plain\] \+temp 20$')
        self.expect(r'^\[picky\] \+robot r1$')
        time.sleep(1.0)
        self.assertFalse(self.log.lines(r'^\[picky\] \+(battery|temp)'))
        # the bridge's present/1 is filtered too: picky did not declare it
        self.assertFalse(self.log.lines(r'^\[picky\] present'))

    def test_2_selection_changes_at_run_time(self):
        self.expect(r'^\[picky\] \+robot r1$')
        self.command('picky', 'perceive_only(["battery/1", "cmd/3"])', r'perceiving only .*')
        # what cam sent last is re-filtered at once, without cam publishing again
        self.expect(r'^\[picky\] \+battery 50$')
        self.expect(r'^\[picky\] -robot r1$')
        self.command('picky', 'perceive_all', 'perceiving all')
        self.expect(r'^\[picky\] \+temp 20$')
        self.expect(r'^\[picky\] present plain$')
        out = self.command('picky', 'perceive_only(["robot"])', r'failed .*')
        self.assertIn('wrong_arguments', out)
        self.assertIn("'robot' is not functor/arity", out)

    def test_3_rate_limit_holds_a_burst_and_applies_the_newest(self):
        self.send('counter', 'count(1)')
        sent = time.monotonic()
        first = self.expect(r'^\[slow\] \+count 1$')
        for k in range(2, 11):  # nine more within about 0.2 s, inside slow's 0.5 s window
            time.sleep(0.02)
            self.send('counter', 'count(%d)' % k)
        burst = time.monotonic() - sent
        last = self.expect(r'^\[slow\] \+count 10$')
        self.expect(r'^\[plain\] \+count 10$')
        time.sleep(1.0)
        between = self.log.lines(r'^\[slow\] \+count ([2-9])$')
        # none, unless this busy machine stretched the burst over more than one window
        self.assertLessEqual(len(between), int(burst / 0.5), 'slow saw held-back updates: %r' % between)
        self.assertGreater(last - first, 0.35)  # the newest waited for the window
        print('rate limit 2/s: burst of 10 in 0.2 s -> 2 updates, the last %.2f s after the first' % (last - first))

    def test_4_rate_limit_bounds_a_steady_stream(self):
        self.log.clear()
        start = time.monotonic()
        k = 100
        while time.monotonic() - start < 2.0:  # 20 Hz for 2 s
            k += 1
            self.send('stream', 'count(%d)' % k)
            time.sleep(0.05)
        self.expect(r'^\[slow\] \+count %d$' % k)  # nothing stale sticks
        time.sleep(0.5)
        slow = len(self.log.lines(r'^\[slow\] \+count 1\d\d$'))
        plain = len(self.log.lines(r'^\[plain\] \+count 1\d\d$'))
        print('steady 20 Hz for 2 s: plain saw %d updates, slow (2/s) saw %d' % (plain, slow))
        self.assertGreaterEqual(slow, 3)
        self.assertLessEqual(slow, 7)
        self.assertGreater(plain, 2 * slow)

    def test_5_accumulate_keeps_every_message_per_source_replaces(self):
        self.send('thermo', 'temp(1)')
        self.expect(r'^\[hoarder\] \+temp 1$')
        self.send('thermo', 'temp(2)')
        self.expect(r'^\[hoarder\] \+temp 2$')
        self.expect(r'^\[plain\] \+temp 2$')
        self.assertEqual(self.command('hoarder', 'temps', r'temps .*'), 'temps [1,2,20]')
        self.assertEqual(self.command('plugin', 'temps', r'temps .*'), 'temps [1,2,20]')
        self.assertEqual(self.command('plain', 'temps', r'temps .*'), 'temps [2,20]')

    def test_6_bad_perception_options_stop_the_node_with_a_clear_message(self):
        for args, why in (
                ([os.path.join(AGENTS, 'bad_manager.mas2j')],
                 "agent 'oops': perception_manager: perception manager 'fancy' is neither per_source, accumulate"),
                ([os.path.join(AGENTS, 'managers.mas2j'), '_perception_manager:=fancier'],
                 "perception_manager: perception manager 'fancier' is neither")):
            proc = subprocess.run(['rosrun', 'rason_bridge', 'rason_mas'] + args + ['__ns:=/bad'],
                                  stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=120)
            out = proc.stdout.decode(errors='replace')
            self.assertEqual(proc.returncode, 1, out)
            self.assertIn(why, out)


if __name__ == '__main__':
    rostest.rosrun('rason', 'perception_managers', TestPerceptionManagers)
