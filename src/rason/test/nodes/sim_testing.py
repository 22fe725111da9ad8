"""Helpers for the rostests against the simulator: true poses, teleporting, running
decomposer actions directly on jason/action, and the camera-frame ground truth."""
import math
import threading
import time

import rosgraph
import rospy
from geometry_msgs.msg import Pose2D, PoseStamped, Twist
from nav_msgs.msg import Odometry
from rason_msgs.msg import Action, Event
from rason_testing import poll

# Where the simulator mounts the Kinect on the helper (rason_sim world.h CameraConfig).
CAMERA_FORWARD = 0.08


def yaw_of(quaternion):
    """Heading (rad, counter-clockwise) of a quaternion that only turns about z."""
    return 2.0 * math.atan2(quaternion.z, quaternion.w)


def wrap_degrees(angle):
    """Into (-180, 180]."""
    angle = math.fmod(angle, 360.0)
    if angle <= -180.0:
        angle += 360.0
    elif angle > 180.0:
        angle -= 360.0
    return angle


def camera_truth(helper, faulty):
    """What the helper's camera should report of the faulty robot.

    helper, faulty: (x, y, yaw) world poses. Returns (angle, depth, yaw) with the
    vision_synth conventions: angle and yaw in degrees, clockwise (right) positive; depth
    along the optical axis to the robot's centre; Yaw = psi + angle, psi the faulty's heading
    relative to the camera's.
    """
    hx, hy, hyaw = helper
    cx, cy = hx + CAMERA_FORWARD * math.cos(hyaw), hy + CAMERA_FORWARD * math.sin(hyaw)
    dx, dy = faulty[0] - cx, faulty[1] - cy
    forward = dx * math.cos(hyaw) + dy * math.sin(hyaw)
    right = dx * math.sin(hyaw) - dy * math.cos(hyaw)
    angle = math.degrees(math.atan2(right, forward))
    psi = -math.degrees(faulty[2] - hyaw)
    return angle, forward, wrap_degrees(psi + angle)


class SimRobot(object):
    """One simulated robot as a test sees it: true pose, teleport, decomposer actions."""

    def __init__(self, name, agent=None):
        self.name = name
        self.agent = agent or name
        self._lock = threading.Condition()
        self._pose = None
        self._results = {}
        self._next_id = 1000
        rospy.Subscriber('/%s/true_pose' % name, PoseStamped, self._on_pose, queue_size=10)
        rospy.Subscriber('/%s/jason/event' % name, Event, self._on_event, queue_size=100)
        self._teleport = rospy.Publisher('/%s/set_pose' % name, Pose2D, queue_size=1)
        self._actions = rospy.Publisher('/%s/jason/action' % name, Action, queue_size=10)

    def _on_pose(self, msg):
        with self._lock:
            self._pose = (msg.pose.position.x, msg.pose.position.y, yaw_of(msg.pose.orientation))
            self._lock.notify_all()

    def _on_event(self, msg):
        if msg.agent != self.agent or msg.event_type != Event.ACTION_FEEDBACK or len(msg.parameters) < 2:
            return
        with self._lock:
            self._results[msg.parameters[1]] = msg.parameters[0]
            self._lock.notify_all()

    def pose(self, timeout=10.0):
        """Latest true pose (x, y, yaw rad); waits for the first one."""
        deadline = time.monotonic() + timeout
        with self._lock:
            while self._pose is None and time.monotonic() < deadline:
                self._lock.wait(0.1)
            return self._pose

    def wait_connected(self, actions=True, timeout=15.0):
        """Wait until the simulator (and, with ``actions``, the decomposer /<name>/motion_decomp)
        listen to us: a message published before the connection is up is lost. Another node
        listening to jason/action (a diagnosis_reporter) does not stand in for the decomposer."""
        decomposer = '/%s/motion_decomp' % self.name
        master = rosgraph.Master(rospy.get_name())

        def listening():
            if not self._teleport.get_num_connections():
                return False
            if not actions:
                return True
            _, subscribers, _ = master.getSystemState()
            nodes = next((n for t, n in subscribers if t == self._actions.resolved_name), [])
            return decomposer in nodes and self._actions.get_num_connections() >= len(nodes)
        return bool(poll(listening, timeout, interval=0.05))

    def teleport(self, x, y, yaw, settle=0.3):
        """Put the robot at (x, y, yaw rad) and wait (sim time) until the pose shows it."""
        if not self.wait_connected(actions=False):
            raise RuntimeError('the simulator does not listen to /%s/set_pose' % self.name)
        self._teleport.publish(Pose2D(x=x, y=y, theta=yaw))

        def there():
            p = self.pose()
            return math.hypot(p[0] - x, p[1] - y) < 0.01 and abs(math.remainder(p[2] - yaw, 2 * math.pi)) < 0.01
        if not poll(there, 10.0):
            raise RuntimeError('%s did not reach the teleport pose: %s' % (self.name, self.pose()))
        # settle s of sim time on purpose: camera frames rendered before the teleport are
        # published by then, and the physics has had its steps after the jump
        rospy.sleep(settle)

    def wait_at_rest(self, still=0.5, timeout=20.0):
        """Wait until the true pose has stayed within 1 mm and 0.1 degree for ``still`` s of sim
        time; returns that pose. Fails after ``timeout`` s (wall) of movement."""
        deadline = time.monotonic() + timeout
        ref, since = self.pose(), rospy.get_time()
        while True:
            p = self.pose()
            if math.hypot(p[0] - ref[0], p[1] - ref[1]) > 0.001 or abs(
                    math.degrees(math.remainder(p[2] - ref[2], 2 * math.pi))) > 0.1:
                ref, since = p, rospy.get_time()
            elif rospy.get_time() - since >= still:
                return p
            if time.monotonic() > deadline:
                raise AssertionError('%s did not come to rest within %.0f s: %s' % (self.name, timeout, p))
            time.sleep(0.02)

    def act(self, action, *parameters, timeout=120.0):
        """Publish a decomposer action and return its result (Event.OK or a failure reason)."""
        self._next_id += 1
        action_id = str(self._next_id)
        self._actions.publish(Action(agent=self.agent, action_id=self._next_id, action=action,
                                     parameters=[str(p) for p in parameters]))
        deadline = time.monotonic() + timeout
        with self._lock:
            while action_id not in self._results and time.monotonic() < deadline:
                self._lock.wait(0.1)
            return self._results.get(action_id)


class BaseWatch(object):
    """The latest odometry pose, the true poses with their sim stamps, cmd_vel_mux."""

    def __init__(self, ns):
        self._cond = threading.Condition()
        self.odom = None
        self.true_poses = []    # (sim time, x, y, yaw)
        self.commands = []      # (wall time, linear x, angular z)
        rospy.Subscriber('/%s/odom_filtered' % ns, Odometry, self._on_odom, queue_size=10)
        rospy.Subscriber('/%s/true_pose' % ns, PoseStamped, self._on_truth, queue_size=100)
        rospy.Subscriber('/%s/cmd_vel_mux' % ns, Twist, self._on_cmd, queue_size=100)

    def _on_odom(self, msg):
        p = msg.pose.pose
        with self._cond:
            self.odom = (p.position.x, p.position.y, yaw_of(p.orientation))

    def _on_truth(self, msg):
        with self._cond:
            self.true_poses.append((msg.header.stamp.to_sec(), msg.pose.position.x, msg.pose.position.y,
                                    yaw_of(msg.pose.orientation)))
            del self.true_poses[:-20000]    # 400 s of sim time at 50 Hz
            self._cond.notify_all()

    def _on_cmd(self, msg):
        with self._cond:
            self.commands.append((time.monotonic(), msg.linear.x, msg.angular.z))

    def wait_sim_time(self, stamp, timeout=20.0):
        """Wait for a true pose stamped ``stamp`` or later; returns those stamped from ``stamp`` on."""
        deadline = time.monotonic() + timeout
        with self._cond:
            while not self.true_poses or self.true_poses[-1][0] < stamp:
                if time.monotonic() > deadline:
                    raise AssertionError('no true pose stamped %.2f s' % stamp)
                self._cond.wait(0.1)
            return [p for p in self.true_poses if p[0] >= stamp]

    def rest_after(self, stamp):
        """Once 1.5 s of sim time has passed since ``stamp``: (metres moved from ``stamp`` until
        1 s after it, metres moved in the 0.5 s after that) by the true pose."""
        self.wait_sim_time(stamp + 1.5)
        with self._cond:
            poses = [p for p in self.true_poses if stamp <= p[0] <= stamp + 1.5]
        at_rest = [p for p in poses if p[0] >= stamp + 1.0]
        spread = max(math.hypot(p[1] - at_rest[0][1], p[2] - at_rest[0][2]) for p in at_rest)
        return math.hypot(at_rest[0][1] - poses[0][1], at_rest[0][2] - poses[0][2]), spread

    def path(self):
        """(x, y) of every true pose heard (the last 400 s of sim time)."""
        with self._cond:
            return [(p[1], p[2]) for p in self.true_poses]

    def commands_since(self, wall_time):
        """(linear x, angular z) of the cmd_vel_mux twists heard since ``wall_time`` (monotonic)."""
        with self._cond:
            return [c[1:] for c in self.commands if c[0] >= wall_time]


def relative(pose, forward, left):
    """The point ``forward`` ahead and ``left`` to the left of ``pose`` (x, y, yaw)."""
    x, y, yaw = pose
    return (x + forward * math.cos(yaw) - left * math.sin(yaw),
            y + forward * math.sin(yaw) + left * math.cos(yaw))
