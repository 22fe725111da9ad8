#!/usr/bin/python3
"""The simulator at real-time factor 1, with both robots' decomposers, fault injectors and
the vision synthesizer running: both odometries, the camera and vision_synth's perceptions
keep coming and /clock advances with the wall clock. The bounds are loose, for a busy
machine (nominal: 50 Hz odometry, 10 Hz camera, factor 1); make bench measures the rates."""
import threading
import time
import unittest

import rason_rospy

import rospy
import rostest
from nav_msgs.msg import Odometry
from rason_msgs.msg import Perception
from rosgraph_msgs.msg import Clock
from sensor_msgs.msg import CameraInfo

WINDOW = 5.0  # wall seconds


class Counter(object):
    def __init__(self, topic, kind):
        self.lock = threading.Lock()
        self.stamps = []
        self.last = None
        rospy.Subscriber(topic, kind, self._on_msg, queue_size=100)

    def _on_msg(self, msg):
        with self.lock:
            self.stamps.append(time.monotonic())
            self.last = msg

    def rate(self, since):
        with self.lock:
            return sum(1 for t in self.stamps if t >= since) / WINDOW


class TestSimRates(unittest.TestCase):

    def test_everything_keeps_publishing_and_the_clock_advances(self):
        rason_rospy.init_node('test_sim_rates')
        counters = {
            'faulty odom': Counter('/faulty/odom', Odometry),
            'helper odom': Counter('/helper/odom', Odometry),
            'camera': Counter('/helper/camera/rgb/camera_info', CameraInfo),
            'vision': Counter('/helper/jason/perception', Perception),
        }
        clock = Counter('/clock', Clock)
        deadline = time.monotonic() + 30
        while time.monotonic() < deadline and counters['vision'].last is None:
            time.sleep(0.1)  # vision_synth subscribed and publishing: the camera renders
        self.assertIsNotNone(counters['vision'].last, 'vision_synth never published')
        start_wall, start_sim = time.monotonic(), clock.last.clock.to_sec()
        time.sleep(WINDOW)
        rates = {name: c.rate(start_wall) for name, c in counters.items()}
        factor = (clock.last.clock.to_sec() - start_sim) / (time.monotonic() - start_wall)
        rospy.loginfo('rates over %.0f s: %s; real-time factor %.3f', WINDOW,
                      ', '.join('%s %.1f Hz' % kv for kv in sorted(rates.items())), factor)
        self.assertGreater(factor, 0.2)
        self.assertGreater(rates['faulty odom'], 5.0)
        self.assertGreater(rates['helper odom'], 5.0)
        self.assertGreater(rates['camera'], 1.0)
        self.assertGreater(rates['vision'], 1.0)


if __name__ == '__main__':
    rostest.rosrun('rason', 'sim_rates', TestSimRates)
