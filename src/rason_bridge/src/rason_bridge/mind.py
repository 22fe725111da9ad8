"""jason/mind: the ~params that shape it, and the agents' snapshots (Java's
``rason.mind.AgentMind``) as a ``rason_msgs/MindState``; no rospy.

The snapshots are taken by the agents' own threads in Java (``RosAgArch``); the node's
``rason_mind`` thread only asks ``Bridge.mindChanges()`` for them and publishes, and
turns the reading off while nobody subscribes, so an unwatched robot pays nothing.
"""
from collections import namedtuple

import genpy
from rason_msgs.msg import AgentMind, IntentionState, MindState, PendingAction

from rason_bridge.limits import seconds_to_nanos

#: The defaults of ~mind_period (s), ~mind_max_items and ~mind_max_chars.
DEFAULT_PERIOD = 0.5
DEFAULT_MAX_ITEMS = 200
DEFAULT_MAX_CHARS = 500
#: The bounds the two limits may take: a snapshot stays far below rospy's message sizes.
MAX_ITEMS = 10000
MIN_CHARS, MAX_CHARS = 16, 100000

MindSettings = namedtuple('MindSettings', 'period max_items max_chars')


def mind_settings(get_param):
    """The jason/mind settings from ``get_param(name, default)`` (private ~params).

    ``mind_period`` 0 turns jason/mind off; otherwise states are read at most that often.

    :raises ValueError: a value out of its range, naming the parameter
    """
    period = get_param('mind_period', DEFAULT_PERIOD)
    seconds_to_nanos('mind_period', period)  # a number, finite, not absurd
    if period < 0:
        raise ValueError('mind_period must be 0 (off) or more seconds, not %r' % (period,))
    max_items = _whole('mind_max_items', get_param('mind_max_items', DEFAULT_MAX_ITEMS), 1, MAX_ITEMS)
    max_chars = _whole('mind_max_chars', get_param('mind_max_chars', DEFAULT_MAX_CHARS), MIN_CHARS, MAX_CHARS)
    return MindSettings(float(period), max_items, max_chars)


def _whole(name, value, low, high):
    if isinstance(value, bool) or not isinstance(value, int) or not low <= value <= high:
        raise ValueError('%s must be a whole number from %d to %d, not %r' % (name, low, high, value))
    return value


class MindSwitch(object):
    """Whether the agents' states are read: only while jason/mind has subscribers
    (a dashboard, ``rostopic echo``, ``rosbag record``)."""

    def __init__(self, period):
        self._period = period
        self.on = False

    def update(self, subscribers):
        """The period to give Java now (0: off), or None when it stays as it is."""
        want = self._period > 0 and subscribers > 0
        if want == self.on:
            return None
        self.on = want
        return self._period if want else 0


def _time(nanos):
    return genpy.Time(nsecs=max(0, int(nanos)))


def _texts(java_list):
    return [str(t) for t in java_list]


def to_msg(mas_id, stamp_nanos, minds, inspector_url=''):
    """A ``MindState`` of the Java ``AgentMind`` records (or anything with the same accessors)."""
    msg = MindState(stamp=_time(stamp_nanos), mas_id=mas_id, inspector_url=inspector_url)
    for m in minds:
        msg.agents.append(AgentMind(
            name=str(m.name()), cycle=int(m.cycle()), stamp=_time(m.stampNanos()),
            beliefs=_texts(m.beliefs()), goals=_texts(m.goals()),
            intentions=[IntentionState(id=int(i.id()), state=str(i.state()), plans=_texts(i.plans()))
                        for i in m.intentions()],
            actions=[PendingAction(id=int(a.id()), action=str(a.action()), started=_time(a.startedNanos()),
                                   held=bool(a.held()))
                     for a in m.actions()],
            events=_texts(m.events()), messages=_texts(m.messages()), omitted=int(m.omitted())))
    return msg
