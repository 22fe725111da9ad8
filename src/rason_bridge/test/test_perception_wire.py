"""The source of a serialized rason_msgs/Perception (rason_bridge.perception_wire), read from
genpy's own bytes, and the node's coalescing and pump with such raw messages (no ROS master)."""
import io
import struct

from rason_msgs.msg import Perception

from rason_bridge.coalesce import ADDED, DROPPED, REPLACED, PerceptionCoalescer
from rason_bridge.perception_pump import PerceptionPump
from rason_bridge.perception_wire import ANY_TYPE, SourceReader, max_message_bytes

HEADER = {'type': Perception._type, 'md5sum': Perception._md5sum, 'callerid': '/synth'}


def raw(source, literals):
    buff = io.BytesIO()
    Perception(source=source, perception=literals).serialize(buff)
    return buff.getvalue()


def reader(max_bytes=10 ** 6, max_source_length=256):
    return SourceReader(max_bytes, max_source_length, Perception._md5sum)


def test_the_source_is_the_one_genpy_reads():
    for source, literals in [('cam_robots', ['robot(faulty,-3.5,1.5,12)']), ('', []), ('caméra ✓ 𝄞', ['a', 'b'])]:
        message = raw(source, literals)
        assert reader().source(message, HEADER) == (source, None)
        assert Perception().deserialize(message).source == source


def test_invalid_utf8_in_the_source_becomes_replacement_characters_as_genpy_reads_it():
    message = struct.pack('<I', 4) + b'c\xe9m\xff' + struct.pack('<I', 0)
    assert reader().source(message, HEADER) == ('c\ufffdm\ufffd', None)
    assert Perception().deserialize(message).source == 'c\ufffdm\ufffd'


def test_a_message_too_short_for_its_source_is_refused_with_why():
    assert reader().source(b'', HEADER) == (None, 'not a rason_msgs/Perception: 0 bytes')
    assert reader().source(b'\x05\x00', HEADER) == (None, 'not a rason_msgs/Perception: 2 bytes')
    source, why = reader().source(struct.pack('<I', 2 ** 32 - 1) + b'abc', HEADER)
    assert source is None and why == 'not a rason_msgs/Perception: its source of 4294967295 bytes goes past its end'


def test_another_type_is_refused_and_any_type_or_no_header_is_read():
    message = raw('cam', ['a(1)'])
    source, why = reader().source(message, {'type': 'std_msgs/String', 'md5sum': '992ce8a1687cec8c8bd883ec73ca41d1'})
    assert source is None and why == 'its type std_msgs/String is not rason_msgs/Perception'
    assert reader().source(message, {'type': ANY_TYPE, 'md5sum': ANY_TYPE}) == ('cam', None)
    assert reader().source(message, None) == ('cam', None)


def test_a_message_bigger_than_the_limits_allow_is_refused_before_it_is_copied():
    limit = max_message_bytes(max_literals=3, max_literal_length=10, max_source_length=5)
    largest = raw('€€€€€', ['€' * 10] * 3)  # every field as long as allowed, at 3 bytes a character
    assert len(largest) <= limit
    assert reader(max_bytes=limit).source(largest, HEADER) == ('€€€€€', None)
    big = raw('cam', ['x' * (limit + 1)])
    source, why = reader(max_bytes=limit).source(big, HEADER)
    assert source is None and why == '%d bytes, more than %d: too many literals or one too long' % (len(big), limit)


def test_a_long_source_is_read_only_so_far_that_it_is_still_too_long():
    message = raw('s' * 10 ** 6, ['a(1)'])
    source, why = reader(max_bytes=len(message), max_source_length=256).source(message, HEADER)
    assert why is None and 256 < len(source) <= 4 * 257
    assert PerceptionCoalescer(max_source_length=256).put(source, message, 0) == DROPPED


def test_raw_messages_are_coalesced_by_their_source():
    sources, coalescer = reader(), PerceptionCoalescer()
    first, second, other = raw('cam', ['robot(a,1)']), raw('cam', ['robot(a,2)']), raw('odom', ['pose(1)'])
    assert coalescer.put(sources.source(first, HEADER)[0], first, 1) == ADDED
    assert coalescer.put(sources.source(other, HEADER)[0], other, 2) == ADDED
    assert coalescer.put(sources.source(second, HEADER)[0], second, 3) == REPLACED
    assert coalescer.take(0) == ('cam', second, 3)
    assert coalescer.take(0) == ('odom', other, 2)
    assert Perception().deserialize(second).perception == ['robot(a,2)']


def test_the_pump_hands_the_bytes_on_as_they_came():
    handed = []
    pump = PerceptionPump(PerceptionCoalescer(), lambda *args: handed.append(args), lambda: None,
                          lambda *a: None, lambda *a: None)
    message = raw('cam', ['robot(a,1)', 'battery(90)'])
    pump.put('cam', message, 7)
    pump.step()
    assert handed == [('cam', message, 7)]
    assert isinstance(handed[0][1], bytes)


def test_the_framing_read_here_and_in_java_is_genpys():
    # uint32 little-endian lengths and counts (rason.perception.PerceptionWire reads the rest)
    assert raw('a', ['b', '']) == b'\x01\x00\x00\x00a\x02\x00\x00\x00\x01\x00\x00\x00b\x00\x00\x00\x00'
