"""When a fleet connection is reset and when a lost subscriber connection is made again
(no rospy: :mod:`rason_bridge.link_repair` applies these rules to rospy's connections).

After a partition, a TCPROS connection whose data was lost during the cut waits for its next
retransmission, which TCP schedules at doubling intervals: messages flowed again up to 18 s
after the heal while the peer's pulses, on a connection of their own, were back within 2 s.
A publisher that hears its peer again but gets no acknowledgement on its connection to it
resets that connection; the subscriber then makes a new one at once (rospy itself never makes
a subscriber's connection again once it ended), which starts with a fresh retransmission
timeout. Whatever the reset drops was published to a peer that had been away: the sender's
receipts report it (docs/guides/fleet-channel.md, "The ROS channel across hosts").
"""
import struct
import threading
from collections import namedtuple

#: The fields of Linux's ``struct tcp_info`` we read (from the start of the struct).
TcpInfo = namedtuple('TcpInfo', 'state retransmits backoff unacked last_ack_recv')
TCP_ESTABLISHED = 1
#: u8 state, ca_state, retransmits, probes, backoff, options, wscale, flags; u32 rto, ato,
#: snd_mss, rcv_mss, unacked, sacked, lost, retrans, fackets, last_data_sent, last_ack_sent,
#: last_data_recv, last_ack_recv (ms since the last acknowledgement)
_TCP_INFO = struct.Struct('=8B13I')
TCP_INFO_SIZE = _TCP_INFO.size


def parse_tcp_info(raw):
    f = _TCP_INFO.unpack_from(raw)
    return TcpInfo(state=f[0], retransmits=f[2], backoff=f[4], unacked=f[12], last_ack_recv=f[20] / 1000.0)


class PeerReturns(object):
    """When each peer process was last heard after an absence (its messages, pulses and presence).

    :param away_after: a silence this long (s) is an absence (``presence_timeout``)
    """

    def __init__(self, away_after):
        self._away_after = away_after
        self._last = {}   # node -> when last heard
        self._back = {}   # node -> when heard again after an absence

    def heard(self, node, now):
        last = self._last.get(node)
        if last is not None and now - last >= self._away_after:
            self._back[node] = now
        self._last[node] = now

    def back_for(self, node, now):
        """Seconds since node came back after an absence; None if it never was away or is silent now."""
        back, last = self._back.get(node), self._last.get(node)
        if back is None or now - last >= self._away_after:
            return None
        return now - back


#: Seconds a publisher waits for an acknowledgement after its peer came back before it resets
#: (a connection on linear retransmission timeouts retransmits within ~0.4 s).
GRACE = 0.5
#: Seconds after its peer came back during which a connection may be reset for it.
WINDOW = 10.0


def stuck(info, back_for, grace=GRACE, window=WINDOW):
    """Whether a publisher connection with tcp_info ``info`` is stuck although its peer is back:
    data unacknowledged, and no acknowledgement since the peer came back ``back_for`` s ago."""
    if back_for is None or not grace <= back_for <= window:
        return False
    return info.state == TCP_ESTABLISHED and info.unacked > 0 and info.last_ack_recv > back_for


class Relinks(object):
    """Which lost subscriber connections to make again: every publisher a subscriber was connected
    to and is not any more, tried at once, then 0.5 s, 1 s, 2 s... apart (at most ``longest`` s)
    until linked, or until the publisher refuses (gone, or no longer publishing)."""

    FIRST = 0.5

    def __init__(self, longest=5.0):
        self._longest = longest
        self._lost = {}      # (topic, uri) -> [next attempt, interval]
        self._known = set()  # (topic, uri) linked at some point
        self._busy = set()   # (topic, uri) attempts under way
        self._lock = threading.Lock()  # attempts end on threads of their own

    def due(self, topic, linked, now):
        """Publisher URIs of topic to try now; ``linked``: the URIs the subscriber has now."""
        with self._lock:
            return self._due(topic, set(linked), now)

    def _due(self, topic, linked, now):
        due = []
        for uri in linked:
            self._known.add((topic, uri))
            self._lost.pop((topic, uri), None)
        for key in [k for k in self._known if k[0] == topic and k[1] not in linked]:
            if key in self._busy:
                continue
            attempt = self._lost.setdefault(key, [now, self.FIRST])
            if now >= attempt[0]:
                due.append(key[1])
        return sorted(due)

    def started(self, topic, uri, now):
        with self._lock:
            self._started((topic, uri), now)

    def _started(self, key, now):
        self._busy.add(key)
        attempt = self._lost.setdefault(key, [now, self.FIRST])
        attempt[0] = now + attempt[1]
        attempt[1] = min(attempt[1] * 2, self._longest)

    def ended(self, topic, uri, gone):
        """An attempt ended; ``gone``: the publisher refused it, so it is not tried again."""
        key = (topic, uri)
        with self._lock:
            self._busy.discard(key)
            if gone:
                self._known.discard(key)
                self._lost.pop(key, None)
