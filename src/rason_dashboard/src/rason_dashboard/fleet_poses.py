"""Every robot's poses as time goes, and at any time its true pose and the pose it believes
it is at (its odometry placed in the world). Not thread-safe: the Timeline holds its lock."""
import math

from rason_dashboard.poses import anchor, compose
from rason_dashboard.series import Series

#: A robot's pose of one kind is kept at most this often (s): the simulator publishes 50 Hz.
POSE_PERIOD = 0.2
MAX_POSES = 20000
#: Room around the poses seen on the map (m).
MARGIN = 0.75


class FleetPoses(object):

    def __init__(self):
        self._series = {}   # (robot, kind) -> Series of poses; kind 'true', 'odom' or 'origin'
        self._last = {}     # (robot, kind) -> time of the pose last kept
        self._anchors = {}  # robot -> its odometry frame in the world from its first true pose
        self._latest = {}   # (robot, kind) -> the newest pose added, for the anchor
        self._box = None    # [min x, min y, max x, max y] of every pose placed in the world

    def add(self, t, kind, robot, pose):
        """Keeps pose (unless one of the same kind came less than POSE_PERIOD before); False
        when it is not finite (left out: it has no place on a map, nor in JSON)."""
        if not all(math.isfinite(pose[k]) for k in ('x', 'y', 'yaw')):
            return False
        key = (robot, kind)
        self._latest[key] = pose
        if robot not in self._anchors and (robot, 'true') in self._latest and (robot, 'odom') in self._latest:
            self._anchors[robot] = anchor(self._latest[(robot, 'true')], self._latest[(robot, 'odom')])
        last = self._last.get(key)
        if kind != 'origin' and last is not None and abs(t - last) < POSE_PERIOD:
            return True
        self._last[key] = t
        self._series.setdefault(key, Series(MAX_POSES)).add(t, pose)
        world = pose if kind == 'true' else self._believed(robot, pose, None) if kind == 'odom' else None
        if world is not None:
            self._grow(world)
        return True

    def _origin(self, robot, t):
        series = self._series.get((robot, 'origin'))
        origin = series.at(t) if series else None
        return origin or self._anchors.get(robot)

    def _believed(self, robot, odom, t):
        origin = self._origin(robot, t)
        return compose(origin, odom) if origin else dict(odom, frame='odom')

    def _grow(self, p):
        if self._box is None:
            self._box = [p['x'], p['y'], p['x'], p['y']]
        else:
            b = self._box
            self._box = [min(b[0], p['x']), min(b[1], p['y']), max(b[2], p['x']), max(b[3], p['y'])]

    def at(self, t):
        """{robot: {'true': pose or None, 'believed': pose or None}} at time t (None: the
        newest); a believed pose whose odometry frame is not known in the world is marked
        frame 'odom' (drawn where its odometry says, as if that were the world)."""
        robots = {}
        for robot in sorted({r for r, kind in self._series if kind != 'origin'}):
            true = self._series.get((robot, 'true'))
            odom = self._series.get((robot, 'odom'))
            true = true.at(t) if true else None
            odom = odom.at(t) if odom else None
            if true is None and odom is None:
                continue
            robots[robot] = {'true': true, 'believed': None if odom is None else self._believed(robot, odom, t)}
        return robots

    def bounds(self):
        """[min x, min y, max x, max y] of the run's poses with MARGIN round them, or None."""
        if self._box is None:
            return None
        b = self._box
        return [b[0] - MARGIN, b[1] - MARGIN, b[2] + MARGIN, b[3] + MARGIN]
