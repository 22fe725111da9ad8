#!/usr/bin/python3
"""An agent that changes its mind stops its robot, on the simulator (true poses): each Jason
construct that takes a motion back, the action timeout, .stopMAS, SIGTERM and SIGKILL of the
agents' process, and a killed decomposer. Each method starts its own decomposer and agents."""
import math
import os
import signal
import subprocess
import sys
import threading
import time
import unittest

import rason_rospy

import rospy
import rostest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), 'nodes'))
from rason_testing import HERE, LogWatcher, node_command, start_mas, stop_mas  # noqa: E402
from sim_testing import SimRobot  # noqa: E402
from geometry_msgs.msg import PoseStamped  # noqa: E402
from rason_msgs.msg import Action, Perception  # noqa: E402

NS = 'faulty'
MAS2J = os.path.join(HERE, 'agents', 'preempt', 'taker.mas2j')
START = (-1.0, -0.75, 0.0)
#: Acceptance: after a take-back the robot travels less than this (true pose). The simulated
#: Kobuki brakes at about 1 m/s^2, so from 0.2 m/s about 2 cm of it is braking.
MAX_AFTER_TAKE_BACK = 0.03
#: Acceptance: SIGTERM/SIGKILL of the agents stop the robot within this; a killed decomposer's
#: action fails within DECOMPOSER_LOST_WITHIN.
STOP_WITHIN = 1.0
DECOMPOSER_LOST_WITHIN = 2.0


class Track(object):
    """The true poses of the robot with the (wall) time they were heard."""

    def __init__(self):
        self._lock = threading.Lock()
        self._samples = []
        rospy.Subscriber('/%s/true_pose' % NS, PoseStamped, self._on_pose, queue_size=100)

    def _on_pose(self, msg):
        with self._lock:
            self._samples.append((time.monotonic(), msg.pose.position.x, msg.pose.position.y))

    def now(self):
        with self._lock:
            return self._samples[-1] if self._samples else None

    def wait_moved(self, since, distance, timeout=15.0):
        """Wait until the robot is ``distance`` away from the pose heard at ``since``."""
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            p0, p = self.at(since), self.now()
            if p0 and p and math.hypot(p[1] - p0[1], p[2] - p0[2]) >= distance:
                return True
            time.sleep(0.02)
        return False

    def at(self, when):
        """The last sample heard at or before ``when``."""
        with self._lock:
            before = [s for s in self._samples if s[0] <= when]
            return before[-1] if before else (self._samples[0] if self._samples else None)

    def wait_still(self, still_for=0.5, timeout=10.0):
        """Wait until the pose has not changed by 1 mm for ``still_for`` s; returns the time it last moved."""
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            with self._lock:
                samples = list(self._samples)
            last = samples[-1]
            moved_at = next((s[0] for s in reversed(samples)
                             if math.hypot(s[1] - last[1], s[2] - last[2]) > 0.001), samples[0][0])
            if time.monotonic() - moved_at >= still_for:
                return moved_at
            time.sleep(0.05)
        raise AssertionError('the robot did not come to rest within %.0f s' % timeout)


class TestPreemption(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        rason_rospy.init_node('test_preemption')
        cls.log = LogWatcher()
        cls.robot = SimRobot(NS)
        cls.track = Track()
        cls.perception = rospy.Publisher('/%s/jason/perception' % NS, Perception, queue_size=10)
        cls.actions = []
        rospy.Subscriber('/%s/jason/action' % NS, Action,
                         lambda m: cls.actions.append((time.monotonic(), m)), queue_size=100)

    def setUp(self):
        self.robot.teleport(*START)
        self.decomposer = subprocess.Popen(
            node_command('motion_decomp', 'motion_decomp_node') + [
                '__ns:=/' + NS, 'cmd_vel:=cmd_vel_mux', 'odom:=odom_filtered'])
        self.mas = None
        self.percepts = []

    def tearDown(self):
        # both stop at once: each takes about a second to exit, and nothing here waits on the other
        if self.decomposer.poll() is None:
            self.decomposer.send_signal(signal.SIGTERM)
        if self.mas is not None:
            stop_mas(self.mas)
        self.decomposer.wait(20)

    def start_agents(self, **params):
        self.mas = start_mas(NS, MAS2J, **params)
        deadline = time.monotonic() + 30
        while self.perception.get_num_connections() == 0 or not self.robot.wait_connected(timeout=0.1):
            self.assertLess(time.monotonic(), deadline, 'agents or decomposer never connected')
            time.sleep(0.05)

    def perceive(self, *literals):
        self.percepts += [l for l in literals if l not in self.percepts]
        self.perception.publish(Perception(source='test', perception=self.percepts))

    def drive(self):
        """The agent starts move(3); returns once the robot is under way."""
        started = time.monotonic()
        self.perceive('go')
        self.assertTrue(self.track.wait_moved(started, 0.1), 'the robot never started moving')

    def action_after(self, since, name, timeout=10.0):
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            for t, m in list(self.actions):
                if t >= since and m.action == name:
                    return t, m
            time.sleep(0.01)
        return None, None

    def take_back(self, construct):
        self.start_agents()
        self.drive()
        taken = time.monotonic()
        self.perceive('take(%s)' % construct)
        cancel_at, cancel = self.action_after(taken, Action.CANCEL)
        self.assertIsNotNone(cancel, '%s sent no cancel' % construct)
        self.track.wait_still()
        # from the cancel on the wire: the agent ran the construct a few ms before it
        before, after = self.track.at(cancel_at), self.track.now()
        travelled = math.hypot(after[1] - before[1], after[2] - before[2])
        rospy.loginfo('%s: cancel %.0f ms after the take-back; travelled %.1f mm after it',
                      construct, (cancel_at - taken) * 1e3, travelled * 1e3)
        self.assertLess(travelled, MAX_AFTER_TAKE_BACK)
        return taken

    def next_motion_runs(self):
        since = time.monotonic()
        self.perceive('next')
        t, turn = self.action_after(since, 'turn')
        self.assertIsNotNone(turn, 'the next action was not published')
        self.assertTrue(self.log.wait_for(r'^\[taker\] next done$', timeout=15),
                        'the next action did not end OK: %s' % self.log.lines(r'^\[taker\] next'))
        self.assertFalse(self.log.lines(r'^\[taker\] drive arrived'))

    def test_drop_intention(self):
        self.take_back('drop_intention')
        self.next_motion_runs()

    def test_drop_desire(self):
        self.take_back('drop_desire')
        self.next_motion_runs()

    def test_drop_all_intentions(self):
        self.take_back('drop_all_intentions')
        self.next_motion_runs()

    def test_drop_all_desires(self):
        self.take_back('drop_all_desires')
        self.next_motion_runs()

    def test_fail_goal(self):
        taken = self.take_back('fail_goal')
        self.assertTrue(self.log.wait_for(r'^\[taker\] drive failed$', timeout=10))
        self.assertGreater(self.log.lines(r'^\[taker\] drive failed$')[-1][0], taken)
        self.next_motion_runs()

    def test_succeed_goal(self):
        self.take_back('succeed_goal')
        self.next_motion_runs()

    def test_suspend_then_resume(self):
        taken = self.take_back('suspend')
        self.next_motion_runs()  # the agent goes on while drive is suspended
        self.assertFalse([l for l in self.log.lines(r'^\[taker\] drive failed') if l[0] > taken])
        self.perceive('resume')
        self.assertTrue(self.log.wait_for(r'^\[taker\] drive failed suspended$', timeout=10))

    def test_action_timeout_stops_the_robot(self):
        self.start_agents(action_timeout=2.0)
        since = time.monotonic()
        self.perceive('go')
        self.assertTrue(self.log.wait_for(r'^\[taker\] drive failed timeout$', timeout=15))
        failed = self.log.lines(r'^\[taker\] drive failed timeout$')[-1][0]
        self.assertIsNotNone(self.action_after(since, Action.CANCEL)[1])
        moved_at = self.track.wait_still()
        self.assertLess(moved_at - failed, STOP_WITHIN)

    def test_stop_mas_stops_the_robot(self):
        self.take_back('stop_mas')
        self.assertEqual(self.mas.wait(20), 0)

    def _killed_agents_stop_the_robot(self, sig):
        self.start_agents()
        self.drive()
        killed = time.monotonic()
        self.mas.send_signal(sig)
        moved_at = self.track.wait_still()
        rospy.loginfo('signal %d: the robot stopped %.0f ms after it', sig, (moved_at - killed) * 1e3)
        self.assertLess(moved_at - killed, STOP_WITHIN)
        self.mas.wait(20)

    def test_sigterm_stops_the_robot(self):
        self._killed_agents_stop_the_robot(signal.SIGTERM)

    def test_sigkill_stops_the_robot(self):
        self._killed_agents_stop_the_robot(signal.SIGKILL)

    def test_killed_decomposer_fails_the_action(self):
        self.start_agents()
        self.drive()
        killed = time.monotonic()
        self.decomposer.send_signal(signal.SIGKILL)
        self.assertTrue(self.log.wait_for(r'^\[taker\] drive failed decomposer_lost$', timeout=10))
        failed = self.log.lines(r'^\[taker\] drive failed decomposer_lost$')[-1][0]
        rospy.loginfo('decomposer killed: the action failed %.0f ms later', (failed - killed) * 1e3)
        self.assertLess(failed - killed, DECOMPOSER_LOST_WITHIN)


if __name__ == '__main__':
    rostest.rosrun('rason', 'preemption', TestPreemption)
