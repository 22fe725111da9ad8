"""The outbound pump: the one thread that takes what the agents queued in Java's ``Outbox``
(``rason.bridge.Outbound`` items) and hands each to the node; no rospy.

This thread blocks in Java (JPype lets the other Python threads run), never an agent's
thread, so an agent never waits for Python.
"""
import threading

#: How long the thread blocks in Java waiting for the agents' next item (ms).
TAKE_WAIT_MS = 200


class OutboundPump(object):
    """
    :param take: ``take(wait_ms)`` -> the next item, or None after ``wait_ms``
    :param handle: ``handle(item)`` publishes one item
    :param error: ``error(format, *args)``
    """

    def __init__(self, take, handle, error):
        self._take = take
        self._handle = handle
        self._error = error
        self._stop = threading.Event()
        self._thread = None

    def start(self):
        self._thread = threading.Thread(target=self.run, name='rason_outbound', daemon=True)
        self._thread.start()

    def stop(self, join_timeout):
        """Hand on what is still queued, then end (waiting up to join_timeout s)."""
        self._stop.set()
        if self._thread is not None:
            self._thread.join(join_timeout)

    def run(self):
        while True:
            item = self._take(TAKE_WAIT_MS)
            if item is None:
                if self._stop.is_set():
                    return
                continue
            try:
                self._handle(item)
            except Exception as e:  # a bug must not end the thread that publishes every action
                self._error('could not publish %s: %s', item, e)


class OutboundItems(object):
    """Reads Java's ``Outbound`` items and calls the matching method of a receiver:
    ``publish_action(agent, action_id, functor, parameters)``, ``publish_cancel(agent, action_id, reason)``,
    ``publish_message(sender, receiver_mas, receiver, performative, content, msg_id, in_reply_to)``,
    ``announce()`` and ``stop_requested(exit_value)``.

    :param java_class: ``java_class(name)`` -> the Java class (``jpype.JClass``)
    """

    def __init__(self, java_class):
        outbound = 'rason.bridge.Outbound$'
        self._kinds = [(java_class(outbound + name), getattr(self, '_' + name.lower()))
                       for name in ('Action', 'Cancel', 'AgentMessage', 'Announce', 'Stop')]

    def dispatch(self, item, receiver):
        for kind, read in self._kinds:
            if isinstance(item, kind):
                read(item, receiver)
                return

    @staticmethod
    def _action(item, receiver):
        receiver.publish_action(str(item.agent()), int(item.actionId()), str(item.action()),
                        [str(p) for p in item.parameters()])

    @staticmethod
    def _cancel(item, receiver):
        receiver.publish_cancel(str(item.agent()), int(item.actionId()), str(item.reason()))

    @staticmethod
    def _agentmessage(item, receiver):
        receiver.publish_message(str(item.sender()), str(item.receiverMas()), str(item.receiver()),
                                 str(item.performative()), str(item.content()), str(item.msgId()),
                                 str(item.inReplyTo()))

    @staticmethod
    def _announce(item, receiver):
        receiver.announce()

    @staticmethod
    def _stop(item, receiver):
        receiver.stop_requested(int(item.exitValue()))
