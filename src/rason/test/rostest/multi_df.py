#!/usr/bin/python3
"""Jason's directory facilitator across robots: a dispatcher (robot1) finds the couriers
registered on robot2 and robot3 with .df_search, runs a tender with them and awards the
cheapest; its .df_subscribe hears of couriers coming and going; a robot that joins late
(started with rosrun from /) finds the registrations already there, and its own reach
everyone; a robot killed takes its registrations along within the presence timeout.
Nobody announces Jason's internal df agent, so there is no name clash. The couriers'
includes resolve from their project although roslaunch runs them in ROS_HOME."""
import os
import signal
import sys
import time
import unittest

import rason_rospy

import rospy
import rostest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), 'nodes'))
from fleet_wire import fleet_tap  # noqa: E402
from rason_testing import HERE, LogWatcher, Robot, poll, run, start_mas, stop_mas  # noqa: E402

DF_AGENTS = os.path.join(HERE, 'agents', 'df')
TIMEOUT = 1.5          # presence_timeout of every process in this test
PARAMS = dict(presence_period=0.3, presence_timeout=TIMEOUT)
SLACK = 1.5            # rosout, a busy 2-core machine


class TestDirectoryAcrossRobots(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        rason_rospy.init_node('test_multi_df')
        cls.log = LogWatcher()
        cls.robot1 = Robot('robot1')
        cls.robot4 = Robot('robot4')
        cls.robot1.wait_connected()
        assert cls.log.wait_ready()
        for courier in ('swift', 'steady'):
            assert cls.log.wait_for(r'^\[dispatcher\] provider \+ %s delivery$' % courier, timeout=40), \
                'the dispatcher never heard of %s' % courier
        cls.late = None
        cls.announced = {}  # mas_id -> the agents of its latest presence
        cls.tap = fleet_tap(on_presence=cls._on_presence)  # hears the announcements on the fleet channel
        assert cls.tap.wait_ready(3), 'not connected to the fleet channel'

    @classmethod
    def _on_presence(cls, msg):
        if not msg.leaving:
            cls.announced[msg.mas_id] = sorted(msg.agents)

    @classmethod
    def tearDownClass(cls):
        if cls.late is not None:
            stop_mas(cls.late)

    def expect(self, line, timeout=10.0, node=None):
        found = self.log.wait_for(line, timeout=timeout, node=node)
        self.assertTrue(found, 'never saw %r' % line)
        return found

    def start_late_robot(self):
        """robot4 (bargain, asking 3, and the lookout), run from / as a user might, and seen by the dispatcher."""
        self.log.clear()
        type(self).late = start_mas('robot4', os.path.join(DF_AGENTS, 'late.mas2j'), cwd='/', **PARAMS)
        self.robot4.wait_connected()
        self.assertTrue(self.log.wait_ready())
        self.expect(r'^\[dispatcher\] provider \+ bargain delivery$', timeout=40)

    def stop_late_robot(self):
        if self.late is not None:
            stop_mas(self.late)
            type(self).late = None

    def until(self, robot, agent, command, expect, timeout=15.0):
        """Run command until it answers expect (what the agent knows may still be on its way);
        returns the last answer."""
        answers = []

        def answered():
            try:
                answers.append(run(self.log, robot, agent, command, r'\S+ .*', timeout=3))
            except AssertionError as e:  # a robot just started may not have its link to us yet
                answers.append(str(e))
            return answers[-1] == expect
        poll(answered, timeout, interval=0.2)
        return answers[-1]

    def test_df_is_nobodys_agent(self):
        self.start_late_robot()  # it uses the directory too, and everyone hears of it now
        for node in ('/robot1/rason_mas', '/robot2/rason_mas', '/robot3/rason_mas'):
            self.expect(r'^presence: agent lookout is reachable$', node=node)
        # a clash line would have come before the reachable line of the same announcement
        self.assertEqual([], self.log.lines(r"agent name 'df'|announced by both|hosted here and also announced"))
        poll(lambda: len(self.announced) >= 4, 5, interval=0.05)
        self.assertEqual(self.announced, {'/robot1/rason_mas': ['dispatcher'], '/robot2/rason_mas': ['swift'],
                                          '/robot3/rason_mas': ['steady'], '/robot4/rason_mas': ['bargain', 'lookout']})
        self.assertEqual(self.until(self.robot4, 'lookout', 'search', 'found [bargain,steady,swift]'),
                         'found [bargain,steady,swift]')
        self.stop_late_robot()

    def test_a_tender_over_three_robots_goes_to_the_cheapest(self):
        self.stop_late_robot()
        got = run(self.log, self.robot1, 'dispatcher', 'tender(parcel_a)', r'(awarded|no courier|failed) .*',
                  timeout=20)
        self.assertEqual(got, 'awarded parcel_a to swift for 7 among [steady,swift]')
        self.expect(r'^\[swift\] won parcel_a from dispatcher$')
        self.expect(r'^\[steady\] lost parcel_a$')
        self.assertEqual(len(self.log.lines(r'^\[dispatcher\] \d+ awarded parcel_a ')), 1)

    def test_a_late_robot_finds_the_registrations_and_its_own_reach_everyone(self):
        self.start_late_robot()
        # its lookout subscribed before it had heard of anyone: the others' couriers came with their presence
        self.assertEqual(self.until(self.robot4, 'lookout', 'providers', 'told [bargain,steady,swift]'),
                         'told [bargain,steady,swift]')
        self.assertEqual(run(self.log, self.robot4, 'lookout', 'search', r'found .*'), 'found [bargain,steady,swift]')
        got = run(self.log, self.robot1, 'dispatcher', 'tender(parcel_b)', r'(awarded|no courier|failed) .*',
                  timeout=20)
        self.assertEqual(got, 'awarded parcel_b to bargain for 3 among [bargain,steady,swift]')
        self.expect(r'^\[bargain\] won parcel_b from dispatcher$')
        self.stop_late_robot()

    def test_a_robot_killed_takes_its_registrations_along_within_the_presence_timeout(self):
        self.start_late_robot()
        self.late.send_signal(signal.SIGKILL)
        killed = time.monotonic()
        self.late.wait()
        type(self).late = None
        found = self.expect(r'^\[dispatcher\] provider - bargain delivery$', timeout=TIMEOUT + SLACK + 5)
        took = found[0][0] - killed
        rospy.loginfo('bargain left the dispatcher\'s directory %.2f s after its robot was killed', took)
        self.assertLess(took, TIMEOUT + SLACK)
        self.assertEqual(run(self.log, self.robot1, 'dispatcher', 'search', r'found .*'), 'found [steady,swift]')
        got = run(self.log, self.robot1, 'dispatcher', 'tender(parcel_c)', r'(awarded|no courier|failed) .*',
                  timeout=20)
        self.assertEqual(got, 'awarded parcel_c to swift for 7 among [steady,swift]')

    def test_a_robot_stopping_cleanly_is_untold_at_once(self):
        self.start_late_robot()
        stop_mas(self.late)
        stopped = time.monotonic()
        type(self).late = None
        found = self.expect(r'^\[dispatcher\] provider - bargain delivery$', timeout=10)
        self.assertLess(found[0][0] - stopped, TIMEOUT)


if __name__ == '__main__':
    rostest.rosrun('rason', 'multi_df', TestDirectoryAcrossRobots)
