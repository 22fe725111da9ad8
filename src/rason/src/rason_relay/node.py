"""``rosrun rason topic_relay``: ROS topics between robots on masters of their own, over the
fleet's MQTT broker, signed with the fleet key.

- ``~send`` (list of topic names): every message published here on them goes to the broker
  (any type: the relay forwards the serialized bytes);
- ``~receive`` (list of topic names): what another robot's relay sends on them is published
  on this master under the same name (the publisher is made at the first message, with its
  type);
- ``~mqtt_url``, ``~mqtt_prefix``, ``~mqtt_username``, ``~mqtt_password_file``,
  ``~mqtt_ca_file``: the broker, as for rason_mas;
- ``~fleet_key_file`` (default ``$ROS_HOME/rason/fleet.key``), ``~robot`` (default: the
  namespace), ``~max_bytes`` (65536), ``~max_age`` (5 s, wall clock: the robots' clocks
  must agree to within it), ``~max_rate`` (per topic sent, Hz; 0: every message).

Messages go at most once (MQTT QoS 0): a stream such as a pose needs its newest message,
not every one. So a message is skipped while the one before it is still unacknowledged on the
way to the broker: on a lossy link a stream would otherwise queue up behind retransmissions
and arrive seconds late. Dropped messages are warned about at most once every 10 s per reason.
"""
import fcntl
import os
import re
import socket
import struct
import sys
import termios
import threading
import time

import rason_rospy
import rospy
import roslib.message

from rason_bridge.fleet_auth import default_key_file
from rason_bridge.fleet_key import read_keys
from rason_relay.envelope import Refused
from rason_relay.relay import Inbound, Outbound
from rason_relay.settings import SettingsError, parse_settings

WARN_PERIOD = 10.0
TCP_THIN_LINEAR_TIMEOUTS = 16     # linux/tcp.h; Python's socket module does not name it


def _mqtt_client(settings, client_id):
    import paho.mqtt.client as mqtt
    client = mqtt.Client(client_id=client_id, clean_session=True, protocol=mqtt.MQTTv311)
    if settings.username:
        password = None
        if settings.password_file:
            with open(settings.password_file, encoding='utf-8') as f:
                password = f.readline().rstrip('\r\n')
        client.username_pw_set(settings.username, password)
    if settings.tls:
        client.tls_set(ca_certs=settings.ca_file or None)
    client.reconnect_delay_set(min_delay=1, max_delay=5)
    return client


def _unacknowledged_bytes(sock):
    """Bytes sent on ``sock`` that its peer has not acknowledged yet (Linux SIOCOUTQ); 0 when
    there is no socket (not connected: paho refuses the publish itself)."""
    if sock is None:
        return 0
    try:
        return struct.unpack('i', fcntl.ioctl(sock.fileno(), termios.TIOCOUTQ, b'\0' * 4))[0]
    except (OSError, ValueError):
        return 0


def _tune_for_thin_stream(sock):
    """A few small messages in flight: retransmit each at a steady timeout, not after an
    exponential backoff that stalls a pose stream for seconds on a lossy link (Linux)."""
    if sock is None:
        return
    try:
        sock.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
        sock.setsockopt(socket.IPPROTO_TCP, TCP_THIN_LINEAR_TIMEOUTS, 1)
        # BBR never leaves initial slow start in Linux's eyes, so no stream of it counts as thin
        if sock.getsockopt(socket.IPPROTO_TCP, socket.TCP_CONGESTION, 16).rstrip(b'\0') == b'bbr':
            _use_loss_based_congestion_control(sock)
    except OSError as e:
        rospy.logwarn('topic_relay: cannot tune the broker connection for a thin stream: %s', e)


def _use_loss_based_congestion_control(sock):
    for name in (b'cubic', b'reno'):     # reno is always allowed; cubic only when listed
        try:
            sock.setsockopt(socket.IPPROTO_TCP, socket.TCP_CONGESTION, name)
            return
        except OSError:
            continue
    rospy.logwarn('topic_relay: the broker connection uses BBR, under which Linux does not retransmit '
                  'a thin stream at a steady timeout; allow reno or cubic '
                  '(net.ipv4.tcp_allowed_congestion_control)')


def _wait_for_keys(path):
    """The fleet keys; rason_mas makes the key on a robot's first run, so wait for the file."""
    while not rospy.is_shutdown():
        if os.path.exists(path):
            return read_keys(path)
        rospy.logwarn_throttle(WARN_PERIOD, 'topic_relay: no fleet key at %s yet (rason_mas makes it on '
                               'first run; every robot needs the same file); waiting' % path)
        time.sleep(0.5)
    return None


class TopicRelay:
    """The rospy and paho plumbing around :class:`Outbound` and :class:`Inbound`."""

    def __init__(self, settings, keys, client):
        self._settings = settings
        self._outbound = Outbound(settings, keys[0])
        self._inbound = Inbound(settings, keys)
        self._client = client
        self._publishers = {}       # ROS topic -> (type, md5, rospy.Publisher)
        self._lock = threading.Lock()
        self._warned = {}           # kind of reason -> when last warned (monotonic s)
        self.sent = self.skipped = self.received = self.dropped = 0
        client.on_connect = self._on_connect
        client.on_disconnect = self._on_disconnect
        client.on_message = self._on_message
        for name in settings.send:
            rospy.Subscriber(name, rospy.AnyMsg, self._on_local, callback_args=name, queue_size=10)

    def start(self):
        self._client.connect_async(self._settings.host, self._settings.port, keepalive=10)
        self._client.loop_start()

    def stop(self):
        self._client.disconnect()
        self._client.loop_stop()

    def _on_connect(self, client, userdata, flags, rc):
        if rc != 0:
            rospy.logwarn_throttle(WARN_PERIOD, 'topic_relay: the broker %s:%d refused the connection (code %d)'
                                   % (self._settings.host, self._settings.port, rc))
            return
        rospy.loginfo('topic_relay %s: connected to %s:%d; sending %s, receiving %s', self._settings.robot,
                      self._settings.host, self._settings.port, list(self._settings.send),
                      list(self._settings.receive))
        _tune_for_thin_stream(client.socket())
        for topic in self._inbound.broker_topics:
            client.subscribe(topic, qos=0)

    def _on_disconnect(self, client, userdata, rc):
        if rc != 0:
            rospy.logwarn_throttle(WARN_PERIOD, 'topic_relay: lost the broker %s:%d; reconnecting'
                                   % (self._settings.host, self._settings.port))

    def _on_local(self, msg, ros_topic):
        if _unacknowledged_bytes(self._client.socket()):
            self.skipped += 1
            return
        header = msg._connection_header
        sealed = self._outbound.sealed(ros_topic, header['type'], header['md5sum'], msg._buff, time.time())
        if sealed is not None and self._client.publish(*sealed, qos=0).rc == 0:
            self.sent += 1

    def _on_message(self, client, userdata, message):
        try:
            header, payload = self._inbound.accepted(message.topic, message.payload, time.time())
            self._publish(header, payload)
        except Refused as e:
            self.dropped += 1
            self._warn_once_a_while(e, 'topic_relay: dropped a message on %s: %s' % (message.topic, e))

    def _warn_once_a_while(self, reason, text):
        # per kind of reason (its words without the numbers), so one flood hides no other kind
        kind = re.sub(r"'[^']*'|[0-9.]+", '#', str(reason))
        now = time.monotonic()
        with self._lock:
            if len(self._warned) > 100:
                self._warned.clear()
            if now - self._warned.get(kind, -WARN_PERIOD) < WARN_PERIOD:
                return
            self._warned[kind] = now
        rospy.logwarn(text)

    def _publish(self, header, payload):
        topic = header['topic']
        with self._lock:
            known = self._publishers.get(topic)
            if known is None:
                msg_class = roslib.message.get_message_class(header['type'])
                if msg_class is None:
                    raise Refused('of type %s, which this robot does not have' % header['type'])
                known = (header['type'], msg_class, rospy.Publisher(topic, msg_class, queue_size=10))
                self._publishers[topic] = known
        msg_type, msg_class, publisher = known
        if header['type'] != msg_type or header['md5'] != msg_class._md5sum:
            raise Refused('of type %s (md5 %s), but %s here is %s (md5 %s): the robots\' message '
                          'definitions differ' % (header['type'], header['md5'], topic, msg_type, msg_class._md5sum))
        msg = msg_class()
        try:
            msg.deserialize(payload)
        except Exception as e:          # genpy raises several kinds on truncated or garbled bytes
            raise Refused('that does not deserialize as %s: %s' % (msg_type, e))
        publisher.publish(msg)
        self.received += 1


def main(argv=None):
    rason_rospy.init_node('topic_relay', argv=argv)
    namespace = rospy.get_namespace().strip('/') or rospy.get_name().strip('/')
    try:
        settings = parse_settings(rospy.get_param('~', {}), rospy.resolve_name, namespace)
    except SettingsError as e:
        rospy.logfatal('topic_relay: %s', e)
        return 2
    import rospkg
    key_file = rospy.get_param('~fleet_key_file', '') or default_key_file(rospkg.get_ros_home())
    try:
        keys = _wait_for_keys(key_file)
        client = _mqtt_client(settings, 'rason-relay-%s-%d' % (settings.robot.replace('/', '-'), os.getpid()))
    except (OSError, ValueError) as e:
        rospy.logfatal('topic_relay: %s', e)
        return 2
    if keys is None:
        return 0
    relay = TopicRelay(settings, keys, client)
    relay.start()
    rospy.on_shutdown(relay.stop)
    rospy.spin()
    return 0


if __name__ == '__main__':
    sys.exit(main())
