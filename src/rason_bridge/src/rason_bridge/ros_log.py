"""The rospy side of :class:`rason_bridge.rosout_writer.RosoutWriter`: /rosout messages as
rospy's own handler makes them (rospy plumbing)."""
import logging

import rospy
from rosgraph_msgs.msg import Log
from rospy.impl.registration import get_topic_manager
from rospy.impl.rosout import RosOutHandler

from rason_bridge.rosout_writer import RosoutWriter

_LEVELS = {'debug': Log.DEBUG, 'info': Log.INFO, 'warn': Log.WARN, 'error': Log.ERROR}


def rosout_writer():
    """A writer to the ``rosout`` logger's handlers and /rosout (after ``rospy.init_node``)."""
    pub = rospy.Publisher('/rosout', Log, latch=True, queue_size=100)  # rospy's own, shared

    def publish(level_name, text, topics, record):
        msg = Log(level=_LEVELS[level_name], name=rospy.get_caller_id(), msg=text, topics=topics,
                  file=record.filename, line=record.lineno, function=record.funcName)
        msg.header.stamp = rospy.Time.now()
        try:
            pub.publish(msg)
        except Exception as e:  # as rospy's handler: the line still went to the screen and the file
            logging.getLogger('rospy.rosout').error('Unable to report rosout: %s', e)

    return RosoutWriter(logging.getLogger('rosout'), RosOutHandler, publish, lambda: get_topic_manager().get_topics(),
                        lambda: rospy.get_param_cached('/rosout_disable_topics_generation', False))
