#!/usr/bin/python3
"""Lockstep at real-time factor 0: the simulator publishes a camera frame only once
vision_synth has reported the one before done (robots_seen, stamped as the frame), so no
frame is skipped and, in simulated time, a frame waits at most one camera period for its
processing however fast the simulation goes; and it goes no faster than its
~max_lockstep_factor times real time (sim_lockstep.test sets 2)."""
import threading
import time
import unittest

import rason_rospy

import rospy
import rostest
from rosgraph_msgs.msg import Clock
from rason_msgs.msg import RobotSightings
from sensor_msgs.msg import Image

CAMERA_PERIOD = 0.1  # s of simulated time (the simulator's ~camera_rate 10 Hz)
CLOCK_STEP = 0.01    # s (~clock_rate 100 Hz)
FRAMES = 40          # frames reported done before the record is judged
MAX_PACE = 2.0       # sim_lockstep.test's max_lockstep_factor


class FrameWatch(object):
    """Stamps of the frames the simulator sent and of those vision_synth reported done,
    with the simulated time the test had heard when each report came."""

    def __init__(self):
        self.lock = threading.Lock()
        self.clock = None
        self.sent = []
        self.done = []  # (frame stamp, clock heard then)
        self.done_wall = []  # monotonic wall time each report came
        rospy.Subscriber('/clock', Clock, self._on_clock, queue_size=1)
        rospy.Subscriber('/helper/camera/rgb/image_raw', Image, self._on_image, queue_size=100)
        rospy.Subscriber('/helper/robots_seen', RobotSightings, self._on_done, queue_size=100)

    def _on_clock(self, msg):
        with self.lock:
            self.clock = msg.clock.to_sec()

    def _on_image(self, msg):
        with self.lock:
            self.sent.append(msg.header.stamp.to_sec())

    def _on_done(self, msg):
        with self.lock:
            self.done.append((msg.header.stamp.to_sec(), self.clock))
            self.done_wall.append(time.monotonic())

    def wait_for_frames(self, count, timeout):
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline and len(self.done) < count:
            time.sleep(0.1)
        with self.lock:
            return list(self.sent), list(self.done), list(self.done_wall)


class TestSimLockstep(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        rason_rospy.init_node('test_sim_lockstep')

    def test_every_frame_is_processed_before_the_simulation_moves_past_the_next(self):
        sent, done, _ = FrameWatch().wait_for_frames(FRAMES, 90)
        self.assertGreaterEqual(len(done), FRAMES, 'vision_synth reported too few frames')
        first, last = done[0][0], done[-1][0]
        self.assertGreater(last - first, 2.0, 'the simulation hardly moved')
        done_stamps = {round(stamp, 3) for stamp, _ in done}
        # every frame from the first to the last reported one was reported (none skipped)
        skipped = [s for s in sent if first <= s <= last and round(s, 3) not in done_stamps]
        self.assertEqual(skipped, [])
        ahead = [(stamp, heard) for stamp, heard in done if heard is not None
                 and heard - stamp > CAMERA_PERIOD + 5 * CLOCK_STEP]
        self.assertEqual(ahead, [], 'simulated time had moved more than a camera period past these frames')

    def test_the_simulation_goes_no_faster_than_its_ceiling(self):
        # vision_synth alone takes a few ms a frame: without the ceiling lockstep's pace
        # would be well above 10 times real time
        _, done, done_wall = FrameWatch().wait_for_frames(FRAMES, 90)
        self.assertGreaterEqual(len(done), FRAMES, 'vision_synth reported too few frames')
        simulated = done[-1][0] - done[0][0]
        wall = done_wall[-1] - done_wall[0]
        self.assertGreater(simulated, 2.0, 'the simulation hardly moved')
        # a frame's report may come up to a camera period early or late in wall time
        self.assertLessEqual(simulated / wall, MAX_PACE * 1.15,
                             '%.2f s simulated in %.2f s of wall time' % (simulated, wall))


if __name__ == '__main__':
    rostest.rosrun('rason', 'sim_lockstep', TestSimLockstep)
