#!/usr/bin/python3
"""Three rason_mas processes: everyone sees everyone, a broadcast from any process
reaches all the others (and only once each), achieve starts goals remotely with the
right source, a list of receivers spans processes, and answers come from the asked one."""
import os
import sys
import unittest

import rason_rospy

import rospy
import rostest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), 'nodes'))
from rason_testing import LogWatcher, Robot, run  # noqa: E402

AGENTS = ['alice', 'bob', 'carol']


class TestThreeProcesses(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        rason_rospy.init_node('test_multi_three')
        cls.log = LogWatcher()
        cls.robots = {a: Robot('robot%d' % (i + 1)) for i, a in enumerate(AGENTS)}
        for r in cls.robots.values():
            r.wait_connected()
        assert cls.log.wait_ready()
        for a in AGENTS:
            for b in AGENTS:
                if a != b:
                    assert cls.log.wait_for(r'^\[%s\] present %s$' % (a, b), timeout=30), '%s never saw %s' % (a, b)

    def expect(self, line, timeout=10.0):
        found = self.log.wait_for(line, timeout=timeout)
        self.assertTrue(found, 'never saw %r' % line)
        return found

    def test_every_process_names_all_three(self):
        for a in AGENTS:
            self.assertEqual(run(self.log, self.robots[a], a, 'names', r'names .*'), 'names [alice,bob,carol]')

    def test_broadcast_from_each_process_reaches_all_others_once(self):
        for k, sender in enumerate(AGENTS):
            run(self.log, self.robots[sender], sender, 'broadcast(tell, hello(%d))' % (20 + k), 'broadcast')
            for receiver in AGENTS:
                if receiver != sender:
                    self.expect(r'^\[%s\] told hello\(%d\) by %s$' % (receiver, 20 + k, sender))
        # Then each process tells the other two something on the same topic. A second copy
        # of a broadcast would have come before it on the same connection; a copy back to
        # the sender before these answers, sent after the broadcast had arrived.
        for k, sender in enumerate(AGENTS):
            others = [a for a in AGENTS if a != sender]
            run(self.log, self.robots[sender], sender,
                'send([%s], tell, hello(%d))' % (', '.join(others), 30 + k), 'sent')
            for receiver in others:
                self.expect(r'^\[%s\] told hello\(%d\) by %s$' % (receiver, 30 + k, sender))
        for k, sender in enumerate(AGENTS):
            for receiver in AGENTS:
                got = self.log.lines(r'^\[%s\] told hello\(%d\) by' % (receiver, 20 + k))
                self.assertEqual(len(got), 0 if receiver == sender else 1, (receiver, sender, got))

    def test_achieve_starts_goals_remotely_with_the_right_source(self):
        run(self.log, self.robots['carol'], 'carol', 'send(alice, achieve, greet(from_carol))', 'sent')
        self.expect(r'^\[alice\] asked to greet from_carol by carol$')
        run(self.log, self.robots['alice'], 'alice', 'send(carol, achieve, greet(from_alice))', 'sent')
        self.expect(r'^\[carol\] asked to greet from_alice by alice$')
        run(self.log, self.robots['bob'], 'bob', 'send(carol, achieve, greet(from_bob))', 'sent')
        self.expect(r'^\[carol\] asked to greet from_bob by bob$')
        # bob heard carol's greet for alice and alice's for carol on his connections from
        # their processes: later messages to him on the same connections come after them
        run(self.log, self.robots['carol'], 'carol', 'send(bob, tell, hello(35))', 'sent')
        self.expect(r'^\[bob\] told hello\(35\) by carol$')
        run(self.log, self.robots['alice'], 'alice', 'send(bob, tell, hello(36))', 'sent')
        self.expect(r'^\[bob\] told hello\(36\) by alice$')
        self.assertFalse(self.log.lines(r'^\[bob\] asked to greet from_(carol|alice)'))

    def test_a_list_of_receivers_spans_processes(self):
        run(self.log, self.robots['alice'], 'alice', 'send([bob, carol], tell, hello(40))', 'sent')
        self.expect(r'^\[bob\] told hello\(40\) by alice$')
        self.expect(r'^\[carol\] told hello\(40\) by alice$')

    def test_each_asked_agent_answers_for_itself(self):
        self.assertEqual(run(self.log, self.robots['alice'], 'alice', 'ask(carol, askOne, secret)', r'answer .*'),
                         'answer secret(carol_secret)[source(carol)]')
        self.assertEqual(run(self.log, self.robots['carol'], 'carol', 'ask(bob, askOne, secret)', r'answer .*'),
                         'answer secret(bob_secret)[source(bob)]')


if __name__ == '__main__':
    rostest.rosrun('rason', 'multi_three', TestThreeProcesses)
