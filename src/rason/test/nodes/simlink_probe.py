#!/usr/bin/python3
"""A node on a robot's master for test_simlink.py: does what one JSON line on stdin asks
(``{"op": ..., ...}``) and answers with one JSON line on stdout. Waits use wall-clock
deadlines; every answer says what was seen, the test judges it."""
import json
import sys
import threading
import time

import rason_rospy

import rospy
from geometry_msgs.msg import PoseStamped, Twist
from nav_msgs.msg import Odometry
from rason_msgs.msg import RobotSightings
from rosgraph_msgs.msg import Clock
from sensor_msgs.msg import Image


class Probe:

    def __init__(self, robot):
        self.robot = robot
        self.cond = threading.Condition()
        self.clocks, self.odoms, self.poses, self.frames = [], [], [], []
        self.camera = None
        self.ack_pub = None
        rospy.Subscriber('/clock', Clock, self._note, callback_args=('clocks', lambda m: m.clock))
        rospy.Subscriber('/%s/odom' % robot, Odometry, self._note,
                         callback_args=('odoms', lambda m: m.header.stamp))
        rospy.Subscriber('/%s/true_pose' % robot, PoseStamped, self._note,
                         callback_args=('poses', lambda m: m.pose.position.x))
        self.cmd_vel = rospy.Publisher('/%s/cmd_vel' % robot, Twist, queue_size=1)

    def _note(self, msg, args):
        name, value = args
        with self.cond:
            item = value(msg)
            getattr(self, name).append(item.to_sec() if hasattr(item, 'to_sec') else item)
            del getattr(self, name)[:-200]
            self.cond.notify_all()

    def _wait(self, condition, timeout):
        deadline = time.monotonic() + timeout
        with self.cond:
            while not condition():
                left = deadline - time.monotonic()
                if left <= 0:
                    return False
                self.cond.wait(min(left, 0.05))
            return True

    def op_clock(self, timeout=20.0):
        """Two /clock values heard from now on, one after the other."""
        with self.cond:
            self.clocks = []
        self._wait(lambda: len(self.clocks) >= 2, timeout)
        with self.cond:
            return {'first': self.clocks[0] if self.clocks else None,
                    'then': self.clocks[-1] if len(self.clocks) >= 2 else None}

    def op_odom(self, timeout=20.0):
        """The next odometry stamp and the last /clock heard when it came."""
        with self.cond:
            self.odoms = []
        self._wait(lambda: self.odoms and self.clocks, timeout)
        with self.cond:
            if not self.odoms or not self.clocks:
                return {'stamp': None}
            return {'stamp': self.odoms[-1], 'clock': self.clocks[-1]}

    def op_drive(self, distance=0.1, timeout=20.0):
        """Drives forward (cmd_vel 0.3 m/s) until the true pose moved distance, or timeout."""
        if not self._wait(lambda: self.poses, timeout):
            return {'start': None}
        start = self.poses[-1]
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline and self.poses[-1] < start + distance:
            twist = Twist()
            twist.linear.x = 0.3
            self.cmd_vel.publish(twist)
            self._wait(lambda: self.poses[-1] >= start + distance, 0.1)
        self.cmd_vel.publish(Twist())
        return {'start': start, 'end': self.poses[-1]}

    def op_subscribe_camera(self):
        with self.cond:
            self.frames = []
        self.camera = rospy.Subscriber('/%s/camera/depth_registered/image_raw' % self.robot, Image,
                                       self._note, callback_args=('frames', lambda m: m.header.stamp),
                                       queue_size=10)
        return {}

    def op_unsubscribe_camera(self):
        self.camera.unregister()
        self.camera = None
        return {}

    def op_next_frame(self, wait):
        """The oldest frame stamp not yet taken, waiting at most wait s (None: none came)."""
        self._wait(lambda: self.frames, wait)
        with self.cond:
            return {'stamp': self.frames.pop(0) if self.frames else None}

    def op_advertise_ack(self):
        self.ack_pub = rospy.Publisher('/%s/robots_seen' % self.robot, RobotSightings,
                                       queue_size=10)
        return {}

    def op_unadvertise_ack(self):
        self.ack_pub.unregister()
        self.ack_pub = None
        return {}

    def op_ack(self, stamp):
        msg = RobotSightings()
        msg.header.stamp = rospy.Time.from_sec(stamp)
        self.ack_pub.publish(msg)
        return {}


def main():
    rason_rospy.init_node('simlink_probe', anonymous=True, disable_signals=True)
    probe = Probe(sys.argv[1])
    print(json.dumps({'ready': True}), flush=True)
    for line in sys.stdin:
        request = json.loads(line)
        op = request.pop('op')
        print(json.dumps(getattr(probe, 'op_' + op)(**request)), flush=True)
    rospy.signal_shutdown('stdin closed')


if __name__ == '__main__':
    main()
