"""The preemption benchmark's pure parts: the stand-in base's kinematics and the timing of
one take-back (no rospy).

A take-back round: the agent starts ``move(3)``; once the motion is under way (a non-zero
twist on ``cmd_vel``) the harness asks the agent to take it back; the agent reads
``rason.time_ms(T)`` right before ``.drop_intention`` and reports T. The latency of the
round is the first zero twist after the motion was under way minus T (both on
CLOCK_MONOTONIC: Java's ``System.nanoTime``, Python's ``time.monotonic``).
"""
import math


def integrate(pose, linear_x, angular_z, dt):
    """The pose of a unicycle base after driving ``(linear_x, angular_z)`` for ``dt`` s.

    Exact for a constant command: a straight line when ``angular_z`` is 0, else an arc.

    :param pose: ``(x, y, yaw)`` in m, m, rad
    :param linear_x: m/s, forward
    :param angular_z: rad/s, counter-clockwise (REP 103)
    :param dt: seconds; 0 or less leaves the pose as it is
    :returns: ``(x, y, yaw)``, yaw wrapped to (-pi, pi]
    """
    x, y, yaw = pose
    if dt <= 0:
        return pose
    turn = angular_z * dt
    if abs(turn) < 1e-9:
        x += linear_x * dt * math.cos(yaw)
        y += linear_x * dt * math.sin(yaw)
    else:
        radius = linear_x / angular_z
        x += radius * (math.sin(yaw + turn) - math.sin(yaw))
        y -= radius * (math.cos(yaw + turn) - math.cos(yaw))
    return (x, y, wrap(yaw + turn))


def wrap(angle):
    """``angle`` (rad) in (-pi, pi]."""
    a = math.fmod(angle, 2 * math.pi)
    if a <= -math.pi:
        a += 2 * math.pi
    elif a > math.pi:
        a -= 2 * math.pi
    return a


def yaw_quaternion(yaw):
    """``(x, y, z, w)`` of a rotation by ``yaw`` rad about z."""
    return (0.0, 0.0, math.sin(yaw / 2.0), math.cos(yaw / 2.0))


def is_zero(linear_x, linear_y, linear_z, angular_x, angular_y, angular_z):
    """True for the stop command: every component of the twist 0."""
    return not any((linear_x, linear_y, linear_z, angular_x, angular_y, angular_z))


class Round(object):
    """What ``cmd_vel`` showed during one take-back round (times in s, monotonic).

    ``under_way``: the first non-zero twist; ``stopped``: the first zero twist after it.
    Zero twists before the motion is under way (a motion's first tick before odometry)
    do not count.
    """

    def __init__(self):
        self.under_way = None
        self.stopped = None

    def twist(self, now, zero):
        """Record a twist heard at ``now``; ``zero``: it was the stop command."""
        if not zero:
            if self.under_way is None:
                self.under_way = now
        elif self.under_way is not None and self.stopped is None:
            self.stopped = now


def round_latencies(took_back_ms, stopped_s, cancel_seen_s):
    """One round's latencies in ms from the take-back's timestamp.

    :param took_back_ms: T, the agent's ``rason.time_ms`` right before ``.drop_intention``
    :param stopped_s: when the harness heard the zero twist (``time.monotonic``)
    :param cancel_seen_s: when it heard the ``.cancel`` Action on ``jason/action``, or None
    :returns: ``{'stop_ms', 'cancel_ms', 'cancel_to_stop_ms'}`` (the last two None without a cancel)
    """
    stop = stopped_s * 1000.0 - took_back_ms
    if cancel_seen_s is None:
        return {'stop_ms': stop, 'cancel_ms': None, 'cancel_to_stop_ms': None}
    cancel = cancel_seen_s * 1000.0 - took_back_ms
    return {'stop_ms': stop, 'cancel_ms': cancel, 'cancel_to_stop_ms': stop - cancel}


def stopped_on_its_own(rnd, take_back_sent_s):
    """True when the motion's zero twist came before the harness asked for the take-back (the
    motion ended for another reason: that round measures nothing)."""
    return rnd.stopped is not None and rnd.stopped < take_back_sent_s
