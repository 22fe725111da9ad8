"""The held flusher: the thread that sends what the senders hold back — actions while their
decomposers connect (:mod:`rason_bridge.action_sender`), agent messages while the link to
their process comes up (:mod:`rason_bridge.message_sender`) — and, when nothing is held,
refreshes the master's subscriber count once a second; no rospy."""
import threading
import time

#: How long the thread sleeps when nobody woke it (s), and between two flushes while some are held.
IDLE_WAIT = 1.0
RETRY_PAUSE = 0.01


class HeldFlusher(object):
    """
    :param actions: the :class:`rason_bridge.action_sender.ActionSender`
    :param messages: the :class:`rason_bridge.message_sender.MessageSender` (None when another
        channel than ROS topics carries the agents' messages)
    :param unlinked: ``unlinked(message)`` for a message published after waiting in vain for its link
    :param alive: ``alive()`` -> False once the process shuts down
    """

    def __init__(self, actions, messages, unlinked, alive=lambda: True, pause=time.sleep):
        self._actions = actions
        self._messages = messages
        self._unlinked = unlinked
        self._alive = alive
        self._pause = pause
        self._wakeup = threading.Event()

    def wake(self):
        """Something was held: flush soon."""
        self._wakeup.set()

    def start(self):
        threading.Thread(target=self._run, name='rason_held', daemon=True).start()

    def _run(self):
        while self._alive():
            self.step(self._wakeup.wait(IDLE_WAIT))

    def step(self, woken):
        """One round: flush until nothing is held (or the process ends), or refresh the count."""
        self._wakeup.clear()
        if woken or self._actions.has_held() or (self._messages and self._messages.held_count()):
            while (self._actions.flush() + self._flush_messages()) and self._alive():
                self._pause(RETRY_PAUSE)
        else:
            self._actions.refresh_listed()

    def _flush_messages(self):
        if self._messages is None:
            return 0
        held, unlinked = self._messages.flush()
        for message in unlinked:
            self._unlinked(message)
        return held
