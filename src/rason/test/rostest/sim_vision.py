#!/usr/bin/python3
"""vision_synth on images rendered by the simulator: the faulty robot teleported to known
poses in front of the helper; robot(Name, Angle, Depth, Yaw) checked against the truth
(Angle within 2 deg, Depth within 5 cm, Yaw within 10 deg), nothing in view -> [], one
cylinder hidden -> no robot. With ``~three: true`` the faulty robot carries the third (blue)
cylinder: it is also found edge-on (left and right on one line of sight) and with the
orange cylinder behind the box."""
import os
import re
import sys
import threading
import time
import math
import unittest

import cv2
import numpy as np
import rason_rospy
import rospy
import rostest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), 'nodes'))
from sim_testing import CAMERA_FORWARD, SimRobot, camera_truth, wrap_degrees  # noqa: E402
from rason_msgs.msg import Perception  # noqa: E402
from sensor_msgs.msg import Image  # noqa: E402

ROBOT = re.compile(r'^robot\((\w+),(-?[\d.]+),(-?[\d.]+),(-?[\d.]+)\)$')
HELPER = (0.0, 0.0, 0.0)


class Perceptions(object):
    """The helper's latest robot(...) perceptions, counted so a test can wait for fresh ones."""

    def __init__(self):
        self._cond = threading.Condition()
        self.count = 0
        self.latest = None
        rospy.Subscriber('/helper/jason/perception', Perception, self._on_msg, queue_size=10)

    def _on_msg(self, msg):
        with self._cond:
            self.count += 1
            self.latest = list(msg.perception)
            self._cond.notify_all()

    def fresh(self, skip=3, timeout=10.0):
        """The list once the frames rendered before a teleport have drained: after ``skip``
        more messages, the first that agrees with the one before it (a busy CPU can hold
        several old frames in the camera -> synthesizer pipeline)."""
        deadline = time.monotonic() + timeout
        with self._cond:
            target = self.count + skip
            previous = None
            while time.monotonic() < deadline:
                if self.count >= target:
                    if previous is not None and same_view(previous, self.latest):
                        return self.latest
                    previous = self.latest
                    target = self.count + 1
                self._cond.wait(0.1)
            return None


def same_view(a, b, angle=0.5, depth=0.02, yaw=2.0):
    """Two perception lists show the same robots at the same places (within noise)."""
    ra, rb = parse(a), parse(b)
    if ra.keys() != rb.keys():
        return False
    return all(abs(ra[n][0] - rb[n][0]) < angle and abs(ra[n][1] - rb[n][1]) < depth
               and abs(wrap_degrees(ra[n][2] - rb[n][2])) < yaw for n in ra)


def parse(literals):
    robots = {}
    for text in literals:
        match = ROBOT.match(text.replace(' ', ''))
        if match:
            robots[match.group(1)] = tuple(float(g) for g in match.groups()[1:])
    return robots


class TestSimVision(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        rason_rospy.init_node('test_sim_vision')
        cls.dim = rospy.get_param('~dim', False)
        cls.three = rospy.get_param('~three', False)
        cls.helper = SimRobot('helper')
        cls.faulty = SimRobot('faulty')
        cls.seen = Perceptions()
        assert cls.seen.fresh(skip=1, timeout=30) is not None, 'vision_synth publishes nothing'

    def place(self, helper, faulty):
        self.helper.teleport(*helper, settle=0.0)
        self.faulty.teleport(*faulty, settle=0.2)
        return self.seen.fresh()

    def test_known_poses(self):
        if self.dim:
            grid = [(d, a, p) for d in (1.5, 2.5) for a in (-15, 15) for p in (0, 40)]
        else:
            grid = [(d, a, p) for d in (1.0, 2.0, 3.0) for a in (-20, 0, 20) for p in (-40, 0, 40, 160)]
        if self.three:  # edge-on: left and right on one line of sight
            grid += [(d, a, a + p) for d in (1.5, 2.5) for a in (-10, 10) for p in (-90, 90)]
        worst = [0.0, 0.0, 0.0]
        for depth, angle, psi in grid:
            # Faulty's centre at `depth` along the optical axis, `angle` to the right, heading psi.
            x = CAMERA_FORWARD + depth
            y = -depth * math.tan(math.radians(angle))
            latest = self.place(HELPER, (x, y, -math.radians(psi)))
            self.assertIsNotNone(latest, 'no perception after teleport')
            truth = camera_truth(self.helper.pose(), self.faulty.pose())
            robots = parse(latest)
            where = 'depth %.1f angle %d heading %d: %s' % (depth, angle, psi, latest)
            self.assertIn('faulty', robots, where)
            seen = robots['faulty']
            errors = (abs(seen[0] - truth[0]), abs(seen[1] - truth[1]),
                      abs(wrap_degrees(seen[2] - truth[2])))
            worst = [max(w, e) for w, e in zip(worst, errors)]
            self.assertLess(errors[0], 2.0, where)
            self.assertLess(errors[1], 0.05, where)
            self.assertLess(errors[2], 10.0, where)
            if 15.0 < abs(truth[2]) < 165.0:  # the sign is meaningless near 0 and 180
                self.assertEqual(math.copysign(1, seen[2]), math.copysign(1, truth[2]), where)
        rospy.loginfo('%d poses; worst errors: angle %.2f deg, depth %.3f m, yaw %.2f deg',
                      len(grid), *worst)

    def test_nothing_in_view_gives_no_robot_only_the_frame_count(self):
        latest = self.place(HELPER, (-2.5, 2.5, 0.0))  # behind the helper
        self.assertEqual(len(latest), 1, latest)
        self.assertRegex(latest[0], r'^cameraFrame\(\d+,\d+\)$')

    def test_one_cylinder_hidden(self):
        """Gives no robot, or, with the third cylinder, the robot where it is."""
        # Helper turned round; the box at (-1.0, 0.06) stands in front of the orange cylinder.
        latest = self.place((0.0, 0.0, math.pi), (-2.0, 0.0, math.pi))
        image = rospy.wait_for_message('/helper/camera/rgb/image_raw', Image, timeout=10)
        hsv = cv2.cvtColor(np.frombuffer(image.data, np.uint8).reshape(image.height, image.width, 3),
                           cv2.COLOR_RGB2HSV)
        green = cv2.inRange(hsv, (40, 90, 10), (90, 255, 255)).sum() // 255
        orange = cv2.inRange(hsv, (4, 130, 12), (24, 255, 255)).sum() // 255
        self.assertGreater(green, 200, 'the green cylinder should be in view')
        self.assertLess(orange, 20, 'the orange cylinder should be hidden')
        if not self.three:
            self.assertEqual(parse(latest), {})
            return
        truth = camera_truth(self.helper.pose(), self.faulty.pose())
        seen = parse(latest).get('faulty')
        self.assertIsNotNone(seen, latest)
        self.assertLess(abs(seen[0] - truth[0]), 2.0, (seen, truth))
        self.assertLess(abs(seen[1] - truth[1]), 0.05, (seen, truth))
        self.assertLess(abs(wrap_degrees(seen[2] - truth[2])), 10.0, (seen, truth))


if __name__ == '__main__':
    rostest.rosrun('rason', 'sim_vision', TestSimVision)
