"""The fleet channel as the multi-robot rostests see it, the same over ROS topics and MQTT.

A .test says its channel once, by including test/fleet_channel.launch (``fleet_channel:=ros|mqtt``);
that include puts the channel under ``/rason_test``. Here the test scripts read it back
(:func:`fleet_params`, which :func:`rason_testing.start_mas` adds to every robot a test starts)
and get a :class:`FleetTap` on it: what goes over the channel (agent messages and presence,
captured) and a way to put things on it as a node of the fleet would (genuine, forged, played
again or altered). Over MQTT the tap is a plain broker client that speaks the payload format of
Java's ``rason.messaging.mqtt.MqttPayloads``: it holds no fleet key, so whatever it makes up
carries no valid MAC unless a :class:`rason_testing.FleetSigner` signed the fields.
"""
import struct
import threading
import time
import uuid
from urllib.parse import urlparse

import rospy
from rason_msgs.msg import AgentMessage, Presence

CHANNEL_PARAM = '/rason_test/fleet_channel'
URL_PARAM = '/rason_test/mqtt_url'
PREFIX = 'rason/'  # ~mqtt_prefix's default, which the tests keep

ROS, MQTT = 'ros', 'mqtt'


def fleet_channel():
    """The channel this test runs on: 'ros' (also when the .test does not say) or 'mqtt'."""
    return rospy.get_param(CHANNEL_PARAM, ROS)


def fleet_params():
    """The rason_mas ~params of this test's channel, for the robots a test starts itself (none
    for ROS topics, the default)."""
    if fleet_channel() == ROS:
        return {}
    return {'fleet_channel': MQTT, 'mqtt_url': rospy.get_param(URL_PARAM)}


# ---- MqttPayloads, in Python -------------------------------------------------------------

VERSION = 1
MESSAGE, PRESENCE, WILL = b'M', b'P', b'W'
_MESSAGE_FIELDS = ('sender_mas', 'sender', 'receiver_mas', 'receiver', 'performative', 'content', 'msg_id',
                   'in_reply_to')


class Will(object):
    """The last will of the connection ``link`` of process ``mas_id``."""

    def __init__(self, mas_id, link, incarnation=0, sequence=0, stamp=0, key_id='', mac=b''):
        self.mas_id, self.link = mas_id, link
        self.incarnation, self.sequence, self.stamp, self.key_id, self.mac = incarnation, sequence, stamp, key_id, mac


def _string(s):
    b = (s or '').encode('utf-8')
    return struct.pack('>i', len(b)) + b


def _strings(items):
    return struct.pack('>i', len(items)) + b''.join(_string(s) for s in items)


def _signed(m):
    u64 = 0xFFFFFFFFFFFFFFFF
    return (struct.pack('>QQQ', m.incarnation & u64, m.sequence & u64, m.stamp & u64) + _string(m.key_id)
            + struct.pack('>i', len(m.mac)) + bytes(m.mac))


def encode_message(m):
    """An AgentMessage as the MQTT channel publishes it."""
    return bytes([VERSION]) + MESSAGE + b''.join(_string(getattr(m, f)) for f in _MESSAGE_FIELDS) + _signed(m)


def encode_presence(p, link=''):
    """A Presence as the MQTT channel publishes it, announced over the connection named link."""
    return (bytes([VERSION]) + PRESENCE + _string(p.mas_id) + _strings(p.agents) + _strings(p.df_agents)
            + _strings(p.df_services) + struct.pack('>fB', p.period, 1 if p.leaving else 0) + _string(link)
            + _signed(p))


def encode_will(w):
    return bytes([VERSION]) + WILL + _string(w.mas_id) + _string(w.link) + _signed(w)


class _Reader(object):
    def __init__(self, payload):
        self.b, self.at = payload, 0

    def take(self, n):
        if n < 0 or self.at + n > len(self.b):
            raise ValueError('cut short')
        out = self.b[self.at:self.at + n]
        self.at += n
        return out

    def unpack(self, fmt):
        return struct.unpack(fmt, self.take(struct.calcsize(fmt)))

    def string(self):
        return self.take(self.unpack('>i')[0]).decode('utf-8')

    def strings(self):
        return [self.string() for _ in range(self.unpack('>i')[0])]

    def signed(self, into):
        into.incarnation, into.sequence, into.stamp = self.unpack('>QQQ')
        into.key_id = self.string()
        into.mac = self.take(self.unpack('>i')[0])
        return into


def decode(payload):
    """An AgentMessage, (Presence, link) or Will; ValueError if the payload is none of them."""
    r = _Reader(payload)
    version, kind = r.unpack('>Bc')
    if version != VERSION:
        raise ValueError('not a version %d payload' % VERSION)
    if kind == MESSAGE:
        out = r.signed(AgentMessage(**{f: r.string() for f in _MESSAGE_FIELDS}))
    elif kind == PRESENCE:
        p = Presence(mas_id=r.string(), agents=r.strings(), df_agents=r.strings(), df_services=r.strings())
        p.period, leaving = r.unpack('>fB')
        p.leaving = leaving != 0
        link = r.string()
        out = (r.signed(p), link)
    elif kind == WILL:
        out = r.signed(Will(r.string(), r.string()))
    else:
        raise ValueError('unknown kind %r' % kind)
    if r.at != len(payload):
        raise ValueError('%d bytes after the fields' % (len(payload) - r.at))
    return out


def presence_topic(mas_id):
    return PREFIX + 'presence/' + mas_id.lstrip('/')


def inbox_topic(mas_id):
    return PREFIX + 'inbox/' + mas_id.lstrip('/')


BROADCAST_TOPIC = PREFIX + 'broadcast'


# ---- the taps ----------------------------------------------------------------------------

class FleetTap(object):
    """Hears the fleet channel (``messages``: every AgentMessage; presence goes to ``on_presence``)
    and publishes on it. ``on_presence(presence)`` is called on a ROS or MQTT thread."""

    channel = None

    def __init__(self, on_presence=None):
        self._lock = threading.Lock()
        self.messages = []
        self._on_presence = on_presence or (lambda presence: None)

    def _heard_message(self, msg):
        with self._lock:
            self.messages.append(msg)

    def heard(self, predicate):
        """The messages heard so far for which predicate is true."""
        with self._lock:
            return [m for m in self.messages if predicate(m)]

    def wait_ready(self, receivers, timeout=30.0):
        """True once what this tap publishes reaches ``receivers`` processes (ROS) or the broker (MQTT)."""
        raise NotImplementedError

    def publish_message(self, msg):
        raise NotImplementedError

    def publish_presence(self, presence, on_topic_of=None, link=''):
        """Publish presence (over MQTT on the presence topic of ``on_topic_of``, default its mas_id)."""
        raise NotImplementedError


class RosTap(FleetTap):
    """/rason/messages and /rason/presence of this master, as this node."""

    channel = ROS

    def __init__(self, on_presence=None):
        super(RosTap, self).__init__(on_presence)
        self._subs = [rospy.Subscriber('/rason/messages', AgentMessage, self._heard_message, queue_size=None),
                      rospy.Subscriber('/rason/presence', Presence, self._on_presence, queue_size=100)]
        self._messages = rospy.Publisher('/rason/messages', AgentMessage, queue_size=100)
        self._presence = rospy.Publisher('/rason/presence', Presence, queue_size=100)

    def wait_ready(self, receivers, timeout=30.0):
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline and not rospy.is_shutdown():
            if min(self._messages.get_num_connections(), self._presence.get_num_connections()) >= receivers:
                return True
            time.sleep(0.02)
        return False

    def publish_message(self, msg):
        self._messages.publish(msg)

    def publish_presence(self, presence, on_topic_of=None, link=''):
        self._presence.publish(presence)


class MqttTap(FleetTap):
    """A client of the test's broker subscribed to everything under the prefix, with no fleet key.
    ``raw`` keeps every (topic, payload, retained) that arrived, for playing again or altering."""

    channel = MQTT

    def __init__(self, on_presence=None, url=None):
        super(MqttTap, self).__init__(on_presence)
        import paho.mqtt.client as mqtt
        from paho.mqtt.packettypes import PacketTypes
        from paho.mqtt.properties import Properties
        self._mqtt = mqtt
        self.raw = []
        self.unreadable = []
        address = urlparse(url or rospy.get_param(URL_PARAM))
        self._subscribed = threading.Event()
        self._client = mqtt.Client(client_id='rason-test-%s' % uuid.uuid4().hex[:12], protocol=mqtt.MQTTv5)
        self._client.on_connect = self._connected
        self._client.on_subscribe = lambda *args: self._subscribed.set()
        self._client.on_message = self._arrived
        self._expiry = Properties(PacketTypes.PUBLISH)
        self._expiry.MessageExpiryInterval = 60
        self._client.connect_async(address.hostname, address.port, keepalive=10, clean_start=True)
        self._client.loop_start()

    def _connected(self, client, userdata, flags, reason, properties=None):
        client.subscribe(PREFIX + '#', qos=1)

    def _arrived(self, client, userdata, msg):
        with self._lock:
            self.raw.append((msg.topic, bytes(msg.payload), bool(msg.retain)))
        try:
            item = decode(msg.payload)
        except ValueError as e:
            with self._lock:
                self.unreadable.append((msg.topic, str(e)))
            return
        if isinstance(item, AgentMessage):
            self._heard_message(item)
        elif isinstance(item, tuple):
            self._on_presence(item[0])

    def wait_ready(self, receivers=None, timeout=30.0):
        return self._subscribed.wait(timeout)

    def close(self):
        self._client.disconnect()
        self._client.loop_stop()

    def publish_raw(self, topic, payload, retain=False, timeout=10.0):
        """Publish payload (QoS 1) and wait until the broker has taken it."""
        info = self._client.publish(topic, payload, qos=1, retain=retain, properties=self._expiry)
        info.wait_for_publish(timeout)
        if not info.is_published():
            raise AssertionError('the broker did not take what was published on %s' % topic)

    def publish_message(self, msg):
        self.publish_raw(inbox_topic(msg.receiver_mas) if msg.receiver_mas else BROADCAST_TOPIC,
                         encode_message(msg))

    def publish_presence(self, presence, on_topic_of=None, link=''):
        self.publish_raw(presence_topic(on_topic_of or presence.mas_id), encode_presence(presence, link))

    def publish_will(self, will, on_topic_of=None):
        self.publish_raw(presence_topic(on_topic_of or will.mas_id), encode_will(will))

    def captured(self, predicate):
        """The (topic, payload) of everything that arrived whose decoded AgentMessage, Presence or
        Will passes predicate, in the order it arrived."""
        with self._lock:
            raw = list(self.raw)
        out = []
        for topic, payload, _ in raw:
            try:
                item = decode(payload)
            except ValueError:
                continue
            if predicate(item[0] if isinstance(item, tuple) else item):
                out.append((topic, payload))
        return out


def fleet_tap(on_presence=None):
    """A tap on this test's channel (call after rospy.init_node)."""
    return MqttTap(on_presence) if fleet_channel() == MQTT else RosTap(on_presence)
