"""jason/mind: when the agents' states are read, and their snapshots (Java's
``rason.mind.AgentMind``) as a ``rason_msgs/MindState``; no rospy. Its ~params are in
:mod:`rason_bridge.params`.

The snapshots are taken by the agents' own threads in Java (``RosAgArch``); the node's
``rason_mind`` thread only asks the Java ``MindPort.changes()`` for them and publishes, and
turns the reading off while nobody subscribes, so an unwatched robot pays nothing.
"""
import genpy
from rason_msgs.msg import AgentMind, IntentionState, MindState, PendingAction


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
            beliefs=_texts(m.beliefs()), rules=_texts(m.rules()), goals=_texts(m.goals()),
            intentions=[IntentionState(id=int(i.id()), state=str(i.state()), plans=_texts(i.plans()))
                        for i in m.intentions()],
            actions=[PendingAction(id=int(a.id()), action=str(a.action()), started=_time(a.startedNanos()),
                                   held=bool(a.held()))
                     for a in m.actions()],
            events=_texts(m.events()), messages=_texts(m.messages()), omitted=int(m.omitted())))
    return msg
