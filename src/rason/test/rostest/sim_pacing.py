#!/usr/bin/python3
"""The simulator's real-time factor is a ceiling: held still for a while (SIGSTOP, as a
starved CPU holds it), it goes on at the factor from where it was instead of running the
lost time in a burst, which left the camera pipeline and the controllers seconds behind
the world."""
import os
import signal
import threading
import time
import unittest
import xmlrpc.client

import rosgraph
import rason_rospy
import rospy
import rostest
from rosgraph_msgs.msg import Clock

PAUSE = 2.0   # wall seconds the simulator is held
WINDOW = 1.0  # wall seconds measured after it resumes


class ClockWatch(object):
    def __init__(self):
        self.lock = threading.Lock()
        self.samples = []  # (wall, sim)
        rospy.Subscriber('/clock', Clock, self._on_clock, queue_size=1000)

    def _on_clock(self, msg):
        with self.lock:
            self.samples.append((time.monotonic(), msg.clock.to_sec()))

    def sim_at(self, wall):
        """The newest simulated time heard at or before wall."""
        with self.lock:
            heard = [sim for w, sim in self.samples if w <= wall]
        return heard[-1] if heard else None


def node_pid(name):
    api = rosgraph.Master('/test_sim_pacing').lookupNode(name)
    code, _, pid = xmlrpc.client.ServerProxy(api).getPid('/test_sim_pacing')
    if code != 1:
        raise RuntimeError('getPid of %s failed' % name)
    return pid


class TestSimPacing(unittest.TestCase):

    def test_after_a_stall_the_simulation_goes_on_at_its_factor(self):
        rason_rospy.init_node('test_sim_pacing')
        watch = ClockWatch()
        deadline = time.monotonic() + 30
        while time.monotonic() < deadline and watch.sim_at(time.monotonic()) is None:
            time.sleep(0.05)
        self.assertIsNotNone(watch.sim_at(time.monotonic()), 'no /clock')
        pid = node_pid('/rason_sim')
        os.kill(pid, signal.SIGSTOP)
        try:
            time.sleep(PAUSE)
        finally:
            os.kill(pid, signal.SIGCONT)
        resumed = time.monotonic()
        while time.monotonic() < resumed + WINDOW + 0.5:
            time.sleep(0.05)
        start = watch.sim_at(resumed)
        end = watch.sim_at(resumed + WINDOW)
        advanced = end - start
        rospy.loginfo('after a %.1f s stall: %.2f s simulated in the next %.1f s of wall time',
                      PAUSE, advanced, WINDOW)
        # caught up, it would run PAUSE + WINDOW = 3 s of simulated time in that second
        self.assertLess(advanced, WINDOW + 0.5)
        self.assertGreater(advanced, 0.3 * WINDOW, 'the simulation goes on')


if __name__ == '__main__':
    rostest.rosrun('rason', 'sim_pacing', TestSimPacing)
