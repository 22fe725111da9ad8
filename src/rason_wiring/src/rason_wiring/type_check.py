"""Whether the topics a synthesizer reads are published with the types its entries expect; no
rospy. A subscriber of another type than the publishers' is never connected (the md5sums
differ) and rospy says nothing on the subscriber's side: the entry would perceive nothing,
silently. The node hands :meth:`TypeCheck.warnings` the master's published topics now and
then and logs what it returns."""

#: How long a mismatch that goes on is not warned about again (s).
REPEAT = 60.0


def mismatch(entry, topic, expected, published):
    """The warning for an entry of type ``expected`` on ``topic`` published as ``published``."""
    return ('%s: %s is published as %s, but the entry reads it as %s: it perceives nothing from it '
            'until the entry\'s type is %s' % (entry, topic, published, expected, published))


class TypeCheck(object):
    """
    :param entries: ``[(entry name, resolved topic, type name)]``
    :param repeat: seconds before a mismatch that goes on is warned about again
    """

    def __init__(self, entries, repeat=REPEAT):
        self._entries = list(entries)
        self._repeat = repeat
        self._warned = {}     # entry -> (published type, when warned)

    def warnings(self, published, now):
        """The lines to warn now.

        :param published: ``{resolved topic: type name}`` of the topics that have publishers
        :param now: seconds of a monotonic clock
        """
        out = []
        for entry, topic, expected in self._entries:
            actual = published.get(topic)
            if actual is None or actual in (expected, '*'):
                self._warned.pop(entry, None)   # matched (or gone): a later mismatch is news
                continue
            last = self._warned.get(entry)
            if last is None or last[0] != actual or now - last[1] >= self._repeat:
                self._warned[entry] = (actual, now)
                out.append(mismatch(entry, topic, expected, actual))
        return out
