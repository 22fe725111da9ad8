"""Commanded odometry: dead reckoning from the velocity commands the decomposer sends (issue
15), without rospy.

When the encoders fail, the wheel odometry says nothing useful, but the robot still knows what
it commanded: integrating those twists from the zero pose tells how far, and where, it told
itself to go. It is what the robot would have done on a healthy base: an actuator fault bends
the real path (the fault injector sits after the decomposer), this pose does not bend.

A command stays in force until the next one, for at most ``command_timeout`` seconds: the base
(Kobuki, and the simulator) stops by itself when no ``cmd_vel`` came for 0.6 s.
"""
import math

from motion_decomp.geometry import wrap_angle

#: Seconds a command keeps the base moving without a newer one (kobuki_node's 0.6 s).
COMMAND_TIMEOUT = 0.6


class CommandedOdometry(object):
    """The integrated pose of the commanded twists.

    :param command_timeout: seconds a command stays in force without a newer one
    """

    def __init__(self, command_timeout=COMMAND_TIMEOUT):
        if not (command_timeout > 0 and math.isfinite(command_timeout)):
            raise ValueError('command_timeout must be a positive number, got %r' % command_timeout)
        self.command_timeout = float(command_timeout)
        self.pose = (0.0, 0.0, 0.0)       # x, y (m), yaw (rad) in the commanded frame
        self._twist = (0.0, 0.0)          # the last command: linear x (m/s), angular z (rad/s)
        self._commanded_at = None
        self._time = None                 # the pose is integrated up to this time

    def command(self, linear_x, angular_z, now):
        """A twist was sent at ``now``: integrate up to now, then hold the new one.

        :param linear_x: m/s
        :param angular_z: rad/s
        :param now: seconds
        """
        self.advance(now)
        self._twist = (float(linear_x), float(angular_z))
        self._commanded_at = float(now)

    def advance(self, now):
        """Integrate the command in force up to ``now``; returns the pose.

        When time goes back (a restarted simulation), nothing is integrated: the integration
        goes on from ``now``.
        """
        now = float(now)
        if self._time is not None and now >= self._time:
            end = now if self._commanded_at is None else min(now, self._commanded_at + self.command_timeout)
            if end > self._time:
                self.pose = integrate(self.pose, self._twist[0], self._twist[1], end - self._time)
        elif self._time is not None and self._commanded_at is not None:
            self._commanded_at = min(self._commanded_at, now)
        self._time = now
        return self.pose

    def twist(self, now):
        """The commanded twist in force at ``now``: ``(linear_x, angular_z)``, zero once the
        last command is older than ``command_timeout``."""
        if self._commanded_at is None or now - self._commanded_at > self.command_timeout:
            return (0.0, 0.0)
        return self._twist


def integrate(pose, linear_x, angular_z, dt):
    """The pose after driving ``(linear_x, angular_z)`` for ``dt`` seconds from ``pose``,
    exactly (a circular arc, or a straight line when ``angular_z`` is 0).

    :param pose: ``(x, y, yaw)``
    """
    x, y, yaw = pose
    if abs(angular_z) < 1e-9:
        return (x + linear_x * math.cos(yaw) * dt, y + linear_x * math.sin(yaw) * dt, yaw)
    end = yaw + angular_z * dt
    radius = linear_x / angular_z
    return (x + radius * (math.sin(end) - math.sin(yaw)),
            y - radius * (math.cos(end) - math.cos(yaw)),
            wrap_angle(end))
