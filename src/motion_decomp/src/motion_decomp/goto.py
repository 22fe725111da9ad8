"""Driving to a goal pose in the odometry frame: the core of the ``move_base_server`` node
(a ``move_base_msgs/MoveBaseAction`` server for the simulated robots, so agents written for
a ROS navigation stack run on the simulator unchanged). Plain Python, no rospy.

A :class:`GotoController` gets to the goal's position with a steering, then turns to the
goal's heading when it has one. The default :class:`DirectSteering` turns toward the goal
and drives to it (steering as it goes, turning on the spot again when it is more than
``MAX_DRIVE_ERROR`` off, e.g. after passing the goal); ``motion_decomp.arc.ArcSteering``
drives a base that curves by itself (an actuator fault) in planned arcs. The controller
owns what every steering shares: arrival, the final heading, no progress and the timeout.
Poses are ``(x, y, yaw)``
(metres, radians, REP 103: yaw counter-clockwise); times are seconds (the node feeds ROS
time). It ends with:

``succeeded``
    within ``xy_tolerance`` of the goal (and ``yaw_tolerance`` of its heading): it aims at
    half the tolerance, and stops inside the tolerance once it gets no closer;
``no_progress``
    the pose has not changed (< 1 mm and < 0.1 degree, as motion_decomp) for
    ``no_progress_time`` while motion was commanded, or no odometry came at all;
``timeout``
    ``max_duration`` seconds passed.

No obstacle avoidance and no map: the simulator's world is open floor.
"""
import math
from collections import namedtuple

from motion_decomp.geometry import PROGRESS_ANGLE, PROGRESS_DISTANCE, is_finite_pose, wrap_angle

SUCCEEDED = 'succeeded'
NO_PROGRESS = 'no_progress'
TIMEOUT = 'timeout'

#: Default tuning: a Kobuki's comfortable speeds, like motion_decomp.
DEFAULTS = dict(
    linear_speed=0.2,         # m/s, at most
    angular_speed=0.5,        # rad/s, at most
    xy_tolerance=0.05,        # m
    yaw_tolerance=0.05,       # rad (2.9 degrees)
    no_progress_time=2.0,     # s
    max_duration=50.0,        # s; below rason_mas's 60 s ~action_timeout
)
#: Heading error (rad) below which the robot drives (turns on the spot above it) ...
FACING = 0.1
#: ... and above which a drive stops to turn on the spot again.
MAX_DRIVE_ERROR = 0.6
#: Proportional gains: speed per metre of distance, turn rate per radian of error.
LINEAR_GAIN = 1.0
ANGULAR_GAIN = 2.0
#: Floors of the commanded speeds, so that the last centimetres and degrees are covered.
MIN_LINEAR = 0.03
MIN_ANGULAR = 0.1

#: A goal: position and, when ``yaw`` is not None, the heading to end with.
Goal = namedtuple('Goal', 'x y yaw')


def check_options(options):
    """The full option dict (defaults filled in).

    :raises ValueError: an unknown key, or a value that is not a positive finite number
    """
    unknown = set(options) - set(DEFAULTS)
    if unknown:
        raise ValueError('unknown option(s): %s' % ', '.join(sorted(unknown)))
    full = dict(DEFAULTS)
    full.update((k, float(v)) for k, v in options.items())
    for key, value in full.items():
        if not (value > 0 and math.isfinite(value)):
            raise ValueError('%s must be a positive number, got %r' % (key, value))
    return full


def goal_from_pose(x, y, qx, qy, qz, qw):
    """The :class:`Goal` of a target pose: a zero quaternion means "any heading".

    :raises ValueError: a value that is not finite, or a quaternion that is neither zero nor
        of unit length (within 1 %) or that does not turn about z only
    """
    values = (x, y, qx, qy, qz, qw)
    if not all(math.isfinite(v) for v in values):
        raise ValueError('the goal has a value that is not finite: %r' % (values,))
    norm = math.sqrt(qx * qx + qy * qy + qz * qz + qw * qw)
    if norm == 0.0:
        return Goal(float(x), float(y), None)
    if abs(norm - 1.0) > 0.01:
        raise ValueError('the goal orientation is not a unit quaternion (length %.3f)' % norm)
    if abs(qx) > 0.01 or abs(qy) > 0.01:
        raise ValueError('the goal orientation does not turn about z only (a planar robot)')
    return Goal(float(x), float(y), 2.0 * math.atan2(qz, qw))


def toward(error, gain, floor, ceiling):
    """A signed speed that reduces ``error``: proportional (``gain``), at least ``floor``, at
    most ``ceiling`` (floors cover the last centimetres and degrees)."""
    return math.copysign(min(ceiling, max(floor, gain * abs(error))), error)


class DirectSteering(object):
    """Steering of a healthy differential base: turn on the spot toward the goal until within
    ``FACING``, then drive, steering proportionally, until more than ``MAX_DRIVE_ERROR`` off
    (e.g. after passing the goal), then turn on the spot again."""

    TURN, DRIVE = 'turn', 'drive'

    def __init__(self):
        self.phase = self.TURN

    def steer(self, pose, goal, linear_speed, angular_speed):
        """``(linear_x, angular_z)`` toward ``goal``'s position from ``pose``."""
        x, y, yaw = pose
        dx, dy = goal.x - x, goal.y - y
        error = wrap_angle(math.atan2(dy, dx) - yaw)
        if self.phase == self.DRIVE and abs(error) > MAX_DRIVE_ERROR:
            self.phase = self.TURN
        elif self.phase == self.TURN and abs(error) <= FACING:
            self.phase = self.DRIVE
        if self.phase == self.TURN:
            return (0.0, toward(error, ANGULAR_GAIN, MIN_ANGULAR, angular_speed))
        speed = min(linear_speed, max(MIN_LINEAR, LINEAR_GAIN * math.hypot(dx, dy)))
        turn = max(-angular_speed, min(angular_speed, ANGULAR_GAIN * error))
        return (speed * math.cos(error), turn)


class GotoController(object):
    """Drives to one :class:`Goal`: call :meth:`update` each control cycle with the latest
    pose (None while there is none), then publish :meth:`command`.

    :param goal: a :class:`Goal`, or a function of the first pose returning it (a goal
        relative to where the robot is when the drive starts, e.g. "1 m ahead")
    :param steering: how to get to the position: an object with
        ``steer(pose, goal, linear_speed, angular_speed) -> (linear_x, angular_z)``, called
        each cycle until the position is reached; default a new :class:`DirectSteering`
    :param options: keys of :data:`DEFAULTS`
    """

    ALIGN = 'align'

    def __init__(self, goal, now, steering=None, **options):
        opts = check_options(options)
        self.goal = goal if isinstance(goal, Goal) else None
        self._make_goal = None if isinstance(goal, Goal) else goal
        self.steering = steering if steering is not None else DirectSteering()
        self.linear_speed = opts['linear_speed']
        self.angular_speed = opts['angular_speed']
        self.xy_tolerance = opts['xy_tolerance']
        self.yaw_tolerance = opts['yaw_tolerance']
        self.no_progress_time = opts['no_progress_time']
        self.max_duration = opts['max_duration']
        self.started = float(now)
        self.aligning = False        # the position is reached: only the heading is left
        self.result = None
        self.distance = None         # to the goal, at the last pose
        self._command = (0.0, 0.0)
        self._closest = {}           # 'xy' / 'yaw' -> the smallest error seen inside the tolerance
        self._still_pose = None
        self._still_since = self.started

    @property
    def done(self):
        return self.result is not None

    @property
    def phase(self):
        """``align`` once the position is reached, else the steering's phase (if it has one)."""
        return self.ALIGN if self.aligning else getattr(self.steering, 'phase', None)

    def update(self, pose, now):
        """Take the latest pose; returns None while driving, else the result (again and
        again once ended)."""
        if self.result is not None:
            return self.result
        if pose is not None and not is_finite_pose(pose):
            pose = None
        self._command = (0.0, 0.0)
        if pose is not None:
            if self.goal is None:
                self.goal = self._make_goal(tuple(float(v) for v in pose))
            self._note_progress(pose, now)
            if self._steer(pose):
                return self._end(SUCCEEDED)
        if now - self._still_since > self.no_progress_time:
            return self._end(NO_PROGRESS)
        if now - self.started >= self.max_duration:
            return self._end(TIMEOUT)
        return None

    def command(self):
        """``(linear_x, angular_z)`` to command now (m/s, rad/s); zero without a pose and
        after the end."""
        return (0.0, 0.0) if self.result is not None else self._command

    def _note_progress(self, pose, now):
        if self._still_pose is None:
            self._still_pose, self._still_since = pose, now    # commanded from now on
            return
        sx, sy, syaw = self._still_pose
        if (math.hypot(pose[0] - sx, pose[1] - sy) >= PROGRESS_DISTANCE
                or abs(wrap_angle(pose[2] - syaw)) >= PROGRESS_ANGLE):
            self._still_pose, self._still_since = pose, now

    def _steer(self, pose):
        # sets self._command; True once the goal is reached
        x, y, yaw = pose
        self.distance = math.hypot(self.goal.x - x, self.goal.y - y)
        if not self.aligning and self._arrived('xy', self.distance, self.xy_tolerance):
            self.aligning = True     # the position is reached: it stays reached
        if self.aligning:
            if self.goal.yaw is None:
                return True
            error = wrap_angle(self.goal.yaw - yaw)
            if self._arrived('yaw', abs(error), self.yaw_tolerance):
                return True
            self._command = (0.0, toward(error, ANGULAR_GAIN, MIN_ANGULAR, self.angular_speed))
            return False
        self._command = self.steering.steer(pose, self.goal, self.linear_speed, self.angular_speed)
        return False

    def _arrived(self, key, error, tolerance):
        # within half the tolerance, or within it and no closer than before (passing by)
        if error > tolerance:
            self._closest.pop(key, None)
            return False
        closest = self._closest.get(key)
        if error <= tolerance / 2 or (closest is not None and error > closest):
            return True
        self._closest[key] = error
        return False

    def _end(self, result):
        self.result = result
        return result
