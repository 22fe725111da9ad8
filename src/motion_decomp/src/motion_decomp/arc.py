"""Driving a base that curves by itself, in planned arcs: the steering of ``compensate``
(issue 15). Plain Python, no rospy.

Under the thesis's one-wheel faults (Eq. 6.2/6.3) every forward command of the differential
base comes out as an arc: the robot turns by a fixed ``curvature`` (radians per metre it
travels forward), counter-clockwise for the left actuator, clockwise for the right, whatever
angular speed was commanded, while a turn on the spot (no linear speed) still works.
:class:`ArcSteering` (a steering of :class:`motion_decomp.goto.GotoController`) drives with
that curvature instead of against it:

1. **plan**: the *target* is the goal, or when the goal is farther than the segment length,
   the point that far along the straight line to the goal. The arc of curvature K from the
   robot through the target, over the chord c, leaves at ``alpha = asin(c * K / 2)`` from
   the chord: to the right of the target's bearing for a counter-clockwise curvature, to the
   left for a clockwise one. The segment is never longer than ``SEGMENT_CAP * 2 / K``, so
   ``c * K / 2`` stays below 1 and alpha below 64 degrees;
2. **turn** on the spot to that heading (within ``HEADING_TOLERANCE``), planning again from
   the pose at each cycle (the robot may still be coasting);
3. **drive**: forward speed, zero angular speed (the fault does the turning), slowing down
   over the last ``linear_speed / SLOWDOWN_GAIN`` metres when the target is the goal (an
   intermediate target is passed at full speed: the next turn on the spot stops the robot
   anyway), until the arc ends: the robot gets no closer to the target (by ``PASSED``
   metres: the closest approach is behind it), or its heading has turned more than
   ``2 * alpha + ARC_TURN_MARGIN`` (it curves more than planned: it would circle);
4. back to 1, from the pose where the arc ended.

Odometry closes the loop: every arc starts from the measured pose, and an arc planned with a
curvature that is off misses its target by a fraction of its chord only, so the following
arcs get there too (the tests drive a curvature 20 % off). The controller decides when the
goal is reached, when there is no progress and when time is up.
"""
import math

from motion_decomp.goto import ANGULAR_GAIN, MIN_ANGULAR, MIN_LINEAR, toward
from motion_decomp.geometry import wrap_angle

#: Longest segment, as a fraction of the curvature's diameter 2/K (c * K / 2 <= this).
SEGMENT_CAP = 0.9
#: Heading error (rad) within which the turn on the spot is done and the arc starts: an arc
#: of chord c started this far off misses its target by about c times it (6 mm over 0.3 m).
HEADING_TOLERANCE = 0.02
#: An arc is over once the robot is this much farther from its target than it has been (m).
PASSED = 0.002
#: Commanded speed per metre to the goal on the last arc (1/s): twice goto's LINEAR_GAIN, as
#: a one-wheel fault halves the speed (Eq. 6.3) and the robot should close in as fast.
SLOWDOWN_GAIN = 2.0
#: An arc whose heading has turned this much more than the planned 2 * alpha is over (rad).
ARC_TURN_MARGIN = 0.35


def segment_target(pose, goal_xy, segment_length):
    """The next target: ``goal_xy``, or the point ``segment_length`` along the straight line
    to it when it is farther.

    :param pose: ``(x, y, yaw)``
    :param goal_xy: ``(x, y)``
    :param segment_length: metres, > 0
    """
    x, y = pose[0], pose[1]
    dx, dy = goal_xy[0] - x, goal_xy[1] - y
    distance = math.hypot(dx, dy)
    if distance <= segment_length:
        return (float(goal_xy[0]), float(goal_xy[1]))
    scale = segment_length / distance
    return (x + dx * scale, y + dy * scale)


def arc_heading(pose, target, curvature):
    """The heading from which an arc of ``curvature`` leads from ``pose`` to ``target``, and
    the half angle alpha it turns (the arc turns by 2 * alpha).

    :param pose: ``(x, y, yaw)``
    :param target: ``(x, y)``, closer than 2 / |curvature|
    :param curvature: rad/m, > 0 counter-clockwise, < 0 clockwise, 0 a straight line
    :returns: ``(heading, alpha)`` in radians
    """
    dx, dy = target[0] - pose[0], target[1] - pose[1]
    chord = math.hypot(dx, dy)
    alpha = math.asin(min(1.0, chord * abs(curvature) / 2.0))
    # counter-clockwise arcs leave to the right of the bearing (clockwise: to the left)
    heading = math.atan2(dy, dx) - math.copysign(alpha, curvature)
    return wrap_angle(heading), alpha


class ArcSteering(object):
    """Steers a :class:`~motion_decomp.goto.GotoController` along arcs of a known curvature
    (see the module docstring).

    :param curvature: rad per metre travelled forward; > 0 counter-clockwise (left actuator
        fault), < 0 clockwise (right); not 0 (use the direct steering then)
    :param segment_length: the longest chord of an arc (m); capped at ``SEGMENT_CAP * 2 / |K|``
    """

    PLAN, TURN, DRIVE = 'plan', 'turn', 'drive'

    def __init__(self, curvature, segment_length=0.3):
        curvature = float(curvature)
        if not (curvature != 0 and math.isfinite(curvature)):
            raise ValueError('the curvature must be a finite number other than 0, got %r' % curvature)
        if not (segment_length > 0 and math.isfinite(segment_length)):
            raise ValueError('segment_length must be a positive number, got %r' % segment_length)
        self.curvature = curvature
        self.segment_length = min(float(segment_length), SEGMENT_CAP * 2.0 / abs(curvature))
        self.phase = self.PLAN
        self.target = None        # (x, y) of the arc being turned to or driven
        self.heading = None       # the heading the arc starts with
        self.alpha = None
        self.arcs = 0             # arcs driven so far (each started drive counts)
        self._best = None         # closest distance to the target in this arc
        self._turned = 0.0        # unwrapped heading change in this arc
        self._prev_yaw = None
        self._final = False       # this arc's target is the goal

    def steer(self, pose, goal, linear_speed, angular_speed):
        """``(linear_x, angular_z)`` for this cycle toward ``goal``'s position from ``pose``."""
        if self.phase == self.DRIVE:
            command = self._drive(pose, linear_speed)
            if command is not None:
                return command
            self.phase = self.PLAN        # the arc is over: plan the next one from here
        # PLAN and TURN: plan from the present pose at every cycle (it may still be moving)
        self.target = segment_target(pose, (goal.x, goal.y), self.segment_length)
        self.heading, self.alpha = arc_heading(pose, self.target, self.curvature)
        error = wrap_angle(self.heading - pose[2])
        if abs(error) > HEADING_TOLERANCE:
            self.phase = self.TURN
            return (0.0, toward(error, ANGULAR_GAIN, MIN_ANGULAR, angular_speed))
        self.phase = self.DRIVE
        self.arcs += 1
        self._best = math.hypot(self.target[0] - pose[0], self.target[1] - pose[1])
        self._turned = 0.0
        self._prev_yaw = pose[2]
        self._final = self.target == (goal.x, goal.y)
        return self._drive(pose, linear_speed) or (0.0, 0.0)

    def _drive(self, pose, linear_speed):
        # the forward command while the arc lasts, None once it is over
        x, y, yaw = pose
        self._turned += wrap_angle(yaw - self._prev_yaw)
        self._prev_yaw = yaw
        distance = math.hypot(self.target[0] - x, self.target[1] - y)
        if distance > self._best + PASSED or abs(self._turned) > 2.0 * self.alpha + ARC_TURN_MARGIN:
            return None
        self._best = min(self._best, distance)
        if not self._final:
            return (linear_speed, 0.0)
        return (min(linear_speed, max(MIN_LINEAR, SLOWDOWN_GAIN * distance)), 0.0)
