"""Linear retransmission timeouts on the TCPROS connections of our fleet publishers, so that a
lossy or cut link between robots stalls them for less long (rospy plumbing: it reaches into
rospy's connection objects).

Every topic pair is a TCP connection of its own, from the subscriber to the publisher. TCP
doubles its retransmission timeout each time the same segment is lost again, so a few losses in
a row stall a connection for seconds (longer than ``presence_timeout``), and after a partition
the next retransmission may come long after the link healed. With ``TCP_THIN_LINEAR_TIMEOUTS``
Linux keeps the timeout linear for the first 6 retransmissions of a connection with fewer than
4 segments in flight, as fleet traffic mostly is (docs/guides/fleet-channel.md, "The ROS
channel across hosts").
"""
import socket
import weakref

TCP_THIN_LINEAR_TIMEOUTS = getattr(socket, 'TCP_THIN_LINEAR_TIMEOUTS', 16)


class LinkTuner(object):
    """Sets the option on each new connection of the publishers it watches (call :meth:`tune` often).

    :param warn: ``warn(format, *args)`` when the option cannot be set (once)
    """

    def __init__(self, warn):
        self._warn = warn
        self._publishers = []
        self._tuned = weakref.WeakSet()  # sockets already set (each connection has its own)
        self._warned = False

    def watch(self, pub):
        self._publishers.append(pub)

    def tune(self):
        for pub in self._publishers:
            impl = pub.impl
            for conn in list(impl.connections) if impl is not None else ():
                sock = getattr(conn, 'socket', None)
                if sock is not None and sock not in self._tuned:
                    self._set(sock)

    def _set(self, sock):
        try:
            sock.setsockopt(socket.IPPROTO_TCP, TCP_THIN_LINEAR_TIMEOUTS, 1)
        except OSError as e:
            if e.errno == 9:  # closed meanwhile
                return
            if not self._warned:
                self._warned = True
                self._warn('cannot make retransmissions linear on the fleet connections: %s', e)
        self._tuned.add(sock)
