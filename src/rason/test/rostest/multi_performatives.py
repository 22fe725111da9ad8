#!/usr/bin/python3
"""Two rason_mas processes: the performatives multi_two and trust_policy leave out (untellHow,
signal), namespaced and annotated content, .send to a list of receivers on both robots,
.broadcast from a plan of a module, and agents created and killed at run time (announced at
once, reachable by name, a remote kill refused with a reason)."""
import itertools
import os
import sys
import time
import unittest

import rason_rospy

import rospy
import rostest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), 'nodes'))
from rason_testing import LogWatcher, Robot, run  # noqa: E402

_tricks = itertools.count(1)


class TestPerformatives(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        rason_rospy.init_node('test_multi_performatives')
        cls.log = LogWatcher()
        cls.r1 = Robot('robot1')  # alice (commands) and ann
        cls.r2 = Robot('robot2')  # bob
        cls.r1.wait_connected()
        cls.r2.wait_connected()
        assert cls.log.wait_ready()
        assert cls.log.wait_for(r'^\[alice\] present bob$', timeout=30)
        assert cls.log.wait_for(r'^\[bob\] present ann$', timeout=30)

    def expect(self, pattern, timeout=10.0):
        found = self.log.wait_for(pattern, timeout=timeout)
        self.assertTrue(found, 'never saw %r' % pattern)
        return found

    def test_told_plans_can_be_untold(self):
        n = next(_tricks)
        plan = '"@taught%d +!trick%d <- .print(\\"trick %d\\")."' % (n, n, n)
        run(self.log, self.r1, 'alice', 'send(bob, tellHow, %s)' % plan, 'sent')
        run(self.log, self.r1, 'alice', 'send(bob, achieve, trick%d)' % n, 'sent')
        self.expect(r'^\[bob\] trick %d$' % n)
        run(self.log, self.r1, 'alice', 'send(bob, untellHow, taught%d)' % n, 'sent')
        run(self.log, self.r1, 'alice', 'send(bob, achieve, trick%d)' % n, 'sent')
        # the plan is gone: Jason's own "no relevant plan" failure, and the plan printed once only
        self.expect(r'trick%d' % n + r'.*(relevant|applicable)|(relevant|applicable).*trick%d' % n)
        self.assertEqual(len(self.log.lines(r'^\[bob\] trick %d$' % n)), 1)

    def test_a_signal_is_an_event_and_no_belief(self):
        run(self.log, self.r1, 'alice', 'send(bob, signal, alarm(3))', 'sent')
        self.expect(r'^\[bob\] signalled alarm\(3\) by alice$')
        self.assertEqual(run(self.log, self.r2, 'bob', 'believes_any(alarm)', r'believes.*'), 'believes no alarm')

    def test_namespaced_content_keeps_its_namespace(self):
        run(self.log, self.r1, 'alice', 'send(bob, tell, inv::item(4))', 'sent')
        self.expect(r'^\[bob\] told inv::item\(4\) by alice$')
        run(self.log, self.r1, 'alice', 'send(bob, tell, ::item(5))', 'sent')
        self.expect(r'^\[bob\] told ::item\(5\) by alice$')
        self.assertFalse(self.log.lines(r'^\[bob\] told ::item\(4\)'))
        self.assertFalse(self.log.lines(r'^\[bob\] told inv::item\(5\)'))
        answer = run(self.log, self.r1, 'alice', 'ask_ns(bob, inv, item)', r'answer .*')
        self.assertRegex(answer, r'^answer inv::item\(4\)\[')

    def test_annotations_cross_both_ways(self):
        run(self.log, self.r1, 'alice', 'send(bob, tell, tagged(6)[mood(happy), urgency(2)])', 'sent')
        answer = run(self.log, self.r1, 'alice', 'ask(bob, askOne, tagged)', r'answer .*')
        for annotation in ('mood(happy)', 'urgency(2)', 'source(alice)'):
            self.assertIn(annotation, answer)

    def test_a_list_of_receivers_on_both_robots(self):
        run(self.log, self.r2, 'bob', 'send([ann, alice], tell, hello(7))', 'sent')
        self.expect(r'^\[ann\] told hello\(7\) by bob$')
        self.expect(r'^\[alice\] told hello\(7\) by bob$')
        run(self.log, self.r1, 'alice', 'send([ann, bob], achieve, greet(seven))', 'sent')
        self.expect(r'^\[ann\] asked to greet seven by alice$')
        self.expect(r'^\[bob\] asked to greet seven by alice$')

    def test_broadcast_from_a_plan_of_a_module(self):
        # ann on alice's robot (Jason's own mailbox) and bob on the other get the same literals
        run(self.log, self.r1, 'alice', 'herald(8)', 'heralded')
        for agent in ('ann', 'bob'):
            self.expect(r'^\[%s\] herald::news 8 from alice$' % agent)
            self.expect(r'^\[%s\] bulletin 8 from alice$' % agent)

    def test_agents_created_and_killed_at_run_time(self):
        created = time.monotonic()
        self.assertEqual(run(self.log, self.r2, 'bob', 'create(scribe, "quiet.asl")', r'created .*'),
                         'created scribe')
        self.expect(r'^\[alice\] present scribe$')
        seen = time.monotonic() - created
        print('an agent created on robot2 perceived by alice after %.2f s (robot2 announces every 5 s)' % seen)
        self.assertLess(seen, 2.5)
        self.assertIn('scribe', run(self.log, self.r1, 'alice', 'names', r'names .*'))
        run(self.log, self.r1, 'alice', 'send(scribe, achieve, greet(new_one))', 'sent')
        self.expect(r'^\[scribe\] asked to greet new_one by alice$')
        # a robot only stops its own agents
        out = run(self.log, self.r1, 'alice', 'kill(scribe)', r'failed .*')
        self.assertIn('failed remote_agent', out)
        self.assertIn('it runs on /robot2/rason_mas', out)
        killed = time.monotonic()
        self.assertEqual(run(self.log, self.r2, 'bob', 'kill(scribe)', r'killed .*'), 'killed scribe')
        self.expect(r'^\[alice\] absent scribe$')
        gone = time.monotonic() - killed
        print('an agent killed on robot2 gone for alice after %.2f s' % gone)
        self.assertLess(gone, 2.5)
        self.assertNotIn('scribe', run(self.log, self.r1, 'alice', 'names', r'names .*'))
        out = run(self.log, self.r1, 'alice', 'send(scribe, tell, hello(9))', r'failed .*')
        self.assertIn('failed receiver_not_found', out)


if __name__ == '__main__':
    rostest.rosrun('rason', 'multi_performatives', TestPerformatives)
