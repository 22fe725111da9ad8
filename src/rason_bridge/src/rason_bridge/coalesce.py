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

    A message that arrives while one of its source waits replaces it and keeps its place.
    Sources already handed on recently (the last ``max_sources`` of them) are *known*, the
    others *new*; the worker takes the two kinds in turn, each in the order its sources
    started waiting. So a flood from one source cannot starve the others, a flood of new
    source names cannot hold back the sources a robot always publishes (they wait behind
    at most as many new ones as there are known ones waiting), and new sources still get
    half the turns.

    Bounds: at most ``max_sources`` sources wait at once, and a message from another one
    waits up to ``wait`` s for room (holding back its publisher's connection, not the
    others') before it is dropped; a source name longer than ``max_source_length`` is
    dropped at once. Drops are counted for :meth:`summary`. Thread-safe.

    :param max_sources: sources waiting at once, and sources remembered as known (1 or more)
    :param max_source_length: characters of a source name
    """

    def __init__(self, max_sources=100, max_source_length=256):
        if max_sources < 1:
            raise ValueError('max_sources must be 1 or more, not %r' % (max_sources,))
        self._max_sources = max_sources
        self._max_source_length = max_source_length
        self._lock = threading.Lock()
        self._cond = threading.Condition(self._lock)  # a message waits
        self._room = threading.Condition(self._lock)  # a source was taken
        self._known_waiting = collections.OrderedDict()  # source -> (message, stamp)
        self._new_waiting = collections.OrderedDict()
        self._known = collections.OrderedDict()  # sources handed on, least recent first
        self._new_turn = False
        self._closed = False
        self._replaced = self._dropped = self._too_long = 0
        self._overtaken_ever = 0
        self._replaced_sources = collections.OrderedDict()  # a few names for the summary
        self._dropped_sources = collections.OrderedDict()

    def _queue_of(self, source):
        for queue in (self._known_waiting, self._new_waiting):
            if source in queue:
                return queue
        return None

    def _count(self):
        return len(self._known_waiting) + len(self._new_waiting)

    def put(self, source, message, stamp, wait=0.0):
        """One message (from a rospy thread; the node's are serialized): ADDED, REPLACED (a
        waiting one of its source was overtaken) or DROPPED (its name is too long, or other
        sources filled the table for ``wait`` s)."""
        with self._lock:
            if len(source) > self._max_source_length:
                self._too_long += 1
                return DROPPED
            if self._queue_of(source) is None and self._count() >= self._max_sources and not self._closed:
                self._room.wait_for(lambda: self._queue_of(source) is not None or self._closed
                                    or self._count() < self._max_sources, wait)
            queue = self._queue_of(source)
            if queue is not None:
                queue[source] = (message, stamp)
                self._replaced += 1
                self._overtaken_ever += 1
                _note(self._replaced_sources, source)
                return REPLACED
            if self._count() >= self._max_sources:
                self._dropped += 1
                _note(self._dropped_sources, source)
                return DROPPED
            (self._known_waiting if source in self._known else self._new_waiting)[source] = (message, stamp)
            self._cond.notify()
            return ADDED

    def take(self, timeout=None):
        """The next waiting source's newest message, ``(source, message, stamp)``; None
        after ``timeout`` s without any, or once closed."""
        with self._lock:
            if not self._count() and not self._closed:
                self._cond.wait(timeout)
            if self._closed or not self._count():
                return None
            new = (self._new_turn or not self._known_waiting) and self._new_waiting
            self._new_turn = not new
            source, (message, stamp) = (self._new_waiting if new else self._known_waiting).popitem(last=False)
            self._known.pop(source, None)
            self._known[source] = True
            if len(self._known) > self._max_sources:
                self._known.popitem(last=False)
            self._room.notify()
            return source, message, stamp

    def close(self):
        """Wakes the worker; :meth:`take` returns None from now on."""
        with self._lock:
            self._closed = True
            self._cond.notify_all()
            self._room.notify_all()

    def overtaken(self):
        """How many messages were overtaken by a newer one of their source so far (ever)."""
        with self._lock:
            return self._overtaken_ever

    def waiting(self):
        """How many sources have a message waiting."""
        with self._lock:
            return self._count()

    def summary(self):
        """A log line for the messages overtaken or dropped since the last call (None if
        none were), and the counts start again."""
        with self._lock:
            replaced, dropped, too_long = self._replaced, self._dropped, self._too_long
            replaced_sources, dropped_sources = list(self._replaced_sources), list(self._dropped_sources)
            self._replaced = self._dropped = self._too_long = 0
            self._replaced_sources.clear()
            self._dropped_sources.clear()
        parts = []
        if replaced:
            parts.append('%d perception messages overtaken by a newer one of their source before the agents '
                         'took them (%s)' % (replaced, _names(replaced_sources)))
        if dropped:
            parts.append('%d dropped: %d other sources were waiting (%s)'
                         % (dropped, self._max_sources, _names(dropped_sources)))
        if too_long:
            parts.append('%d dropped: source name longer than %d characters' % (too_long, self._max_source_length))
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


class FloodEnd(object):
    """Tells when a flood is over: at least ``least`` messages were overtaken (the node fell
    behind) with less than ``quiet`` s between one and the next, and then none for ``quiet``
    s. Fed the coalescer's :meth:`~PerceptionCoalescer.overtaken` count and the time; no
    threads of its own.

    :param quiet: seconds without an overtaken message that end a flood
    :param least: overtaken messages that make a flood; fewer are a node that fell behind for
        a moment (a busy machine), not one whose heap a flood grew
    """

    def __init__(self, quiet=1.0, least=1):
        self.quiet = quiet
        self.least = least
        self._count = 0
        self._start = 0  # the count when the flood began
        self._last = None  # when an overtaken message was last seen, during a flood

    def ended(self, overtaken, now):
        """True once per flood, ``quiet`` s after its last overtaken message."""
        if overtaken != self._count:
            if self._last is None:
                self._start = self._count
            self._count = overtaken
            self._last = now
            return False
        if self._last is not None and now - self._last >= self.quiet:
            self._last = None
            return overtaken - self._start >= self.least
        return False
