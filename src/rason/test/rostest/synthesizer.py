#!/usr/bin/python3
"""rason_wiring's generic_synthesizer, configured only by YAML (agents/wiring/perceptions.yaml),
between topics this test publishes and a Jason agent: nav_msgs/Odometry -> pos(X, Y, Yaw) and
moving (a condition), sensor_msgs/BatteryState -> battery(Percent) and battery_low; the rate
limit, only-when-changed and the refresh, read on jason/perception; malformed configurations
(the node exits 1 with one fatal line naming the entry)."""
import math
import os
import sys
import threading
import time
import unittest

import rason_rospy

import rospy
import rostest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), 'nodes'))
from rason_testing import LogWatcher, run_refused_node, wait_for_link, wait_for_subscribers  # noqa: E402
from nav_msgs.msg import Odometry  # noqa: E402
from rason_msgs.msg import Perception  # noqa: E402
from sensor_msgs.msg import BatteryState  # noqa: E402

NS = 'synth'
AGENT = 'observer'
MAX_RATE = 5.0     # perceptions.yaml's odometry max_rate


def odometry(x, y=0.0, yaw_deg=0.0, speed=0.0):
    msg = Odometry()
    msg.pose.pose.position.x, msg.pose.pose.position.y = x, y
    yaw = math.radians(yaw_deg)
    msg.pose.pose.orientation.z, msg.pose.pose.orientation.w = math.sin(yaw / 2), math.cos(yaw / 2)
    msg.twist.twist.linear.x = speed
    return msg


class Perceptions(object):
    """Every jason/perception message of the namespace: (wall time, source, literals)."""

    def __init__(self):
        self._cond = threading.Condition()
        self.items = []
        rospy.Subscriber('jason/perception', Perception, self._on, queue_size=1000)

    def _on(self, msg):
        with self._cond:
            self.items.append((time.monotonic(), msg.source, list(msg.perception)))
            self._cond.notify_all()

    def wait_for(self, source, literals, since, timeout=10.0):
        """The time of the first message of ``source`` with ``literals`` heard after ``since``."""
        deadline = time.monotonic() + timeout
        with self._cond:
            while True:
                for t, s, p in self.items:
                    if t >= since and s == source and p == literals:
                        return t
                left = deadline - time.monotonic()
                if left <= 0:
                    return None
                self._cond.wait(left)

    def between(self, source, start, end):
        with self._cond:
            return [(t, p) for t, s, p in self.items if s == source and start <= t <= end]


class TestSynthesizer(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        rason_rospy.init_node('test_synthesizer')
        cls.log = LogWatcher()
        cls.perceptions = Perceptions()
        cls.odom = rospy.Publisher('odom', Odometry, queue_size=100)
        cls.battery = rospy.Publisher('battery', BatteryState, queue_size=100)
        for pub in (cls.odom, cls.battery):
            if not wait_for_subscribers(pub, timeout=30):
                raise AssertionError('generic_synthesizer does not subscribe to %s' % pub.resolved_name)
        if not cls.log.wait_ready():
            raise AssertionError('not connected to every /rosout publisher')
        # the agent is there once rason_mas subscribes to jason/perception
        probe = rospy.Publisher('jason/perception', Perception, queue_size=1)
        if not wait_for_subscribers(probe, timeout=30):
            raise AssertionError('rason_mas does not subscribe to jason/perception')
        probe.unregister()
        # generic_synthesizer sends each state once: its link to rason_mas must be up first
        if not wait_for_link(rospy.resolve_name('generic_synthesizer'), rospy.resolve_name('jason/perception'),
                             rospy.resolve_name('rason_mas')):
            raise AssertionError('generic_synthesizer is not connected to rason_mas on jason/perception')

    def said(self, text, timeout=10.0):
        return self.log.wait_for(r'^\[%s\] %s$' % (AGENT, text), timeout=timeout)

    def test_odometry_becomes_pos_with_converted_yaw_and_the_agent_perceives_it(self):
        start = time.monotonic()
        self.odom.publish(odometry(1.25, -0.5, 90.0))
        self.assertTrue(self.said('pos 1.25 -0.5 90'), [l[3] for l in self.log.lines(r'^\[observer\]')])
        self.assertIsNotNone(self.perceptions.wait_for('odom', ['pos(1.25,-0.5,90)'], start))

    def test_a_condition_adds_and_removes_its_literal(self):
        start = time.monotonic()
        self.odom.publish(odometry(3.0, 1.0, 0.0, speed=0.2))
        self.assertIsNotNone(self.perceptions.wait_for('odom', ['pos(3.0,1.0,0)', 'moving'], start))
        self.assertTrue(self.said('moving'))
        self.log.clear()
        self.odom.publish(odometry(3.0, 1.0, 0.0, speed=0.0))
        self.assertTrue(self.said('still'))

    def test_the_rate_limit_holds_and_the_newest_state_still_arrives(self):
        # 100 distinct positions at 100 Hz: at most MAX_RATE lists a second, the last one among them
        start = time.monotonic()
        for i in range(100):
            self.odom.publish(odometry(10.0 + i / 100.0))
            time.sleep(0.01)
        last = self.perceptions.wait_for('odom', ['pos(10.99,0.0,0)'], start, timeout=5)
        self.assertIsNotNone(last, 'the newest position never arrived')
        sent = self.perceptions.between('odom', start, last)
        seconds = last - start
        rospy.loginfo('100 odometry messages in %.2f s -> %d perceptions', seconds, len(sent))
        self.assertLessEqual(len(sent), MAX_RATE * seconds + 2)
        self.assertGreaterEqual(len(sent), 3)
        gaps = [b[0] - a[0] for a, b in zip(sent, sent[1:])]
        self.assertGreater(min(gaps), 1.0 / MAX_RATE * 0.8, gaps)

    def test_only_changed_sends_a_repeated_state_once(self):
        start = time.monotonic()
        for _ in range(20):
            self.battery.publish(BatteryState(percentage=0.5))
            time.sleep(0.02)
        self.battery.publish(BatteryState(percentage=0.15))     # the marker: a change
        marker = self.perceptions.wait_for('generic_synthesizer_battery', ['battery(15)', 'battery_low'], start)
        self.assertIsNotNone(marker)
        sent = self.perceptions.between('generic_synthesizer_battery', start, marker)
        self.assertEqual([p for _, p in sent], [['battery(50)'], ['battery(15)', 'battery_low']])
        self.assertTrue(self.said('battery low'))

    def test_an_unchanged_state_is_refreshed_while_the_topic_goes_on(self):
        start = time.monotonic()
        while time.monotonic() - start < 2.6:
            self.odom.publish(odometry(-7.0))
            time.sleep(0.05)
        end = time.monotonic()
        sent = [t for t, p in self.perceptions.between('odom', start, end + 0.5) if p == ['pos(-7.0,0.0,0)']]
        # the first list, then once a second (refresh: 1.0) although nothing changed
        self.assertGreaterEqual(len(sent), 3, sent)
        self.assertLessEqual(len(sent), 4, sent)

    # ---------------------------------------------------------------- malformed configurations

    def refused(self, name, perceptions):
        code, fatal, out = run_refused_node('rason_wiring', 'generic_synthesizer', NS, name, 'perceptions', perceptions)
        self.assertEqual(code, 1, out)
        self.assertEqual(len(fatal), 1, out)
        return fatal[0]

    def test_a_bad_field_path_stops_the_node_naming_the_entry(self):
        fatal = self.refused('bad_path', {'odometry': {
            'topic': 'odom', 'type': 'nav_msgs/Odometry',
            'literals': {'pos(X)': {'X': 'pose.pose.postion.x'}}}})
        self.assertIn('odometry: literal pos(X): argument X: bad field path pose.pose.postion.x', fatal)

    def test_an_unknown_type_and_no_perceptions_stop_the_node(self):
        fatal = self.refused('bad_type', {'odometry': {
            'topic': 'odom', 'type': 'nav_msgs/Odometri', 'literals': {'pos(X)': {'X': 'pose.pose.position.x'}}}})
        self.assertIn("odometry: unknown message type 'nav_msgs/Odometri'", fatal)
        self.assertIn('~perceptions', self.refused('no_perceptions', {}))


if __name__ == '__main__':
    rostest.rosrun('rason', 'synthesizer', TestSynthesizer)
