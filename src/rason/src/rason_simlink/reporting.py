"""Rate-limited reporting on the wall clock (ROS time stops with the simulation)."""
import time


class RateLimited:
    """Lets one report per key through every interval seconds and counts the rest."""

    def __init__(self, interval=5.0, clock=time.monotonic):
        self._interval = interval
        self._clock = clock
        self._last = {}
        self._suppressed = {}

    def allow(self, key):
        """(True, reports suppressed since the last one) or (False, None)."""
        now = self._clock()
        last = self._last.get(key)
        if last is not None and now - last < self._interval:
            self._suppressed[key] = self._suppressed.get(key, 0) + 1
            return False, None
        self._last[key] = now
        return True, self._suppressed.pop(key, 0)

    def report(self, key, log, text):
        """log(text) if key's turn has come, noting how many were held back."""
        allowed, suppressed = self.allow(key)
        if allowed:
            log(text + (' (%d more like this since)' % suppressed if suppressed else ''))


class Backoff:
    """Waits between reconnection attempts: first, doubling up to most, reset on success."""

    def __init__(self, first=0.1, most=2.0):
        self._first, self._most = first, most
        self._next = first

    def next_wait(self):
        wait = self._next
        self._next = min(self._most, self._next * 2)
        return wait

    def reset(self):
        self._next = self._first
