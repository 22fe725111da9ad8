"""Resets the fleet publishers' connections stuck in TCP's retransmission backoff after a
partition, and makes the fleet subscribers' lost connections again (rospy plumbing: it reaches
into rospy's connection objects; the rules are :mod:`rason_bridge.repair_rules`)."""
import errno
import http.client
import socket
import struct
import threading
import time
import weakref
import xmlrpc.client

import rospy
import rospy.impl.tcpros

from rason_bridge.repair_rules import TCP_INFO_SIZE, PeerReturns, Relinks, parse_tcp_info, stuck

#: Seconds a request for a lost connection may take (the publisher's XML-RPC server).
REQUEST_TIMEOUT = 2.0
_LINGER_RESET = struct.pack('ii', 1, 0)  # close() then sends a reset, not a FIN queued behind the stuck data
#: Keepalive probes on the fleet subscribers' connections (idle s, s between probes, probes):
#: a subscriber whose publisher's reset was lost learns it from the reset its next probe gets
#: (rospy's own: after 60 s); a silent link ends the connection only after 12 s, longer than
#: the partitions the fleet rides out without making connections again.
KEEPALIVE = ((socket.TCP_KEEPIDLE, 2), (socket.TCP_KEEPINTVL, 1), (socket.TCP_KEEPCNT, 10))


class LinkRepair(object):
    """Call :meth:`heard` for each message, pulse or presence of a peer and :meth:`check` often.

    :param away_after: a peer silent this long (s) was away (``presence_timeout``)
    """

    def __init__(self, away_after, clock=time.monotonic):
        self._clock = clock
        self._peers = PeerReturns(away_after)
        self._relinks = Relinks()
        self._publishers = []
        self._subscribers = []
        self._probed = weakref.WeakSet()  # subscriber sockets with our keepalive

    def publishers(self, *pubs):
        self._publishers.extend(pubs)

    def subscribers(self, *subs):
        self._subscribers.extend(subs)

    def heard(self, node):
        self._peers.heard(node, self._clock())

    def check(self):
        now = self._clock()
        for pub in self._publishers:
            impl = pub.impl
            for conn in list(impl.connections) if impl is not None else ():
                self._check_publisher_connection(pub.resolved_name, conn, now)
        for sub in self._subscribers if not rospy.is_shutdown() else ():
            impl = sub.impl
            if impl is None:
                continue
            topic = sub.resolved_name
            connections = list(impl.connections)
            for conn in connections:
                self._probe(getattr(conn, 'socket', None))
            for uri in self._relinks.due(topic, [c.endpoint_id for c in connections], now):
                self._relinks.started(topic, uri, now)
                threading.Thread(target=self._relink, args=(topic, uri), name='rason_relink', daemon=True).start()

    def _probe(self, sock):
        if sock is None or sock in self._probed:
            return
        try:
            sock.setsockopt(socket.SOL_SOCKET, socket.SO_KEEPALIVE, 1)
            for option, value in KEEPALIVE:
                sock.setsockopt(socket.IPPROTO_TCP, option, value)
        except OSError:  # closed meanwhile
            return
        self._probed.add(sock)

    def _check_publisher_connection(self, topic, conn, now):
        node = getattr(conn, 'endpoint_id', None)
        back_for = self._peers.back_for(node, now) if node else None
        sock = getattr(conn, 'socket', None)
        if back_for is None or sock is None:
            return
        try:
            info = parse_tcp_info(sock.getsockopt(socket.IPPROTO_TCP, socket.TCP_INFO, TCP_INFO_SIZE))
            if not stuck(info, back_for):
                return
            sock.setsockopt(socket.SOL_SOCKET, socket.SO_LINGER, _LINGER_RESET)
        except OSError:  # closed meanwhile
            return
        rospy.loginfo('%s: reset the connection to %s, back for %.1f s but no acknowledgement for %.1f s '
                      '(%d segments unacknowledged, %d retransmissions): it makes a new one', topic, node,
                      back_for, info.last_ack_recv, info.unacked, info.retransmits)
        conn.close()

    def _relink(self, topic, uri):
        gone = False
        try:
            gone = not _request_connection(topic, uri)
        except (OSError, http.client.HTTPException, xmlrpc.client.Error) as e:
            gone = getattr(e, 'errno', None) == errno.ECONNREFUSED  # the process is gone
            rospy.logdebug('%s: could not make the connection to %s again: %s', topic, uri, e)
        except Exception as e:  # a bug must not end quietly
            rospy.logerr('%s: could not make the connection to %s again: %s', topic, uri, e)
        finally:
            self._relinks.ended(topic, uri, gone)


def _request_connection(topic, uri):
    """Ask publisher uri for a connection to topic and make it; False if it declines."""
    proxy = xmlrpc.client.ServerProxy(uri, transport=_TimeoutTransport())
    code, msg, params = proxy.requestTopic(rospy.get_caller_id(), topic, [['TCPROS']])
    if code != 1:
        rospy.logdebug('%s: %s no longer publishes it (%s)', topic, uri, msg)  # it is leaving
        return False
    code, msg, _ = rospy.impl.tcpros.get_tcpros_handler().create_transport(topic, uri, params)
    if code == 1:
        rospy.loginfo('%s: made the connection to %s again', topic, uri)
    return True


class _TimeoutTransport(xmlrpc.client.Transport):
    def make_connection(self, host):
        conn = super(_TimeoutTransport, self).make_connection(host)
        conn.timeout = REQUEST_TIMEOUT
        return conn
