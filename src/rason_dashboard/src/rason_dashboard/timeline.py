"""What the dashboard shows, as time goes: each robot's agents (jason/mind), the messages
between robots, the rason/* statuses of /diagnostics and the robots' poses, and the view at
any time (with who helps whom, from the messages so far). No rospy: the live node and the bag
replay fill it the same way, with ROS time in seconds. Each robot in a view carries what
changed since its snapshot before (:mod:`rason_dashboard.changes`)."""
import threading

from rason_dashboard.changes import robot_changes
from rason_dashboard.dialogue import helping
from rason_dashboard.fleet_poses import FleetPoses
from rason_dashboard.series import Series

#: How many entries of each kind a live timeline keeps (the oldest go first).
MAX_MINDS_PER_ROBOT = 5000
MAX_MESSAGES = 10000
MAX_STATUSES = 2000
#: How many of the latest messages a view holds.
VIEW_MESSAGES = 200


class Timeline(object):
    """Thread-safe: ROS callbacks add, the web server's threads read."""

    def __init__(self, mode='live'):
        self.mode = mode
        self._lock = threading.Lock()
        self._minds = {}     # mas_id -> Series of mind records
        self._messages = Series(MAX_MESSAGES)
        self._statuses = {}  # status name -> Series of status records
        self._poses = FleetPoses()

    def add_mind(self, t, record):
        with self._lock:
            self._minds.setdefault(record['mas_id'], Series(MAX_MINDS_PER_ROBOT)).add(t, record)

    def add_message(self, t, record):
        with self._lock:
            self._messages.add(t, record)

    def add_status(self, t, record):
        with self._lock:
            self._statuses.setdefault(record['name'], Series(MAX_STATUSES)).add(t, record)

    def add_pose(self, t, kind, robot, pose):
        """A robot's pose: kind 'true' (ground truth), 'odom' (its odometry) or 'origin' (where
        its odometry frame is in the world). False when the pose is not finite (left out)."""
        with self._lock:
            return self._poses.add(t, kind, robot, pose)

    def span(self):
        """(first, last) time of anything added, or None while empty."""
        with self._lock:
            spans = [s.span() for s in list(self._minds.values()) + list(self._statuses.values())
                     + [self._messages]]
        spans = [s for s in spans if s]
        return (min(s[0] for s in spans), max(s[1] for s in spans)) if spans else None

    def view(self, t=None):
        """Everything as it stood at time t (None: now, the newest): JSON-ready."""
        with self._lock:
            robots = []
            for mas_id in sorted(self._minds):
                mind, before = self._minds[mas_id].at_and_before(t)
                if mind is not None:
                    robots.append(_with_ages(robot_changes(before, mind), t))
            every_message = [dict(m, time=mt) for mt, m in self._messages.upto(t, MAX_MESSAGES)]
            messages = every_message[-VIEW_MESSAGES:]
            poses, bounds = self._poses.at(t), self._poses.bounds()
            statuses = []
            for name in sorted(self._statuses):
                s = self._statuses[name].at(t)
                if s is not None:
                    statuses.append(s)
        span = self.span()
        return {'mode': self.mode, 'time': t if t is not None else (span[1] if span else None),
                'span': list(span) if span else None, 'robots': robots, 'messages': messages,
                'statuses': statuses, 'helps': helping(every_message), 'poses': poses, 'bounds': bounds}


def _with_ages(mind, t):
    """A robot's record with each pending action's age at the time viewed (its own stamp when now)."""
    now = mind['stamp'] if t is None else t
    agents = []
    for agent in mind['agents']:
        actions = [dict(a, age=max(0.0, now - a['started'])) for a in agent['actions']]
        agents.append(dict(agent, actions=actions))
    return dict(mind, agents=agents)
