"""Agent messages to other rason_mas processes: when one can be published (no ROS here).

All processes share one messages topic. A process that was just heard of may
not be connected to our publisher yet, and a message published before the
connection is up never reaches it. So a message for a process we are not
linked to is held, in order, until the link is up (or ``connect_wait`` has
passed), and later messages for the same process queue behind it. A broadcast
goes out at once to whoever is connected.
"""
import collections
import threading
import time

SENT = 'sent'
HELD = 'held'


class MessageSender(object):
    """Publishes agent messages in order, holding those whose receiving process is not linked yet.

    :param publish: ``publish(message)`` sends one message (must not block)
    :param linked: ``linked(mas_id)`` -> whether our publisher is connected to that process
    :param connect_wait: seconds a message waits for its link before it is published anyway
    :param clock: monotonic clock in seconds
    """

    def __init__(self, publish, linked, connect_wait, clock=time.monotonic):
        self._publish = publish
        self._linked = linked
        self._connect_wait = connect_wait
        self._clock = clock
        # Publishing happens under this lock so a flush and a new message for
        # the same process cannot overtake each other.
        self._lock = threading.Lock()
        self._held = collections.OrderedDict()  # mas_id -> deque of (since, message)

    def submit(self, message, receiver_mas):
        """Publish now or hold; returns SENT or HELD.

        :param receiver_mas: the receiving process, '' for a broadcast
        """
        with self._lock:
            if receiver_mas and (receiver_mas in self._held or not self._linked(receiver_mas)):
                self._held.setdefault(receiver_mas, collections.deque()).append((self._clock(), message))
                return HELD
            self._publish(message)
            return SENT

    def held_count(self):
        with self._lock:
            return sum(len(q) for q in self._held.values())

    def flush(self):
        """Publish held messages whose process is linked now, or that waited ``connect_wait``.

        :returns: ``(still_held, unlinked)``: the number of messages still held, and
            the messages published after waiting in vain for their link
        """
        unlinked = []
        with self._lock:
            now = self._clock()
            for mas in list(self._held):
                queue = self._held[mas]
                up = self._linked(mas)
                while queue and (up or now - queue[0][0] >= self._connect_wait):
                    _, message = queue.popleft()
                    self._publish(message)
                    if not up:
                        unlinked.append(message)
                if not queue:
                    del self._held[mas]
            return sum(len(q) for q in self._held.values()), unlinked
