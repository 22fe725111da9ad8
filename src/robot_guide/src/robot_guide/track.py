"""Where a seen robot is now, from where the camera located it. No ROS.

A located point is 0.1–0.3 s old when it reaches the node (the camera's frame, detection),
and a loaded machine can hold frames back longer. A robot that moves meanwhile is no longer
there: aiming at the point, the guide lags behind it by that delay, and stops on the stale
point when frames stall. So the newest point is moved on by the robot's velocity, measured
between located points about ``baseline`` seconds apart (short enough to follow a robot that
speeds up, long enough that the camera's few millimetres of noise make no speed), for at
most ``horizon`` seconds. A speed no robot has (a teleport, a sighting of another place) is
not believed: the track starts again from the newest point.
"""
import math
from collections import deque


class Track(object):
    """The located points of one robot, and where it is now.

    :param baseline: seconds between the two points the velocity is measured from
    :param horizon: seconds at most that the newest point is moved on
    :param max_speed: m/s; a faster move restarts the track
    :param keep: seconds of points kept
    """

    def __init__(self, baseline=0.3, horizon=0.5, max_speed=1.0, keep=1.0):
        self.baseline, self.horizon, self.max_speed, self.keep = baseline, horizon, max_speed, keep
        self._points = deque()     # (stamp, x, y), oldest first
        self.velocity = (0.0, 0.0)

    def add(self, stamp, x, y):
        """A point located in a frame stamped ``stamp`` (seconds); older than the newest: ignored."""
        if self._points and stamp <= self._points[-1][0]:
            return
        self._points.append((stamp, x, y))
        while self._points and self._points[0][0] < stamp - self.keep:
            self._points.popleft()
        # the point closest to `baseline` before this one
        old = min(self._points, key=lambda p: abs(stamp - self.baseline - p[0]))
        dt = stamp - old[0]
        if dt < self.baseline / 2:
            self.velocity = (0.0, 0.0)
            return
        velocity = ((x - old[1]) / dt, (y - old[2]) / dt)
        if math.hypot(*velocity) > self.max_speed:
            self._points = deque([(stamp, x, y)])
            self.velocity = (0.0, 0.0)
        else:
            self.velocity = velocity

    def at(self, now):
        """``(x, y)`` where the robot is at ``now`` (seconds), or None before any point."""
        if not self._points:
            return None
        stamp, x, y = self._points[-1]
        ahead = min(max(now - stamp, 0.0), self.horizon)
        return (x + self.velocity[0] * ahead, y + self.velocity[1] * ahead)
