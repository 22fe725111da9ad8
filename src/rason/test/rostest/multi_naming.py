#!/usr/bin/python3
"""Naming: two robots run the same program and are addressed separately by their
prefixed names; inside a robot the short names reach its own agents; a third robot
that clashes is reported clearly and does not get the other's messages; a bad prefix
stops the node with a clear message."""
import os
import subprocess
import sys
import unittest

import rason_rospy

import rospy
import rostest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), 'nodes'))
from rason_testing import MULTI_AGENTS, LogWatcher, Robot, node_command, run, start_mas, stop_mas, wait_for  # noqa: E402

ALL = 'names [r1_leader,r1_member,r2_leader,r2_member]'
TEAM = os.path.join(MULTI_AGENTS, 'team.mas2j')


class TestNaming(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        rason_rospy.init_node('test_multi_naming')
        cls.log = LogWatcher()
        cls.r1 = Robot('robot1')
        cls.r2 = Robot('robot2')
        cls.r1.wait_connected()
        cls.r2.wait_connected()
        assert cls.log.wait_ready()
        for who, other in (('r1_leader', 'r2_member'), ('r2_leader', 'r1_member')):
            assert cls.log.wait_for(r'^\[%s\] present %s$' % (who, other), timeout=30)

    def expect(self, line, timeout=10.0, node=None):
        found = self.log.wait_for(line, timeout=timeout, node=node)
        self.assertTrue(found, 'never saw %r%s' % (line, ' from ' + node if node else ''))
        return found

    def test_each_robot_names_all_four_agents(self):
        self.assertEqual(run(self.log, self.r1, 'r1_leader', 'names', r'names .*'), ALL)
        self.assertEqual(run(self.log, self.r2, 'r2_member', 'names', r'names .*'), ALL)

    def test_short_names_reach_the_robots_own_agents(self):
        run(self.log, self.r1, 'r1_leader', 'send(member, tell, hello(21))', 'sent')
        self.expect(r'^\[r1_member\] told hello\(21\) by r1_leader$')
        run(self.log, self.r2, 'r2_leader', 'send(member, tell, hello(22))', 'sent')
        self.expect(r'^\[r2_member\] told hello\(22\) by r2_leader$')
        # had a short name left its robot, the message would have gone over the shared
        # topic: later messages to the other robot's member on the same connection come after it
        run(self.log, self.r1, 'r1_leader', 'send(r2_member, tell, hello(23))', 'sent')
        self.expect(r'^\[r2_member\] told hello\(23\) by r1_leader$')
        run(self.log, self.r2, 'r2_leader', 'send(r1_member, tell, hello(24))', 'sent')
        self.expect(r'^\[r1_member\] told hello\(24\) by r2_leader$', node='/robot1/rason_mas')
        self.assertFalse(self.log.lines(r'^\[r2_member\] told hello\(21\)'))
        self.assertFalse(self.log.lines(r'^\[r1_member\] told hello\(22\)'))

    def test_full_names_reach_the_other_robot(self):
        run(self.log, self.r1, 'r1_leader', 'send(r2_member, achieve, greet(x))', 'sent')
        self.expect(r'^\[r2_member\] asked to greet x by r1_leader$')
        self.assertEqual(run(self.log, self.r2, 'r2_member', 'ask(r1_member, askOne, secret)', r'answer .*'),
                         'answer secret(member_secret)[source(r1_member)]')
        self.assertFalse(self.log.lines(r'^\[r1_member\] asked to greet x'))

    def test_a_clashing_robot_is_reported_and_gets_nothing_of_the_first(self):
        clash = start_mas('robot3', TEAM, agent_prefix='r1_')
        try:
            self.expect(r"agent name 'r1_member' is hosted here and also announced by /robot3/rason_mas.*agent_prefix",
                        timeout=60, node='/robot1/rason_mas')
            self.expect(r"agent name 'r1_member' is announced by both /robot1/rason_mas and /robot3/rason_mas: "
                        r"messages to 'r1_member' go to /robot1/rason_mas", node='/robot2/rason_mas')
            self.assertTrue(self.log.wait_ready())
            run(self.log, self.r2, 'r2_leader', 'send(r1_member, tell, hello(41))', 'sent')
            self.expect(r'^\[r1_member\] told hello\(41\) by r2_leader$', node='/robot1/rason_mas')
            # a broadcast from robot2 reaches robot3 too, once robot2's link to it is up (a
            # broadcast goes to whoever is connected; nothing here proves the link earlier, as
            # hello(41) went to robot1): broadcast until robot3 hears one
            for _ in range(10):
                run(self.log, self.r2, 'r2_leader', 'broadcast(tell, hello(42))', 'broadcast')
                if self.log.wait_for(r'^\[r1_member\] told hello\(42\) by r2_leader$', timeout=1.0,
                                     node='/robot3/rason_mas'):
                    break
            self.expect(r'^\[r1_member\] told hello\(42\) by r2_leader$', node='/robot3/rason_mas')
            self.assertFalse(self.log.lines(r'told hello\(41\)', node='/robot3/rason_mas'))
            # still four names, not six
            self.assertEqual(run(self.log, self.r2, 'r2_leader', 'names', r'names .*'), ALL)
        finally:
            self.assertEqual(stop_mas(clash), 0)
        # robot3 gone, the two robots are as the other tests expect them
        for robot, agent in ((self.r1, 'r1_leader'), (self.r2, 'r2_leader')):
            wait_for(lambda: run(self.log, robot, agent, 'names', r'names .*') == ALL, 10,
                     '%s to name the four agents again' % agent, interval=0.2)

    def test_a_bad_prefix_stops_the_node_with_a_clear_message(self):
        proc = subprocess.run(node_command('rason_bridge', 'rason_mas') + [TEAM, '__ns:=/robot4', '_agent_prefix:=R4-'],
                              stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=120)
        out = proc.stdout.decode(errors='replace')
        self.assertEqual(proc.returncode, 1, out)
        self.assertIn("agent prefix 'R4-' must start with a lower-case letter", out)


if __name__ == '__main__':
    rostest.rosrun('rason', 'multi_naming', TestNaming)
