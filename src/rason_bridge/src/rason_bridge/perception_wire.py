"""The source of a rason_msgs/Perception read from its serialization, the bytes rospy receives
(subscribed with ``rospy.AnyMsg``), so that the node can coalesce messages by source without
deserializing them: Java reads the literals (``rason.perception.PerceptionWire``) in the one call
that hands a message to the agents. No rospy.

The serialization (ROS 1, little-endian): the source's ``uint32`` length and UTF-8 bytes, the
number of literals, then each literal's length and bytes.
"""
import struct

#: What a publisher of any type (AnyMsg, a relay) sends as its md5sum.
ANY_TYPE = '*'
#: Bytes a character takes in UTF-8 at most (an invalid byte becomes one U+FFFD).
MAX_BYTES_PER_CHARACTER = 4

_UINT32 = struct.Struct('<I')


def max_message_bytes(max_literals, max_literal_length, max_source_length):
    """The most bytes a message can have with at most ``max_literals`` literals of at most
    ``max_literal_length`` characters and a source within ``max_source_length``: a longer one
    has too many literals or one too long, and is dropped whole before it is copied to Java."""
    per_literal = 4 + MAX_BYTES_PER_CHARACTER * max_literal_length
    return 8 + MAX_BYTES_PER_CHARACTER * max_source_length + max_literals * per_literal


class SourceReader(object):
    """Reads the source of each message within bounds.

    :param max_bytes: bytes of a message taken at most (:func:`max_message_bytes`)
    :param max_source_length: characters of a source; a longer one is read only so far that it
        is still longer (the coalescer drops it as too long)
    :param md5sum: rason_msgs/Perception's (``Perception._md5sum``): the messages of a publisher of
        another type are refused (subscribed with the type, rospy would refuse its connection)
    """

    def __init__(self, max_bytes, max_source_length, md5sum):
        self.max_bytes = max_bytes
        self._md5sum = md5sum
        self._max_source_bytes = MAX_BYTES_PER_CHARACTER * (max_source_length + 1)

    def source(self, raw, header):
        """``(source, None)``, or ``(None, why)`` for a message to drop.

        :param raw: the message's serialization (``bytes``)
        :param header: its connection header (a dict; None: not known, taken as a Perception)
        """
        md5 = (header or {}).get('md5sum', self._md5sum)
        if md5 not in (self._md5sum, ANY_TYPE):
            return None, 'its type %s is not rason_msgs/Perception' % (header.get('type', '?')[:100],)
        if len(raw) > self.max_bytes:
            return None, '%d bytes, more than %d: too many literals or one too long' % (len(raw), self.max_bytes)
        if len(raw) < 4:
            return None, 'not a rason_msgs/Perception: %d bytes' % len(raw)
        (length,) = _UINT32.unpack_from(raw, 0)
        if length > len(raw) - 4:
            return None, 'not a rason_msgs/Perception: its source of %d bytes goes past its end' % length
        # invalid UTF-8 becomes U+FFFD, as genpy reads it
        return raw[4:4 + min(length, self._max_source_bytes)].decode('utf-8', 'replace'), None
