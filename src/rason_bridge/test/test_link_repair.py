"""LinkRepair applies the repair rules to rospy's connection objects (stand-ins here, no ROS
master): a publisher connection stuck after its peer came back is reset, a lost subscriber
connection is asked for again from its publisher."""
import socket
import struct
import threading
import time
from xmlrpc.server import SimpleXMLRPCServer

from rason_bridge.link_repair import LinkRepair

PEER = '/r2/rason_mas'


class Clock(object):
    def __init__(self):
        self.now = 100.0

    def __call__(self):
        return self.now


class StuckSocket(object):
    """A socket whose tcp_info says: 3 segments unacknowledged, last acknowledgement 8 s ago."""

    def __init__(self, unacked=3):
        self.unacked = unacked
        self.options = []

    def getsockopt(self, level, option, size):
        assert (level, option) == (socket.IPPROTO_TCP, socket.TCP_INFO)
        return struct.pack('=8B13I', 1, 4, 4, 0, 4, 0, 0, 0, *([0] * 4 + [self.unacked] + [0] * 7 + [8000]))

    def setsockopt(self, level, option, value):
        self.options.append((level, option, value))


class Connection(object):
    def __init__(self, endpoint_id, sock=None):
        self.endpoint_id = endpoint_id
        self.socket = sock
        self.closed = False

    def close(self):
        self.closed = True


class Topic(object):
    def __init__(self, name, *connections):
        self.resolved_name = name
        self.impl = type('Impl', (), {'connections': list(connections)})()


def _repair_with_a_peer_back(clock):
    repair = LinkRepair(away_after=2.0, clock=clock)
    repair.heard(PEER)
    clock.now += 6.0  # a partition
    repair.heard(PEER)
    clock.now += 1.0
    return repair


def test_a_stuck_connection_to_a_peer_that_came_back_is_reset():
    clock = Clock()
    repair = _repair_with_a_peer_back(clock)
    stuck, other = Connection(PEER, StuckSocket()), Connection('/r3/rason_mas', StuckSocket())
    repair.publishers(Topic('/rason/messages', stuck, other))
    repair.check()
    assert stuck.closed and stuck.socket.options == [(socket.SOL_SOCKET, socket.SO_LINGER, struct.pack('ii', 1, 0))]
    assert not other.closed  # /r3 was never away


def test_a_connection_with_everything_acknowledged_is_kept():
    clock = Clock()
    repair = _repair_with_a_peer_back(clock)
    idle = Connection(PEER, StuckSocket(unacked=0))
    repair.publishers(Topic('/rason/messages', idle))
    repair.check()
    assert not idle.closed


def test_a_peer_never_away_keeps_its_connections():
    clock = Clock()
    repair = LinkRepair(away_after=2.0, clock=clock)
    for _ in range(10):
        repair.heard(PEER)
        clock.now += 1.0
    conn = Connection(PEER, StuckSocket())
    repair.publishers(Topic('/rason/messages', conn))
    repair.check()
    assert not conn.closed


class Publisher(object):
    """An XML-RPC server that declines every requestTopic, as a node that stopped publishing does."""

    def __init__(self):
        self.requests = []
        self.server = SimpleXMLRPCServer(('127.0.0.1', 0), logRequests=False)
        self.server.register_function(self.requestTopic, 'requestTopic')
        self.uri = 'http://127.0.0.1:%d/' % self.server.server_address[1]
        threading.Thread(target=self.server.serve_forever, daemon=True).start()

    def requestTopic(self, caller_id, topic, protocols):
        self.requests.append((topic, protocols))
        return [0, 'not a publisher of %s' % topic, 0]


def _wait(condition, timeout=5.0):
    deadline = time.monotonic() + timeout
    while not condition():
        assert time.monotonic() < deadline, 'timed out'
        time.sleep(0.01)


def _relinking():
    return any(t.name == 'rason_relink' for t in threading.enumerate())


def test_a_lost_subscriber_connection_is_requested_again_and_a_refusal_ends_the_attempts():
    publisher = Publisher()
    try:
        clock = Clock()
        repair = LinkRepair(away_after=2.0, clock=clock)
        sub = Topic('/rason/messages', Connection(publisher.uri))
        repair.subscribers(sub)
        repair.check()
        assert publisher.requests == []  # connected: nothing to do
        sub.impl.connections = []
        repair.check()
        _wait(lambda: publisher.requests == [('/rason/messages', [['TCPROS']])])
        _wait(lambda: not _relinking())
        clock.now += 60.0
        repair.check()
        # an attempt started now would still be running or would have asked already
        assert not _relinking() and len(publisher.requests) == 1
    finally:
        publisher.server.shutdown()
        publisher.server.server_close()


def test_subscriber_connections_probe_a_silent_link_within_seconds():
    with socket.socket() as sock:
        repair = LinkRepair(away_after=2.0, clock=Clock())
        repair.subscribers(Topic('/rason/messages', Connection('http://127.0.0.1:9/', sock)))
        repair.check()
        assert sock.getsockopt(socket.SOL_SOCKET, socket.SO_KEEPALIVE) == 1
        assert sock.getsockopt(socket.IPPROTO_TCP, socket.TCP_KEEPIDLE) == 2
        assert sock.getsockopt(socket.IPPROTO_TCP, socket.TCP_KEEPCNT) == 10
