"""What the dashboard shows, as time goes: each robot's agents (jason/mind), the messages
between robots and the rason/* statuses of /diagnostics, and the view at any time. No rospy:
the live node and the bag replay fill it the same way, with ROS time in seconds. Each robot in
a view carries what changed since its snapshot before (:mod:`rason_dashboard.changes`)."""
import bisect
import threading

from rason_dashboard.changes import robot_changes

#: How many entries of each kind a live timeline keeps (the oldest go first).
MAX_MINDS_PER_ROBOT = 5000
MAX_MESSAGES = 10000
MAX_STATUSES = 2000
#: How many of the latest messages a view holds.
VIEW_MESSAGES = 200


class _Series(object):
    """(time, item) pairs in time order, bounded; the item at or before a time."""

    def __init__(self, limit):
        self._times = []
        self._items = []
        self._limit = limit

    def add(self, t, item):
        i = bisect.bisect_right(self._times, t)  # in time order even when input is not
        self._times.insert(i, t)
        self._items.insert(i, item)
        if len(self._times) > self._limit:
            del self._times[0]
            del self._items[0]

    def at(self, t):
        """The newest item at or before t (None: the newest of all), or None."""
        i = len(self._times) if t is None else bisect.bisect_right(self._times, t)
        return self._items[i - 1] if i else None

    def at_and_before(self, t):
        """The newest item at or before t (None: the newest of all) and the one before it (or None)."""
        i = len(self._times) if t is None else bisect.bisect_right(self._times, t)
        return (self._items[i - 1] if i else None), (self._items[i - 2] if i > 1 else None)

    def upto(self, t, n):
        """The last n (time, item) pairs at or before t (None: the newest)."""
        i = len(self._times) if t is None else bisect.bisect_right(self._times, t)
        return list(zip(self._times[max(0, i - n):i], self._items[max(0, i - n):i]))

    def span(self):
        return (self._times[0], self._times[-1]) if self._times else None


class Timeline(object):
    """Thread-safe: ROS callbacks add, the web server's threads read."""

    def __init__(self, mode='live'):
        self.mode = mode
        self._lock = threading.Lock()
        self._minds = {}     # mas_id -> _Series of mind records
        self._messages = _Series(MAX_MESSAGES)
        self._statuses = {}  # status name -> _Series of status records

    def add_mind(self, t, record):
        with self._lock:
            self._minds.setdefault(record['mas_id'], _Series(MAX_MINDS_PER_ROBOT)).add(t, record)

    def add_message(self, t, record):
        with self._lock:
            self._messages.add(t, record)

    def add_status(self, t, record):
        with self._lock:
            self._statuses.setdefault(record['name'], _Series(MAX_STATUSES)).add(t, record)

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
            messages = [dict(m, time=mt) for mt, m in self._messages.upto(t, VIEW_MESSAGES)]
            statuses = []
            for name in sorted(self._statuses):
                s = self._statuses[name].at(t)
                if s is not None:
                    statuses.append(s)
        span = self.span()
        return {'mode': self.mode, 'time': t if t is not None else (span[1] if span else None),
                'span': list(span) if span else None, 'robots': robots, 'messages': messages,
                'statuses': statuses}


def _with_ages(mind, t):
    """A robot's record with each pending action's age at the time viewed (its own stamp when now)."""
    now = mind['stamp'] if t is None else t
    agents = []
    for agent in mind['agents']:
        actions = [dict(a, age=max(0.0, now - a['started'])) for a in agent['actions']]
        agents.append(dict(agent, actions=actions))
    return dict(mind, agents=agents)
