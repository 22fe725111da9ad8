"""Perception messages coalesced per source between rospy's threads and the one thread
that hands them to the agents; no rospy.

A flood on ``jason/perception`` used to queue up in front of the agents (in rospy's
subscriber, the TCP buffers and the publisher's queue): seconds of stale messages, each
parsed in turn, and the newest one last. Here the subscriber only stores the message as
its source's newest, and a worker takes the newest message of each waiting source: a
source's list replaces the one before anyway (``per_source``), so an overtaken message is
one nobody would have seen for long.
"""
import collections
import threading

ADDED = 'added'
REPLACED = 'replaced'
DROPPED = 'dropped'

#: Source names shown in a summary line.
_SHOWN_SOURCES = 5


class PerceptionCoalescer(object):
    """The newest perception message of each source, until the worker takes it.

    Sources are taken in the order they started waiting (a message that replaces a waiting
    one keeps its source's place), so a source that floods cannot starve the others. At
    most ``max_sources`` sources wait at once: a message from another source waits up to
    ``wait`` s for room (holding back its publisher's connection, not the others'), then is
    dropped (counted), so a flood of distinct source names cannot grow the table. Thread-safe.

    :param max_sources: sources waiting at once (1 or more)
    """

    def __init__(self, max_sources=1000):
        if max_sources < 1:
            raise ValueError('max_sources must be 1 or more, not %r' % (max_sources,))
        self._max_sources = max_sources
        self._lock = threading.Lock()
        self._cond = threading.Condition(self._lock)  # a message waits
        self._room = threading.Condition(self._lock)  # a source was taken
        self._waiting = collections.OrderedDict()  # source -> (literals, stamp)
        self._closed = False
        self._replaced = 0
        self._dropped = 0
        self._replaced_sources = collections.OrderedDict()  # a few names for the summary
        self._dropped_sources = collections.OrderedDict()

    def put(self, source, literals, stamp, wait=0.0):
        """One message (from a rospy thread): ADDED, REPLACED (a waiting one of its source
        was overtaken) or DROPPED (other sources filled the table for ``wait`` s)."""
        with self._lock:
            if source not in self._waiting and len(self._waiting) >= self._max_sources and not self._closed:
                self._room.wait_for(lambda: source in self._waiting or self._closed
                                    or len(self._waiting) < self._max_sources, wait)
            if source in self._waiting:
                self._waiting[source] = (literals, stamp)
                self._replaced += 1
                _note(self._replaced_sources, source)
                return REPLACED
            if len(self._waiting) >= self._max_sources:
                self._dropped += 1
                _note(self._dropped_sources, source)
                return DROPPED
            self._waiting[source] = (literals, stamp)
            self._cond.notify()
            return ADDED

    def take(self, timeout=None):
        """The oldest waiting source's newest message, ``(source, literals, stamp)``; None
        after ``timeout`` s without any, or once closed."""
        with self._lock:
            if not self._waiting and not self._closed:
                self._cond.wait(timeout)
            if self._closed or not self._waiting:
                return None
            source, (literals, stamp) = self._waiting.popitem(last=False)
            self._room.notify()
            return source, literals, stamp

    def close(self):
        """Wakes the worker; :meth:`take` returns None from now on."""
        with self._lock:
            self._closed = True
            self._cond.notify_all()
            self._room.notify_all()

    def waiting(self):
        """How many sources have a message waiting."""
        with self._lock:
            return len(self._waiting)

    def summary(self):
        """A log line for the messages overtaken or dropped since the last call (None if
        none were), and the counts start again."""
        with self._lock:
            replaced, dropped = self._replaced, self._dropped
            replaced_sources, dropped_sources = list(self._replaced_sources), list(self._dropped_sources)
            self._replaced = self._dropped = 0
            self._replaced_sources.clear()
            self._dropped_sources.clear()
        parts = []
        if replaced:
            parts.append('%d perception messages overtaken by a newer one of their source before the agents '
                         'took them (%s)' % (replaced, _names(replaced_sources)))
        if dropped:
            parts.append('%d dropped: %d other sources were waiting (%s)'
                         % (dropped, self._max_sources, _names(dropped_sources)))
        return '; '.join(parts) if parts else None


def _note(names, source):
    if len(names) <= _SHOWN_SOURCES:
        names[source] = True


def _names(sources):
    shown = ', '.join(repr(_short(s)) for s in sources[:_SHOWN_SOURCES])
    return 'source ' + shown if len(sources) == 1 else 'sources ' + shown + (
        ', …' if len(sources) > _SHOWN_SOURCES else '')


def _short(text, limit=60):
    return text if len(text) <= limit else text[:limit] + '…'
