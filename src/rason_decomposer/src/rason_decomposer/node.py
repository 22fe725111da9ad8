"""The rospy side of every decomposer: :class:`Decomposer`.

It does the protocol of ``rason_msgs/Action.msg`` and ``Event.msg`` so that a decomposer
only starts and stops its work:

- subscribes ``jason/action`` (relative name) and takes the actions named in ``actions``
  (others are dropped silently, as several decomposers share the topic); publishes
  ``jason/event``;
- for each action taken: ``Event.ACTION_STARTED [action_id]``, then ``on_start(action)``;
  the handler ends it with :meth:`Decomposer.finish` (or :meth:`Decomposer.refuse` from
  ``on_start``: the answer goes out without ACTION_STARTED) and exactly one
  ``Event.ACTION_FEEDBACK [result, action_id]`` is published, extra calls are ignored;
- an ``Action.CANCEL`` (``action_id``, 0 = every action of the agent, ``parameters[0]`` =
  why) for a held action, and the loss of the link the action came over (checked at
  ``watch_rate``, 10 Hz), call ``on_cancel(action, reason)``, which must stop it, and then
  answer it ``Event.CANCELLED``; a cancel for an unknown or finished action is ignored;
- at node shutdown every held action gets ``on_cancel(action, Event.SHUTDOWN)`` and the
  answer ``Event.SHUTDOWN``.

Threads: rospy calls back on several threads (one per incoming connection, timers). The
decomposer's state is behind one lock, never held while a user callback runs. ``on_start``
runs on the thread of the requester's connection: it should start the work and return
(a long ``on_start`` delays that agent's next actions and cancels). While ``on_start``
runs, the action's answer and its cancel wait for it: a :meth:`~Decomposer.finish` call
from inside ``on_start`` is published after ACTION_STARTED, and a cancel that arrives
meanwhile calls ``on_cancel`` only once ``on_start`` has returned, so the handler never
sees ``on_cancel`` before ``on_start`` of the same action. ``on_cancel`` may still come
for an action the handler has just finished on another thread: it must then do nothing.
"""
import threading
import time

import rospy
from rason_msgs.msg import Action, Event

from rason_decomposer.book import ActionBook

#: The reason given to ``on_cancel`` when the link the action came over is gone.
REQUESTER_LOST = 'requester_lost'
#: The result that answers an action whose ``on_start`` raised an exception.
DECOMPOSER_ERROR = 'decomposer_error'


def action_text(action):
    """An action as Jason-like text for logs, e.g. ``a: move(1) #7``.

    :param action: anything with agent, action_id, name (or action) and parameters
    """
    name = getattr(action, 'name', None) or getattr(action, 'action', '?')
    return '%s: %s(%s) #%d' % (action.agent, name, ', '.join(action.parameters), action.action_id)


class _Starting(object):
    """What happened to an action while its ``on_start`` ran."""

    def __init__(self):
        self.feedback = None     # its answer, published once on_start returns
        self.refused = False     # answered by refuse(): no ACTION_STARTED
        self.stop = None         # (reason, result): cancelled meanwhile


class Decomposer(object):
    """Takes a decomposer's actions from ``jason/action`` and answers them on ``jason/event``.

    :param actions: the action names (functors) this decomposer handles
    :param on_start: ``on_start(action)``: start the work of a taken action (an object with
        ``agent``, ``action_id``, ``name``, ``parameters``); end it later with :meth:`finish`
    :param on_cancel: ``on_cancel(action, reason)``: stop that action now; ``reason`` is the
        cancel's ``parameters[0]``, :data:`REQUESTER_LOST` or ``Event.SHUTDOWN``
    :param agents: when not empty, only these agents' actions are taken
    :param watch_rate: Hz of the check that each requester's link is still there
    :param listener_wait: seconds to wait, before an action's first event, for a subscriber
        of ``jason/event`` when there is none yet (an event published before the agent's
        bridge is connected would be lost)
    :param queue_size: of the ``jason/action`` subscriber and the ``jason/event`` publisher
    """

    def __init__(self, actions, on_start, on_cancel, agents=(), watch_rate=10.0,
                 listener_wait=5.0, queue_size=100):
        if isinstance(actions, str):
            actions = [actions]
        self.actions = frozenset(actions)
        if Action.CANCEL in self.actions:
            raise ValueError('%r is the cancel, not an action' % Action.CANCEL)
        self.agents = frozenset(agents)
        self._on_start = on_start
        self._on_cancel = on_cancel
        self._listener_wait = float(listener_wait)
        self._name = rospy.get_name()
        self._lock = threading.Lock()
        self._book = ActionBook()
        self._starting = {}          # HeldAction -> _Starting, while its on_start runs
        self._events = rospy.Publisher('jason/event', Event, queue_size=queue_size)
        self._sub = rospy.Subscriber('jason/action', Action, self._on_action, queue_size=queue_size)
        rospy.on_shutdown(self._on_shutdown)
        self._watch_timer = rospy.Timer(rospy.Duration(1.0 / watch_rate), self._watch)

    # ------------------------------------------------------------------ the handler's calls

    def finish(self, action, result):
        """End ``action`` with ``result`` (``Event.OK`` or a failure reason).

        :returns: True when this call answered the action; False when it had already been
            answered (finished, refused, cancelled, lost): then nothing is published
        """
        return self._end(action, result, refused=False)

    def refuse(self, action, reason=Event.BAD_PARAMETERS):
        """Answer ``action`` at once with the failure ``reason``, meant for ``on_start`` (e.g.
        unusable parameters): no ACTION_STARTED goes out. Called after ``on_start`` returned,
        it is :meth:`finish`.

        :returns: as :meth:`finish`
        """
        return self._end(action, reason, refused=True)

    def holds(self, action):
        """True while ``action`` is neither answered nor cancelled."""
        with self._lock:
            return self._book.holds(action)

    def held(self):
        """The actions held now, oldest first."""
        with self._lock:
            return self._book.actions()

    # ------------------------------------------------------------------ internals

    def _publish(self, event):
        # Called with the lock held, so that the events of one action keep their order;
        # Publisher.publish with a queue_size only enqueues.
        try:
            self._events.publish(event)
        except rospy.ROSException as e:    # closing at shutdown
            rospy.logwarn('%s: could not publish %s %s: %s', self._name, event.event_type,
                          list(event.parameters), e)

    def _publish_feedback(self, feedback):
        self._publish(Event(agent=feedback.agent, event_type=Event.ACTION_FEEDBACK,
                            parameters=[feedback.result, str(feedback.action_id)]))

    def _wait_for_listener(self):
        if self._events.get_num_connections() > 0:
            return
        deadline = time.monotonic() + self._listener_wait
        while (self._events.get_num_connections() == 0 and time.monotonic() < deadline
               and not rospy.is_shutdown()):
            time.sleep(0.01)

    def _end(self, action, result, refused):
        with self._lock:
            feedback = self._book.finish(action.agent, action.action_id, result, held=action)
            if feedback is None:
                rospy.logdebug('%s: %s already answered; %s ignored', self._name,
                               action_text(action), result)
                return False
            starting = self._starting.get(action)
            if starting is not None:
                starting.feedback, starting.refused = feedback, refused
            else:
                self._publish_feedback(feedback)
        rospy.loginfo('%s: %s -> %s', self._name, action_text(action), result)
        return True

    def _on_action(self, msg):
        if msg.action == Action.CANCEL:
            self._on_cancel_msg(msg)
            return
        if msg.action not in self.actions:
            return
        if self.agents and msg.agent not in self.agents:
            rospy.logdebug('%s: agent %s is not served here', self._name, msg.agent)
            return
        # rospy gives each message the header dict of its connection (see _watch)
        requester = getattr(msg, '_connection_header', None)
        with self._lock:
            try:
                action = self._book.take(msg.agent, msg.action_id, msg.action, msg.parameters,
                                         requester)
            except ValueError as e:
                rospy.logwarn('%s: %s dropped: %s', self._name, action_text(msg), e)
                return
            starting = self._starting[action] = _Starting()
        rospy.loginfo('%s: %s taken', self._name, action_text(action))
        self._wait_for_listener()
        try:
            self._on_start(action)
        except Exception:
            rospy.logerr('%s: on_start of %s failed', self._name, action_text(action),
                         exc_info=True)
            self.finish(action, DECOMPOSER_ERROR)
        with self._lock:
            del self._starting[action]
            if not starting.refused:
                self._publish(Event(agent=action.agent, event_type=Event.ACTION_STARTED,
                                    parameters=[str(action.action_id)]))
            if starting.feedback is not None:
                self._publish_feedback(starting.feedback)
        if starting.stop is not None:
            self._stop([action], *starting.stop)

    def _on_cancel_msg(self, msg):
        reason = msg.parameters[0] if msg.parameters else ''
        with self._lock:
            gone = self._book.cancel(msg.agent, msg.action_id)
            now = self._defer_starting(gone, reason, Event.CANCELLED)
        if not gone:
            rospy.logdebug('%s: cancel of %s #%d (%s): not held here', self._name, msg.agent,
                           msg.action_id, reason)
        self._stop(now, reason, Event.CANCELLED)

    def _defer_starting(self, gone, reason, result):
        # With the lock held: the actions whose on_start still runs are stopped by that
        # thread once it returns; returns the others, to stop now.
        now = []
        for action in gone:
            starting = self._starting.get(action)
            if starting is not None:
                starting.stop = (reason, result)
            else:
                now.append(action)
        return now

    def _stop(self, actions, reason, result):
        for action in actions:
            rospy.loginfo('%s: %s stopped (%s)', self._name, action_text(action), reason)
            try:
                self._on_cancel(action, reason)
            except Exception:
                rospy.logerr('%s: on_cancel of %s failed', self._name, action_text(action),
                             exc_info=True)
            with self._lock:
                self._publish_feedback(action.feedback(result))

    def _live_requesters(self):
        impl = self._sub.impl
        connections = impl.connections if impl is not None else None
        return None if connections is None else [getattr(c, 'header', None) for c in connections]

    def _watch(self, _event=None):
        if rospy.is_shutdown():
            return
        live = self._live_requesters()
        if live is None:      # the subscriber is closing: shutdown answers the actions
            return
        with self._lock:
            gone = self._book.lost(live)
            now = self._defer_starting(gone, REQUESTER_LOST, Event.CANCELLED)
        if gone:
            rospy.logwarn('%s: the link of %s is gone: stopping %s', self._name,
                          ', '.join(sorted({a.agent for a in gone})),
                          ', '.join(action_text(a) for a in gone))
        self._stop(now, REQUESTER_LOST, Event.CANCELLED)

    def _on_shutdown(self):
        self._watch_timer.shutdown()
        with self._lock:
            gone = self._book.clear()
            now = self._defer_starting(gone, Event.SHUTDOWN, Event.SHUTDOWN)
        self._stop(now, Event.SHUTDOWN, Event.SHUTDOWN)
