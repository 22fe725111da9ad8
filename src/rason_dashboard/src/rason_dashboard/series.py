"""Items in time order, bounded: what the dashboard keeps of each kind of record."""
import bisect


class Series(object):
    """(time, item) pairs in time order, bounded; the item at or before a time."""

    def __init__(self, limit):
        self._times = []
        self._items = []
        self._limit = limit

    def add(self, t, item):
        i = bisect.bisect_right(self._times, t)  # in time order even when input is not
        self._times.insert(i, t)
        self._items.insert(i, item)
        if len(self._times) > self._limit:
            del self._times[0]
            del self._items[0]

    def at(self, t):
        """The newest item at or before t (None: the newest of all), or None."""
        i = len(self._times) if t is None else bisect.bisect_right(self._times, t)
        return self._items[i - 1] if i else None

    def at_and_before(self, t):
        """The newest item at or before t (None: the newest of all) and the one before it (or None)."""
        i = len(self._times) if t is None else bisect.bisect_right(self._times, t)
        return (self._items[i - 1] if i else None), (self._items[i - 2] if i > 1 else None)

    def upto(self, t, n):
        """The last n (time, item) pairs at or before t (None: the newest)."""
        i = len(self._times) if t is None else bisect.bisect_right(self._times, t)
        return list(zip(self._times[max(0, i - n):i], self._items[max(0, i - n):i]))

    def span(self):
        return (self._times[0], self._times[-1]) if self._times else None
