#!/usr/bin/python3
"""sim_fleet_vision.test: in the fleet world every robot carries its own pair of marker
colours, and r1's vision_synth, whose robots table is the same world file's, names each
robot it sees (robots_seen and the robot(Name, ...) perception) where the simulator has it;
a robot turned round (its cylinders in the other order) is still itself."""
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
from sim_testing import SimRobot, camera_truth, wrap_degrees  # noqa: E402
from rason_msgs.msg import Perception, RobotSightings  # noqa: E402

SEEN = ('r4', 'r5', 'r6')   # in r1's field of view on the circle
ANGLE_DEG, DEPTH_M, YAW_DEG = 1.0, 0.08, 6.0
FRAMES = 10                 # consecutive frames that must all name every robot in view


class Frames(object):
    """robots_seen and perception messages of r1's camera, in order."""

    def __init__(self):
        self.cond = threading.Condition()
        self.sightings, self.perceptions = [], []
        rospy.Subscriber('/r1/robots_seen', RobotSightings, self._on_seen, queue_size=50)
        rospy.Subscriber('/r1/jason/perception', Perception, self._on_perception, queue_size=50)

    def _on_seen(self, msg):
        with self.cond:
            self.sightings.append({r.name: r for r in msg.robots})
            self.cond.notify_all()

    def _on_perception(self, msg):
        with self.cond:
            self.perceptions.append(list(msg.perception))
            self.cond.notify_all()

    def await_a_robot(self, timeout):
        """Waits for the first frame that names a robot: until vision_synth has the camera's
        intrinsics (camera_info) its frames are unusable and name nobody, by design."""
        with self.cond:
            deadline = time.monotonic() + timeout
            while not any(self.sightings):
                left = deadline - time.monotonic()
                if left <= 0:
                    raise AssertionError('no frame named a robot in %.0f s (%d frames)' % (timeout, len(self.sightings)))
                self.cond.wait(left)

    def next_frames(self, count, timeout):
        """The next count robots_seen frames (dicts name -> RobotSighting)."""
        with self.cond:
            start = len(self.sightings)
            deadline = time.monotonic() + timeout
            while len(self.sightings) < start + count:
                left = deadline - time.monotonic()
                if left <= 0:
                    raise AssertionError('%d of %d frames in %.0f s' % (len(self.sightings) - start, count, timeout))
                self.cond.wait(left)
            return self.sightings[start:start + count]


class TestSimFleetVision(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        rason_rospy.init_node('test_sim_fleet_vision')
        cls.frames = Frames()
        cls.robots = {r: SimRobot(r) for r in ('r1',) + SEEN}

    def check_frames(self, poses):
        """FRAMES frames in a row name exactly SEEN, each where poses (x, y, yaw) put it."""
        worst = [0.0, 0.0, 0.0]
        for frame in self.frames.next_frames(FRAMES, 60.0):
            self.assertEqual(sorted(frame), list(SEEN))
            for r in SEEN:
                angle, depth, yaw = camera_truth(poses['r1'], poses[r])
                seen = frame[r]
                self.assertAlmostEqual(seen.angle, angle, delta=ANGLE_DEG, msg=r)
                self.assertAlmostEqual(seen.depth, depth, delta=DEPTH_M, msg=r)
                self.assertLess(abs(wrap_degrees(seen.yaw - yaw)), YAW_DEG, '%s: yaw %.1f, true %.1f' % (r, seen.yaw, yaw))
                worst = [max(worst[0], abs(seen.angle - angle)), max(worst[1], abs(seen.depth - depth)),
                         max(worst[2], abs(wrap_degrees(seen.yaw - yaw)))]
        rospy.loginfo('largest errors over %d frames: angle %.2f deg, depth %.3f m, yaw %.1f deg', FRAMES, *worst)

    def test_each_robot_in_view_is_named_from_the_front_and_from_behind(self):
        poses = {r: robot.pose(timeout=30.0) for r, robot in self.robots.items()}
        self.frames.await_a_robot(60.0)
        self.check_frames(poses)
        with self.frames.cond:
            literals = self.frames.perceptions[-1]
        for r in SEEN:
            self.assertTrue(any(l.startswith('robot(%s,' % r) for l in literals), literals)

        # r5 turned its back on r1: its blue/magenta pair now shows in the other order
        x, y, _ = poses['r5']
        self.robots['r5'].teleport(x, y, math.pi)
        poses['r5'] = self.robots['r5'].pose()
        self.frames.next_frames(2, 30.0)  # frames the camera may have taken before the turn
        self.check_frames(poses)


if __name__ == '__main__':
    rostest.rosrun('rason', 'sim_fleet_vision', TestSimFleetVision)
