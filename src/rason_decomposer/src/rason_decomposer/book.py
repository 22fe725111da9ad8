"""The actions a decomposer holds: plain Python, no rospy.

An :class:`ActionBook` answers the questions of the cancel protocol (see
``rason_msgs/Action.msg`` and ``Event.msg``):

- which actions does this decomposer hold (taken, not answered yet), in the order taken;
- which of them does an ``Action.CANCEL`` stop (one ``action_id``, or 0: all of the agent);
- which of them were requested over a link that is gone (the requester is compared by
  identity: rospy gives every message of one connection the very same header dict);
- and it makes sure each action is answered exactly once: :meth:`ActionBook.finish`,
  :meth:`ActionBook.cancel` and :meth:`ActionBook.lost` all take the action out of the
  book, so whichever comes first is the only end; later calls find nothing.

Not thread-safe: the caller holds its own lock around each call.
"""
from collections import OrderedDict, namedtuple

#: What to publish on jason/event: ``Event(agent, Event.ACTION_FEEDBACK, [result, str(action_id)])``.
Feedback = namedtuple('Feedback', 'agent action_id result')


class HeldAction(object):
    """An action a decomposer took.

    :ivar agent: the requesting agent (echoed in every event)
    :ivar action_id: the agent's id of the action (echoed in every event)
    :ivar name: the action's functor, e.g. ``move``
    :ivar parameters: the action's arguments as text (a list)
    :ivar requester: what identifies the link the action came over (compared by identity),
        or ``None`` when it cannot be watched
    """

    def __init__(self, agent, action_id, name, parameters, requester):
        self.agent = agent
        self.action_id = int(action_id)
        self.name = name
        self.parameters = list(parameters)
        self.requester = requester

    @property
    def key(self):
        """``(agent, action_id)``: what the protocol identifies the action by."""
        return (self.agent, self.action_id)

    def feedback(self, result):
        """The :class:`Feedback` that answers this action with ``result``."""
        return Feedback(self.agent, self.action_id, result)

    def __repr__(self):
        return '%s:%s(%s)#%d' % (self.agent, self.name, ', '.join(self.parameters), self.action_id)


class ActionBook(object):
    """The actions a decomposer holds, oldest first."""

    def __init__(self):
        self._held = OrderedDict()   # (agent, action_id) -> HeldAction

    def take(self, agent, action_id, action, parameters, requester=None):
        """Hold a new action.

        :param agent: the requesting agent
        :param action_id: the agent's id of the action; 0 is not an action (it means "all")
        :param action: the functor
        :param parameters: the arguments as text
        :param requester: opaque object identifying the link the action came over (compared
            by identity in :meth:`lost`); ``None``: never counted as lost
        :returns: the new :class:`HeldAction`
        :raises ValueError: ``(agent, action_id)`` is already held, or action_id is 0
        """
        held = HeldAction(agent, action_id, action, parameters, requester)
        if held.action_id == 0:
            raise ValueError('action id 0 means "every action" in a cancel; no action has it')
        if held.key in self._held:
            raise ValueError('%s: action %d is already held (%r)'
                             % (agent, held.action_id, self._held[held.key]))
        self._held[held.key] = held
        return held

    def finish(self, agent, action_id, result, held=None):
        """The action ended with ``result``: returns its :class:`Feedback`, to publish.

        Returns ``None`` when the action is not held (unknown, or already finished,
        cancelled or lost): the caller publishes nothing, so each action is answered once.

        :param held: when given, only that very :class:`HeldAction` is finished (not a newer
            action that reuses the same id, e.g. from a restarted agent)
        """
        key = (agent, int(action_id))
        current = self._held.get(key)
        if current is None or (held is not None and current is not held):
            return None
        del self._held[key]
        return current.feedback(result)

    def cancel(self, agent, action_id):
        """Take the actions an ``Action.CANCEL`` names out of the book; returns them, oldest first.

        The caller stops each of them and answers it ``Event.CANCELLED``.

        :param action_id: the action to stop, or 0: every action of ``agent``
        :returns: list of :class:`HeldAction`; empty for an unknown or finished id
        """
        action_id = int(action_id)
        if action_id == 0:
            gone = [h for h in self._held.values() if h.agent == agent]
        else:
            held = self._held.get((agent, action_id))
            gone = [held] if held is not None else []
        for held in gone:
            del self._held[held.key]
        return gone

    def lost(self, live_requesters):
        """Take out the actions whose requester is not one of ``live_requesters``; returns them.

        Requesters are compared by identity (``is``), never by equality: two connections
        from the same node have equal but distinct headers. Actions taken with requester
        ``None`` are never lost.

        :param live_requesters: iterable of the requesters whose links are still there
        :returns: list of :class:`HeldAction`, oldest first
        """
        live = {id(r) for r in live_requesters}
        # ``live_requesters`` keeps the objects alive during the call, so ids are not reused
        gone = [h for h in self._held.values()
                if h.requester is not None and id(h.requester) not in live]
        for held in gone:
            del self._held[held.key]
        return gone

    def clear(self):
        """Take every action out of the book (e.g. at shutdown); returns them, oldest first."""
        gone = list(self._held.values())
        self._held.clear()
        return gone

    def get(self, agent, action_id):
        """The held action ``(agent, action_id)``, or ``None``."""
        return self._held.get((agent, int(action_id)))

    def holds(self, held):
        """True while that very :class:`HeldAction` is in the book (not ended)."""
        return self._held.get(held.key) is held

    def actions(self, agent=None):
        """The held actions, oldest first; only ``agent``'s when given."""
        return [h for h in self._held.values() if agent is None or h.agent == agent]

    def __len__(self):
        return len(self._held)

    def __contains__(self, key):
        """``(agent, action_id) in book``."""
        agent, action_id = key
        return (agent, int(action_id)) in self._held

