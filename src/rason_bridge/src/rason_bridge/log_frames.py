"""``rosgraph_msgs/Log`` messages for a batch of the agents' lines, serialized at once as
TCPROS frames (each a length and a message, as rospy writes one message to a connection);
no rospy.

genpy builds a ``Log`` object per line and serializes every field of it, the node's topic
list included, which is the same in every line. Here the parts that are the same for every
line of a node (its name, the file, function and line it reports, the topics) are encoded
once and kept, and a line costs its stamp, sequence number, level and text.
"""
import struct

_U32 = struct.Struct('<I')
#: frame length; header: seq, stamp secs, stamp nsecs, frame_id length (0: empty); level
_HEAD = struct.Struct('<IIIIIb')


def _string(text):
    data = text.encode('utf-8')
    return _U32.pack(len(data)) + data


class LogFrames(object):
    """
    :param name: the node's name (``Log.name``)
    :param file: ``Log.file``; ``function`` and ``line`` likewise, the same for every line
    """

    def __init__(self, name, file, function, line):
        self._name = _string(name)
        self._middle = _string(file) + _string(function) + _U32.pack(line)
        self._topics, self._tail = None, None

    def frames(self, lines, first_seq, secs, nsecs, topics):
        """The frames of ``[(level, text), ...]`` (``level`` a ``Log`` level byte) as one
        ``bytes``: sequence numbers from ``first_seq`` on, each stamped ``secs``/``nsecs``,
        carrying ``topics`` (a list of names)."""
        topics = tuple(topics)
        if topics != self._topics:
            self._topics = topics
            self._tail = self._middle + _U32.pack(len(topics)) + b''.join(_string(t) for t in topics)
        fixed = len(self._name) + len(self._tail) + _HEAD.size - 4
        out = []
        for seq, (level, text) in enumerate(lines, first_seq):
            data = text.encode('utf-8')
            out.append(_HEAD.pack(fixed + 4 + len(data), seq & 0xFFFFFFFF, secs, nsecs, 0, level))
            out.append(self._name)
            out.append(_U32.pack(len(data)))
            out.append(data)
            out.append(self._tail)
        return b''.join(out)
