"""Records on the sim link's stream socket: a 5-byte header (body length, kind) and the body.

A reader is fed whatever recv returned (any split, any size) and hands back whole records;
a body over the size cap is an error (the stream cannot be resynchronised, so the link is
dropped) rather than an allocation of whatever a corrupt header says.
"""
import json
import struct

HEADER = struct.Struct('>IB')
CHANNEL = struct.Struct('>H')
# Largest body: the 640x480 point cloud is 4.9 MB; a few times that leaves room for a bigger
# camera and still refuses a garbage length.
MAX_BODY = 32 * 1024 * 1024

HELLO = 1      # JSON {protocol, side, robot}: each side's first record
REFUSE = 2     # JSON {reason}: the sender closes the link after it
TOPIC = 3      # JSON {channel, topic, type, md5}: announces a channel before its data
DATA = 4       # channel (uint16) + one serialized message
PRESENCE = 5   # JSON {subscribed: [...], publishing: [...]}: the robot master's side

KINDS = {HELLO: 'hello', REFUSE: 'refuse', TOPIC: 'topic', DATA: 'data', PRESENCE: 'presence'}
PROTOCOL = 1


class FramingError(Exception):
    """The stream holds something that is not a record: the link must be dropped."""


def header(kind, body_length, max_body=MAX_BODY):
    if kind not in KINDS:
        raise FramingError('unknown record kind %r' % kind)
    if body_length > max_body:
        raise FramingError('record of %d bytes over the %d-byte cap' % (body_length, max_body))
    return HEADER.pack(body_length, kind)


def json_record(kind, value):
    body = json.dumps(value, sort_keys=True).encode()
    return header(kind, len(body)) + body


def data_parts(channel, payload, max_body=MAX_BODY):
    """The pieces of a DATA record, to send one after the other (the payload is not copied)."""
    prefix = CHANNEL.pack(channel)
    return header(DATA, len(prefix) + len(payload), max_body) + prefix, payload


def decode_json(body):
    try:
        value = json.loads(bytes(body).decode())
    except (UnicodeDecodeError, ValueError) as err:
        raise FramingError('a control record is not JSON: %s' % err)
    if not isinstance(value, dict):
        raise FramingError('a control record is not a JSON object: %r' % (value,))
    return value


def decode_data(body):
    """(channel, payload) of a DATA body."""
    if len(body) < CHANNEL.size:
        raise FramingError('a data record of %d bytes has no channel' % len(body))
    return CHANNEL.unpack_from(body)[0], bytes(body[CHANNEL.size:])


class RecordReader:
    """Collects bytes from a stream and returns the whole records in them."""

    def __init__(self, max_body=MAX_BODY):
        self._max_body = max_body
        self._buffer = bytearray()

    def feed(self, data):
        """[(kind, body)] of every record completed by data, in order."""
        self._buffer += data
        records = []
        offset = 0
        while len(self._buffer) - offset >= HEADER.size:
            length, kind = HEADER.unpack_from(self._buffer, offset)
            if kind not in KINDS:
                raise FramingError('unknown record kind %d (not a sim link peer?)' % kind)
            if length > self._max_body:
                raise FramingError('record of %d bytes over the %d-byte cap'
                                   % (length, self._max_body))
            end = offset + HEADER.size + length
            if len(self._buffer) < end:
                break
            records.append((kind, bytes(self._buffer[offset + HEADER.size:end])))
            offset = end
        if offset:
            del self._buffer[:offset]
        return records

    @property
    def pending(self):
        """Bytes of a record not yet complete."""
        return len(self._buffer)
