"""A ROS message sealed for the fleet's broker, and the checks a receiving robot makes.

The broker is not trusted (as for agent messages): every relayed message carries an
HMAC-SHA256 tag made with the fleet key, over a header that names the sender, the ROS topic,
the message type and a sequence number, and the serialized message itself. Layout::

    b'RSNT' | version (1 byte) | header length (2 bytes, big-endian) | header (JSON, UTF-8)
    | serialized ROS message | tag (32 bytes)

A receiver drops what it cannot verify, what was sealed for another topic, and what it has
seen before or is too old (:class:`ReplayGate`).
"""
import hashlib
import hmac
import json
import math
import struct

MAGIC = b'RSNT'
VERSION = 1
TAG_BYTES = 32
_FIXED = len(MAGIC) + 1 + 2
HEADER_FIELDS = {'from': str, 'topic': str, 'type': str, 'md5': str, 'boot': str, 'seq': int,
                 'sent': float, 'key': str}


class Refused(Exception):
    """A relayed message that is dropped; ``str()`` says why, for a rate-limited warning."""


def seal(key, sender, topic, msg_type, md5, boot, seq, sent, payload):
    """The bytes to publish: ``payload`` (a serialized ROS message of ``msg_type`` on ROS
    ``topic``) with its header and tag.

    :param key: ``(key_id, secret)``, the fleet's signing key
    :param boot: a random id of this relay's run; ``seq`` counts up within it
    :param sent: wall-clock seconds when sealed
    """
    key_id, secret = key
    header = json.dumps({'from': sender, 'topic': topic, 'type': msg_type, 'md5': md5,
                         'boot': boot, 'seq': seq, 'sent': sent, 'key': key_id},
                        sort_keys=True, separators=(',', ':')).encode('utf-8')
    body = MAGIC + bytes([VERSION]) + struct.pack('>H', len(header)) + header + bytes(payload)
    return body + hmac.new(secret, body, hashlib.sha256).digest()


def open_sealed(keys, data, max_bytes):
    """The header (a dict) and the serialized message of a sealed message.

    :param keys: ``{key_id: secret}`` of every key this robot accepts
    :raises Refused: not a sealed message, larger than ``max_bytes``, signed with a key not
        held here, or altered
    """
    if len(data) > max_bytes:
        raise Refused('%d bytes, over the %d allowed' % (len(data), max_bytes))
    if len(data) < _FIXED + TAG_BYTES or not data.startswith(MAGIC):
        raise Refused('not a relayed ROS message')
    if data[len(MAGIC)] != VERSION:
        raise Refused('relay format version %d, not %d' % (data[len(MAGIC)], VERSION))
    (header_length,) = struct.unpack('>H', data[len(MAGIC) + 1:_FIXED])
    body, tag = data[:-TAG_BYTES], data[-TAG_BYTES:]
    if _FIXED + header_length > len(body):
        raise Refused('a header longer than the message')
    try:
        header = json.loads(body[_FIXED:_FIXED + header_length].decode('utf-8'))
    except (UnicodeDecodeError, ValueError):
        raise Refused('a header that is not JSON')
    if not isinstance(header, dict):
        raise Refused('a header that is not a JSON object')
    secret = keys.get(header.get('key'))
    if secret is None:
        raise Refused('signed with key %r, which this robot does not hold (the robots\' key files differ)'
                      % (header.get('key'),))
    if not hmac.compare_digest(hmac.new(secret, body, hashlib.sha256).digest(), tag):
        raise Refused('a tag that does not match (altered, or not signed with the fleet key)')
    for name, kind in HEADER_FIELDS.items():
        value = header.get(name)
        if kind is float and isinstance(value, int) and not isinstance(value, bool):
            value = header[name] = float(value)
        if not isinstance(value, kind) or isinstance(value, bool):
            raise Refused('a header without a valid %r' % name)
    if not math.isfinite(header['sent']):
        raise Refused('a header whose sent time is not finite')
    return header, body[_FIXED + header_length:]


class ReplayGate:
    """Lets each sealed message through once, and none older than ``max_age`` seconds.

    Per sender and topic it keeps the newest run (``boot``), its highest ``seq`` and sent
    time. A message of that run must have a higher ``seq``; a message of another run must
    have been sent later than the newest accepted one (a relay that restarted), so an old run's
    messages cannot be played again. Senders beyond ``max_streams`` evict the least recently
    heard one.
    """

    def __init__(self, max_age, max_streams=1000):
        self._max_age = max_age
        self._max_streams = max_streams
        self._streams = {}      # (sender, topic) -> (boot, seq, sent); insertion order = recency

    def admit(self, header, now):
        """:raises Refused: replayed, out of order, or sent more than ``max_age`` s away from ``now``"""
        if abs(now - header['sent']) > self._max_age:
            raise Refused('sent %.1f s from this robot\'s clock (over %.1f s: stale, replayed or the '
                          'clocks differ)' % (now - header['sent'], self._max_age))
        stream = (header['from'], header['topic'])
        last = self._streams.get(stream)
        if last is not None:
            boot, seq, sent = last
            if header['boot'] == boot and header['seq'] <= seq:
                raise Refused('seen before or out of order (seq %d after %d)' % (header['seq'], seq))
            if header['boot'] != boot and header['sent'] <= sent:
                raise Refused('from an earlier run of the sender')
            del self._streams[stream]
        elif len(self._streams) >= self._max_streams:
            del self._streams[next(iter(self._streams))]
        self._streams[stream] = (header['boot'], header['seq'], header['sent'])
