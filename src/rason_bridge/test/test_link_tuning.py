"""LinkTuner: each new connection socket of a watched publisher gets linear retransmission
timeouts once (no ROS master: rospy's publisher and connection objects are stand-ins)."""
import socket

from rason_bridge.link_tuning import TCP_THIN_LINEAR_TIMEOUTS, LinkTuner


class Connection(object):
    def __init__(self, sock):
        self.socket = sock


class Publisher(object):
    def __init__(self):
        self.impl = type('Impl', (), {'connections': []})()


class CountingSocket(object):
    """A socket that records setsockopt calls (real sockets cannot be counted)."""

    def __init__(self, fail=None):
        self.calls = []
        self._fail = fail

    def setsockopt(self, level, option, value):
        if self._fail:
            raise OSError(self._fail, 'refused')
        self.calls.append((level, option, value))


def test_a_real_tcp_socket_takes_the_option():
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as sock:
        pub = Publisher()
        pub.impl.connections.append(Connection(sock))
        tuner = LinkTuner(warn=lambda *a: None)
        tuner.watch(pub)
        tuner.tune()
        assert sock.getsockopt(socket.IPPROTO_TCP, TCP_THIN_LINEAR_TIMEOUTS) == 1


def test_each_socket_is_set_once_and_new_connections_are_set_on_the_next_tune():
    pub = Publisher()
    first, second = CountingSocket(), CountingSocket()
    pub.impl.connections.append(Connection(first))
    tuner = LinkTuner(warn=lambda *a: None)
    tuner.watch(pub)
    tuner.tune()
    tuner.tune()
    pub.impl.connections.append(Connection(second))
    tuner.tune()
    assert first.calls == [(socket.IPPROTO_TCP, TCP_THIN_LINEAR_TIMEOUTS, 1)]
    assert second.calls == [(socket.IPPROTO_TCP, TCP_THIN_LINEAR_TIMEOUTS, 1)]


def test_a_publisher_without_connections_or_impl_is_skipped():
    closed = Publisher()
    closed.impl = None
    tuner = LinkTuner(warn=lambda *a: None)
    tuner.watch(closed)
    tuner.watch(Publisher())
    tuner.tune()


def test_a_refused_option_is_warned_once_and_a_closed_socket_not_at_all():
    warnings = []
    pub = Publisher()
    pub.impl.connections += [Connection(CountingSocket(fail=92)), Connection(CountingSocket(fail=92)),
                             Connection(CountingSocket(fail=9))]
    tuner = LinkTuner(warn=lambda fmt, *args: warnings.append(fmt % args))
    tuner.watch(pub)
    tuner.tune()
    tuner.tune()
    assert len(warnings) == 1 and 'linear' in warnings[0]
