"""The rospy side of :class:`rason_bridge.rosout_writer.RosoutWriter`: /rosout messages as
rospy's own handler makes them, a batch of them written to each connection at once (rospy
plumbing)."""
import logging

import rospy
from rosgraph.roslogging import RosStreamHandler, _color_reset, _logging_to_rospy_names
from rosgraph_msgs.msg import Log
from rospy.impl.registration import get_topic_manager
from rospy.impl.rosout import RosOutHandler

from rason_bridge.log_frames import LogFrames
from rason_bridge.rosout_writer import RosoutWriter
from rason_bridge.screen_lines import emit_batch

_LEVELS = {'debug': Log.DEBUG, 'info': Log.INFO, 'warn': Log.WARN, 'error': Log.ERROR}


def rosout_writer():
    """A writer to the ``rosout`` logger's handlers and /rosout (after ``rospy.init_node``)."""
    pub = rospy.Publisher('/rosout', Log, latch=True, queue_size=100)  # rospy's own, shared
    frames = LogFrames(rospy.get_caller_id(), 'rosout_writer.py', 'write', 0)

    def publish(lines, topics):
        try:
            _publish_frames(pub, frames, [(_LEVELS[level], text) for level, text in lines], topics)
        except Exception as e:  # as rospy's handler: the lines still went to the screen and the file
            logging.getLogger('rospy.rosout').error('Unable to report rosout: %s', e)

    def screen(handler, records):
        emit_batch(handler, records, _logging_to_rospy_names, _color_reset, rospy.get_name())

    return RosoutWriter(logging.getLogger('rosout'), RosOutHandler, publish, lambda: get_topic_manager().get_topics(),
                        lambda: rospy.get_param_cached('/rosout_disable_topics_generation', False),
                        emitters={RosStreamHandler: screen})


def _publish_frames(pub, frames, lines, topics):
    """What ``pub.publish`` does for each line (its own sequence number, the latch keeps the
    last line), with the lines' frames written to each connection in one piece: one queue
    entry and one socket write per batch instead of per line."""
    impl = pub.impl
    if impl is None or impl.closed:
        return
    now = rospy.Time.now()
    impl.acquire()
    try:
        if impl.is_latch:
            last = Log(level=lines[-1][0], name=rospy.get_caller_id(), msg=lines[-1][1], topics=topics,
                       file='rosout_writer.py', line=0, function='write')
            last.header.stamp = now
            impl.latch = last
        if not impl.has_connections():
            return
        first, impl.seq = impl.seq + 1, impl.seq + len(lines)
        data = frames.frames(lines, first, now.secs, now.nsecs, topics or [])
        for c in list(impl.connections):
            try:
                if not rospy.is_shutdown():
                    c.write_data(data)
            except Exception:  # as rospy: a connection that fails a write is dropped
                impl.remove_connection(c)
        impl.message_data_sent += len(data)
    finally:
        impl.release()
