#!/usr/bin/python3
"""Under /use_sim_time the agents' Jason timing follows /clock: a .wait(2000) lasts 2 s of
ROS time and a .wait(Event, 1000) times out after 1 s of it, with the clock (this test)
running at half the wall clock's pace; a clock that stands still is said, and its return."""
import os
import re
import sys
import threading
import time
import unittest

import rason_rospy

import rospy
import rostest
from rosgraph_msgs.msg import Clock, Log

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), 'nodes'))
from rason_testing import LogWatcher, start_agents  # noqa: E402

STEP = 0.01         # s of ROS time per /clock message
WALL_PER_STEP = 0.02  # s of wall time per message: the clock runs at half speed
START = 1.0         # s, the first ROS time published


class TestAgentClock(unittest.TestCase):
    last_now = START    # the tests share one rason_mas: the clock goes on from where one left it

    def setUp(self):
        self.now = TestAgentClock.last_now
        self.heard = {}  # what the agent said -> the ROS time it read then, s
        self.lock = threading.Lock()
        self.clock = rospy.Publisher('/clock', Clock, queue_size=1)
        # the clock runs before anything else, as a simulator's does
        self.stop = self._start_clock()
        rospy.Subscriber('/rosout', Log, self._on_log, queue_size=None)

    def tearDown(self):
        self.stop.set()
        with self.lock:
            TestAgentClock.last_now = self.now

    def _start_clock(self):
        stop = threading.Event()
        threading.Thread(target=self._run_clock, args=(self.clock, stop), daemon=True).start()
        return stop

    def _run_clock(self, pub, stop):
        while not stop.is_set():
            with self.lock:
                self.now += STEP
                now = self.now
            pub.publish(Clock(clock=rospy.Time.from_sec(now)))
            time.sleep(WALL_PER_STEP)

    def _on_log(self, msg):
        said = re.match(r'^\[sleeper\] (.*?)(?: at ([\d.]+))?$', msg.msg)
        if said:
            with self.lock:
                self.heard.setdefault(said.group(1), float(said.group(2) or -1) / 1000.0)

    def test_waits_last_their_ros_time(self):
        log = LogWatcher()
        go = start_agents(log, timeout=60)  # noqa: F841 (kept alive for its latch)
        self.assertTrue(log.wait_for(r'^\[sleeper\] gave up waiting at [\d.]+$', timeout=60),
                        'the agent did not end its nap: %s' % self.heard)
        with self.lock:
            heard = dict(self.heard)
        slept = heard['awake'] - heard['asleep']
        waited = heard['gave up waiting'] - heard['awake']
        # not before the ROS time is up (on the wall clock it would be half of it), and at
        # most a few clock steps later; the times are the agent's own readings of the
        # bridge's clock, the one its waits run on
        self.assertGreaterEqual(slept, 2.0 - 1e-6, heard)
        self.assertLess(slept, 2.3, heard)
        self.assertGreaterEqual(waited, 1.0 - 1e-6, heard)
        self.assertLess(waited, 1.3, heard)
        self.assertNotIn('ready', heard)

    def test_when_the_clock_stands_still_it_is_said_and_so_is_its_return(self):
        log = LogWatcher()
        self.assertTrue(log.wait_ready(20), 'not connected to every /rosout publisher')
        self.stop.set()
        # (rason_mas may start watching the clock only now: then it has heard none)
        self.assertTrue(log.wait_for(r'^/clock has not moved for \d+ s \((simulated time stands at [\d.]+ s|no /clock '
                                     r'heard since the start)\): under /use_sim_time the agents', timeout=30),
                        'rason_mas did not say that the clock stands still')
        self.stop = self._start_clock()
        self.assertTrue(log.wait_for(r"^/clock moves again: the agents' waits and timeouts go on$", timeout=10),
                        'rason_mas did not say that the clock moves again')


if __name__ == '__main__':
    rason_rospy.init_node('test_agent_clock')
    rostest.rosrun('rason', 'agent_clock', TestAgentClock)
