"""The presence loop: the thread that announces this process to the others every
``presence_period`` and lets Java check links and silences every 50 ms; no rospy.

Wall clock on purpose: presence is about processes and links, and must keep working
when /clock is paused or runs faster than real time.
"""
import threading
import time

#: How often the fleet checks links and silences (wall clock, seconds).
TICK = 0.05


class PresenceLoop(object):
    """
    :param publish: ``publish(leaving)`` signs and publishes one announcement
    :param tick: ``tick()`` lets Java check links and silences
    :param period: seconds between announcements
    :param error: ``error(format, *args)`` for a failed tick (called at most as often as the ticks)
    :param alive: ``alive()`` -> False once the process shuts down
    """

    def __init__(self, publish, tick, period, error, alive=lambda: True, clock=time.monotonic):
        self._publish = publish
        self._tick = tick
        self._period = period
        self._error = error
        self._alive = alive
        self._clock = clock
        self._stop = threading.Event()
        self._lock = threading.Lock()
        self._next = 0.0

    def announce(self, leaving=False):
        """Announce now (from any thread); after :meth:`leave` only the leaving announcement goes out."""
        # The lock and the check keep a periodic announcement from following the leaving one.
        with self._lock:
            if self._stop.is_set() and not leaving:
                return
            self._publish(leaving)

    def leave(self):
        """Stop announcing, and tell the others at once that this process is leaving."""
        self._stop.set()
        self.announce(leaving=True)

    def start(self):
        threading.Thread(target=self._run, name='rason_presence', daemon=True).start()

    def _run(self):
        while not self._stop.is_set() and self._alive():
            self.step()
            self._stop.wait(TICK)

    def step(self):
        """Announce if the period is up, then tick."""
        now = self._clock()
        if now >= self._next:
            self.announce(leaving=False)
            self._next = now + self._period
        try:
            self._tick()
        except Exception as e:
            self._error('presence tick failed: %s', e)
