"""The relay's two directions, without ROS or MQTT: what goes to the broker for a local
message, and what a message from the broker may be published as here."""
import secrets
import threading

from rason_relay.envelope import Refused, ReplayGate, open_sealed, seal
from rason_relay.settings import broker_topic


class Outbound:
    """Seals this robot's messages on the ``send`` topics (one sequence per run of the relay),
    at most ``max_rate`` a second per topic (0: all): a stream that outruns a lossy link would
    queue up behind it and arrive late, when only its newest message matters."""

    def __init__(self, settings, signing_key):
        self._settings = settings
        self._key = signing_key
        self._boot = secrets.token_hex(8)
        self._seq = 0
        self._period = 1.0 / settings.max_rate if settings.max_rate > 0 else 0.0
        self._last_sent = {}
        self._lock = threading.Lock()     # rospy calls each subscriber on its own thread

    def sealed(self, ros_topic, msg_type, md5, payload, now):
        """``(broker topic, bytes)`` for a message received on ``ros_topic``, or ``None`` when
        one went less than a period ago."""
        with self._lock:
            last = self._last_sent.get(ros_topic)
            if last is not None and 0 <= now - last < self._period:
                return None
            self._last_sent[ros_topic] = now
            self._seq += 1
            seq = self._seq
        data = seal(self._key, self._settings.robot, ros_topic, msg_type, md5, self._boot, seq, now, payload)
        return broker_topic(self._settings.prefix, ros_topic), data


class Inbound:
    """Checks what arrives on the ``receive`` topics' broker topics."""

    def __init__(self, settings, keys):
        """:param keys: ``[(key_id, secret), ...]`` of the fleet key file"""
        self._settings = settings
        self._keys = dict(keys)
        self._topics = {broker_topic(settings.prefix, name): name for name in settings.receive}
        self._gate = ReplayGate(settings.max_age)
        self._lock = threading.Lock()

    @property
    def broker_topics(self):
        return sorted(self._topics)

    def accepted(self, topic, data, now):
        """The header and serialized message to publish on header['topic'].

        :raises Refused: why the message is dropped
        """
        ros_topic = self._topics.get(topic)
        if ros_topic is None:
            raise Refused('on broker topic %r, which this relay does not receive' % topic)
        header, payload = open_sealed(self._keys, data, self._settings.max_bytes)
        if header['topic'] != ros_topic:
            raise Refused('sealed for %s but published on the broker topic of %s' % (header['topic'], ros_topic))
        with self._lock:
            self._gate.admit(header, now)
        return header, payload
