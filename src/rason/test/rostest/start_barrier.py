#!/usr/bin/python3
"""The start barrier (~await_agents): a program written for one MAS, whose initiator gives the
bidders a second to register in the directory before its call for proposals, split over robots
started 3 s apart. Behind the barrier the initiator finds every bidder and hears every proposal;
the same initiator without it finds nobody."""
import os
import sys
import time
import unittest

import rason_rospy

import rospy
import rostest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), 'nodes'))
from rason_testing import HERE, LogWatcher, start_mas, stop_mas  # noqa: E402

BARRIER_AGENTS = os.path.join(HERE, 'agents', 'barrier')
PARAMS = dict(presence_period=0.3, presence_timeout=1.5)
APART = 3.0  # seconds between the robots' starts: the scenario, not a wait for something


class TestStartBarrier(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        rason_rospy.init_node('test_start_barrier')
        cls.log = LogWatcher()
        assert cls.log.wait_ready(), 'not connected to every /rosout publisher'
        cls.bidders = []

    @classmethod
    def tearDownClass(cls):
        for proc in cls.bidders:
            stop_mas(proc)

    def expect(self, pattern, timeout):
        found = self.log.wait_for(pattern, timeout=timeout)
        self.assertTrue(found, 'never saw %r; heard %r' % (pattern, [l[3] for l in self.log.lines('')][-30:]))
        return found[0][3]

    def test_split_program_finds_every_bidder_behind_the_barrier_and_none_without(self):
        self.expect(r'^holding the agents until agents bidder_b, bidder_c are present', timeout=60)
        # without the barrier, the same initiator searched the directory before any bidder ran
        self.assertEqual(self.expect(r'^\[eager\] found ', timeout=60), '[eager] found 0 bidders: []')
        for i, mas2j in enumerate(('bidder_b.mas2j', 'bidder_c.mas2j')):
            time.sleep(APART)
            self.bidders.append(start_mas('robot%d' % (i + 2), os.path.join(BARRIER_AGENTS, mas2j), **PARAMS))
        self.expect(r'^agents bidder_b, bidder_c present after [0-9.]+ s: starting the agents$', timeout=60)
        self.assertEqual(self.expect(r'^\[initiator\] found ', timeout=30),
                         '[initiator] found 2 bidders: [bidder_b,bidder_c]')
        self.expect(r'^\[initiator\] proposal of bidder_b: 7$', timeout=30)
        self.expect(r'^\[initiator\] proposal of bidder_c: 5$', timeout=30)


if __name__ == '__main__':
    rostest.rosrun('rason', 'start_barrier', TestStartBarrier)
