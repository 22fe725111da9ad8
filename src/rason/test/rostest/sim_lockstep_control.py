#!/usr/bin/python3
"""Lockstep with a robot's controller at real-time factor 0: while the helper is commanded
to move, the simulator does not step past the next control tick (50 Hz) before the
controller has reported it on helper/odom_commanded; after a tick that stops the robot, not
before the zero twist has reached helper/cmd_vel; and it publishes the clock of an odometry
message only once the relay (helper/odom_filtered) has passed that message on. The test is a
slow controller and a slow relay: without the waits the simulation would run ahead of both."""
import threading
import time
import unittest

import rason_rospy

import rospy
import rostest
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from rosgraph_msgs.msg import Clock

TICK = 0.02             # s of simulated time (rason_sim ~control_rate 50 Hz)
CLOCK_STEP = 0.01       # s (~clock_rate 100 Hz)
CONTROLLER_WORK = 0.03  # s of wall time the test's controller takes for a tick
RELAY_WORK = 0.01       # s of wall time the test's relay takes for an odometry message
TICKS = 20
TURN = 0.5              # rad/s


class Clocks(object):
    """The newest simulated time heard on /clock, with waits on it."""

    def __init__(self):
        self.cond = threading.Condition()
        self.now = None
        rospy.Subscriber('/clock', Clock, self._on_clock, queue_size=1)

    def _on_clock(self, msg):
        with self.cond:
            self.now = msg.clock.to_sec()
            self.cond.notify_all()

    def heard(self):
        with self.cond:
            return self.now

    def wait_for(self, t, timeout=10.0):
        """The clock heard once it reached t (fails the test after timeout s of wall time)."""
        with self.cond:
            if not self.cond.wait_for(lambda: self.now is not None and self.now >= t - 1e-6, timeout):
                raise AssertionError('the clock did not reach %.2f s (heard %s)' % (t, self.now))
            return self.now


class SlowRelay(object):
    """helper/odom -> helper/odom_filtered, RELAY_WORK late; records (stamp, clock heard)."""

    def __init__(self, clocks):
        self.clocks = clocks
        self.lock = threading.Lock()
        self.relayed = []
        self.pub = rospy.Publisher('/helper/odom_filtered', Odometry, queue_size=100)
        rospy.Subscriber('/helper/odom', Odometry, self._on_odom, queue_size=100)

    def _on_odom(self, msg):
        time.sleep(RELAY_WORK)  # the relay's work
        heard = self.clocks.heard()
        self.pub.publish(msg)
        with self.lock:
            self.relayed.append((msg.header.stamp.to_sec(), heard))

    def records(self):
        with self.lock:
            return list(self.relayed)


def twist(angular):
    msg = Twist()
    msg.angular.z = angular
    return msg


def tick_report(stamp, angular):
    msg = Odometry()
    msg.header.stamp = rospy.Time.from_sec(stamp)
    msg.twist.twist.angular.z = angular
    return msg


class TestSimLockstepControl(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        rason_rospy.init_node('test_sim_lockstep_control')
        cls.clocks = Clocks()
        cls.relay = SlowRelay(cls.clocks)
        cls.cmd_vel = rospy.Publisher('/helper/cmd_vel', Twist, queue_size=10)
        cls.ticks = rospy.Publisher('/helper/odom_commanded', Odometry, queue_size=10)
        deadline = time.monotonic() + 20.0
        while (cls.cmd_vel.get_num_connections() == 0 or cls.ticks.get_num_connections() == 0
               or cls.relay.pub.get_num_connections() == 0) and time.monotonic() < deadline:
            time.sleep(0.05)

    def test_a_moving_robots_controller_ticks_and_its_stop_are_waited_for(self):
        fired = self.clocks.wait_for((self.clocks.heard() or 0.0) + 0.5)
        late = []
        for k in range(TICKS):
            time.sleep(CONTROLLER_WORK)  # the controller's work, on the wall clock
            heard = self.clocks.heard()
            # the first tick is reported while the robot stands, so nothing waits for it, nor
            # (the simulation may have run on before that report came) for the second
            if k > 1 and heard > fired + CLOCK_STEP + 1e-6:
                late.append((fired, heard))
            self.cmd_vel.publish(twist(TURN))
            self.ticks.publish(tick_report(fired, TURN))
            fired = self.clocks.wait_for(fired + TICK)  # the next tick is due
        self.assertEqual(late, [], 'simulated time ran on past these ticks (fired, heard)')
        # a tick that stops the robot, and its zero twist on the way to the base
        self.ticks.publish(tick_report(fired, 0.0))
        time.sleep(CONTROLLER_WORK)  # the zero twist's way through the fault injector
        heard = self.clocks.heard()
        self.cmd_vel.publish(twist(0.0))
        self.assertLessEqual(heard, fired + CLOCK_STEP + 1e-6,
                             'the simulation went on before the stop reached the base')
        # stopped: the simulation runs on without the controller
        self.clocks.wait_for(fired + 1.0)

    def test_odometry_is_relayed_before_its_clock_is_published(self):
        start = self.clocks.wait_for((self.clocks.heard() or 0.0) + 0.5)
        self.clocks.wait_for(start + 1.0)
        relayed = [(stamp, heard) for stamp, heard in self.relay.records() if stamp > start]
        self.assertGreaterEqual(len(relayed), 40, 'too few odometry messages relayed')
        ahead = [(stamp, heard) for stamp, heard in relayed if heard >= stamp - 1e-6]
        self.assertEqual(ahead, [], 'the clock had reached these odometry stamps before they '
                         'were relayed (stamp, clock heard)')


if __name__ == '__main__':
    rostest.rosrun('rason', 'sim_lockstep_control', TestSimLockstepControl)
