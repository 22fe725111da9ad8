"""The perception sources the agents need (``~expected_sources``): each not heard within
``~expect_within`` seconds of the agents' start is named once, so a synthesizer that is missing,
dead or reading the wrong topic is not met only as agents that never react; no rospy."""
import threading
import time


def late_source(source, within):
    """The warning for an expected source not heard in time."""
    return ('perception source %r not heard within %.0f s of the start (~expected_sources): nothing has '
            'published it on jason/perception; is its synthesizer running, and does it read the right topic '
            'with the right type (see its warnings)?' % (source, within))


class SourceWatch(object):
    """
    :param expected: the sources to wait for
    :param within: seconds after :meth:`start`
    """

    def __init__(self, expected, within, clock=time.monotonic):
        self._waiting = set(expected)
        self._within = within
        self._clock = clock
        self._deadline = None
        self._lock = threading.Lock()

    def start(self):
        self._deadline = self._clock() + self._within

    def heard(self, source):
        """A message of ``source`` came (any thread)."""
        if self._waiting:
            with self._lock:
                self._waiting.discard(source)

    def overdue(self):
        """The warnings due now: each expected source not heard by the deadline, once."""
        if not self._waiting or self._deadline is None or self._clock() < self._deadline:
            return []
        with self._lock:
            late, self._waiting = sorted(self._waiting), set()
        return [late_source(s, self._within) for s in late]
