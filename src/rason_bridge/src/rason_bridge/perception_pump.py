"""The perception pump: the one thread that hands the stored perceptions to Java (parsed there,
then to every agent); no rospy.

Subscribers only :meth:`PerceptionPump.put` a message: the newest message of its source wins
(see :mod:`rason_bridge.coalesce`), so a flood never queues up in front of the agents.
"""
import threading
import time

from rason_bridge.coalesce import FloodEnd
from rason_bridge.source_watch import SourceWatch

#: How long a message from a new source may hold its connection back while max_sources
#: others wait, before it is dropped (s).
ROOM_WAIT = 1.0
#: How long the thread waits for a message before it looks at its stop flag (s).
TAKE_WAIT = 0.2
#: How often at most it logs what a flood made it skip (s, wall clock).
SUMMARY_PERIOD = 10.0
#: Messages overtaken that make a flood, whose end asks the JVM for a (concurrent) collection:
#: on a busy machine a 50 Hz stream has a few overtaken now and then, and a collection for each
#: cost more CPU than the stream itself.
FLOOD_LEAST = 100


class PerceptionPump(object):
    """
    :param coalescer: a :class:`rason_bridge.coalesce.PerceptionCoalescer`
    :param perceive: ``perceive(source, message, stamp_ns)`` hands one message (as :meth:`put` got it) to the agents
    :param release_memory: ``release_memory()`` once a flood has ended
    :param warn: ``warn(format, *args)``; ``error`` likewise
    :param alive: ``alive()`` -> False once the process shuts down
    :param watch: a :class:`rason_bridge.source_watch.SourceWatch` of the expected sources
    """

    def __init__(self, coalescer, perceive, release_memory, warn, error, alive=lambda: True,
                 clock=time.monotonic, watch=None):
        self._coalescer = coalescer
        self._perceive = perceive
        self._release_memory = release_memory
        self._warn, self._error = warn, error
        self._alive = alive
        self._clock = clock
        self._stop = threading.Event()
        self._flood = FloodEnd(least=FLOOD_LEAST)
        self._next_summary = clock() + SUMMARY_PERIOD
        self._watch = watch or SourceWatch((), 0.0)

    def put(self, source, message, stamp):
        """Store one message of source (from a subscriber's thread): the node's are serialized
        rason_msgs/Perception messages, read in Java."""
        self._watch.heard(source)
        self._coalescer.put(source, message, stamp, wait=ROOM_WAIT)

    def start(self):
        self._watch.start()
        threading.Thread(target=self._run, name='rason_perceive', daemon=True).start()

    def stop(self):
        self._stop.set()
        self._coalescer.close()

    def _run(self):
        while not self._stop.is_set() and self._alive():
            self.step()

    def step(self):
        """Hand on at most one message (waiting up to TAKE_WAIT for one), and do what is due."""
        if self._flood.ended(self._coalescer.overtaken(), self._clock()):
            self._release_memory()  # what the flood made the JVM grow goes back now
        item = self._coalescer.take(TAKE_WAIT)
        if item is not None:
            source, message, stamp = item
            try:
                self._perceive(source, message, stamp)
            except Exception as e:  # a bug must not end the thread every perception goes through
                self._error('could not hand the perception of %r to the agents: %s', source[:100], e)
        for line in self._watch.overdue():
            self._warn('%s', line)
        if self._clock() >= self._next_summary:
            self._next_summary = self._clock() + SUMMARY_PERIOD
            line = self._coalescer.summary()
            if line:
                self._warn('perceptions come faster than the agents take them: %s in the last %.0f s',
                           line, SUMMARY_PERIOD)
