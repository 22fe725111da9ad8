"""Deciding when an action can be published (no ROS here: the node injects the I/O).

A publisher only delivers to subscribers it is already connected to, and the
connection to a node that just subscribed takes a moment. So an action is
published at once when every subscriber the master lists is connected, held
back (for at most ``connect_wait`` seconds) while some are still connecting,
and failed with ``no_decomposer`` when the master lists no subscriber at all.
"""
import threading
import time

from rason_msgs.msg import Event

SENT = 'sent'
DEFERRED = 'deferred'
#: outcome of submit, and the failure reason the action ends with
NO_DECOMPOSER = Event.NO_DECOMPOSER


class ActionSender(object):
    """Publishes actions, or holds them until their subscribers are connected.

    :param publish: ``publish(action)`` sends one action
    :param connected: ``connected()`` -> number of subscribers this publisher is connected to
    :param listed: ``listed()`` -> number of subscribers the master lists (may be slow)
    :param fail: ``fail(action, reason)`` ends an action that cannot be sent
    :param connect_wait: seconds to wait for listed subscribers to connect
    :param clock: monotonic clock in seconds
    """

    def __init__(self, publish, connected, listed, fail, connect_wait, clock=time.monotonic):
        self._publish = publish
        self._connected = connected
        self._listed = listed
        self._fail = fail
        self._connect_wait = connect_wait
        self._clock = clock
        self._lock = threading.Lock()
        self._held = []          # (since, action)
        self._listed_cache = 0   # refreshed by refresh_listed()

    def refresh_listed(self):
        """Ask the master again how many subscribers there are; returns the count."""
        self._listed_cache = self._listed()
        return self._listed_cache

    def submit(self, action):
        """Publish now, hold, or refuse one action; returns SENT, DEFERRED or NO_DECOMPOSER."""
        with self._lock:
            if self._held:  # behind earlier held actions: never overtake them (a cancel follows its action)
                self._held.append((self._clock(), action))
                return DEFERRED
        connected = self._connected()
        if connected > 0 and connected >= self._listed_cache:
            self._publish(action)
            return SENT
        listed = self.refresh_listed()
        if listed == 0:
            if connected > 0:  # the master is behind: we are connected, so send
                self._publish(action)
                return SENT
            return NO_DECOMPOSER
        if connected >= listed:
            self._publish(action)
            return SENT
        with self._lock:
            self._held.append((self._clock(), action))
        return DEFERRED

    def has_held(self):
        with self._lock:
            return bool(self._held)

    def flush(self):
        """Send held actions whose subscribers are now connected (or waited long enough).

        Actions still unsubscribed after the wait fail with ``no_decomposer``.
        :returns: number of actions still held
        """
        with self._lock:
            if not self._held:
                return 0
            held, self._held = self._held, []
        connected = self._connected()
        listed = self.refresh_listed()
        keep = []
        now = self._clock()
        for since, action in held:
            waited_out = now - since >= self._connect_wait
            if connected > 0 and (connected >= listed or waited_out):
                self._publish(action)
            elif listed == 0 and connected == 0:
                self._fail(action, NO_DECOMPOSER)
            elif waited_out:
                # listed but never connected: the subscriber is not reachable
                self._fail(action, NO_DECOMPOSER)
            else:
                keep.append((since, action))
        with self._lock:
            self._held = keep + self._held
            return len(self._held)
