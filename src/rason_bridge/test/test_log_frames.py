"""LogFrames: a batch of lines serialized as the frames rospy would write for one Log
message each (compared with genpy's own serialization; no ROS master)."""
import io
import struct

from rosgraph_msgs.msg import Log

from rason_bridge.log_frames import LogFrames


def _genpy_frame(seq, level, text, topics, secs, nsecs, name='/rason_mas', file='rosout_writer.py', line=0,
                 function='write'):
    msg = Log(level=level, name=name, msg=text, topics=topics, file=file, line=line, function=function)
    msg.header.seq, msg.header.stamp.secs, msg.header.stamp.nsecs = seq, secs, nsecs
    buff = io.BytesIO()
    msg.serialize(buff)
    return struct.pack('<I', buff.tell()) + buff.getvalue()


def test_frames_are_genpys_bytes_line_by_line_with_their_sequence_numbers():
    frames = LogFrames('/rason_mas', 'rosout_writer.py', 'write', 0)
    lines = [(Log.INFO, '[bob] p1'), (Log.ERROR, 'hé 😀'), (Log.WARN, '')]
    topics = ['/rosout', '/jason/action']
    expected = b''.join(_genpy_frame(seq, level, text, topics, 17, 250) for seq, (level, text) in enumerate(lines, 41))
    assert frames.frames(lines, 41, 17, 250, topics) == expected


def test_a_change_of_topics_is_carried_and_no_topics_is_an_empty_list():
    frames = LogFrames('/rason_mas', 'rosout_writer.py', 'write', 0)
    frames.frames([(Log.INFO, 'a')], 1, 0, 0, ['/rosout'])
    assert frames.frames([(Log.INFO, 'a')], 2, 0, 0, ['/x', '/y']) == _genpy_frame(2, Log.INFO, 'a', ['/x', '/y'], 0, 0)
    assert frames.frames([(Log.INFO, 'a')], 3, 0, 0, []) == _genpy_frame(3, Log.INFO, 'a', [], 0, 0)


def test_the_sequence_number_wraps_as_a_uint32_and_the_fixed_fields_are_the_given_ones():
    frames = LogFrames('/n', 'f.py', 'g', 12)
    assert frames.frames([(Log.DEBUG, 'a')], 2 ** 32 + 5, 1, 2, ['/t']) == _genpy_frame(
        5, Log.DEBUG, 'a', ['/t'], 1, 2, name='/n', file='f.py', line=12, function='g')
