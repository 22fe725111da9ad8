"""A recorded bag as a Timeline: jason/mind, the messages between robots and the rason/*
statuses of /diagnostics, each at the time it was recorded. Reads the bag only: nothing is
published, so replaying never reaches live agents."""
import rosbag

from rason_dashboard.records import message_record, mind_record, status_records
from rason_dashboard.timeline import Timeline

MIND_TYPE = 'rason_msgs/MindState'
MESSAGE_TYPE = 'rason_msgs/AgentMessage'
DIAGNOSTICS_TYPE = 'diagnostic_msgs/DiagnosticArray'


def load_bag(path):
    """The Timeline of a bag; IOError/ROSBagException if it cannot be read. Returns (timeline, counts)."""
    timeline = Timeline(mode='replay')
    counts = {'minds': 0, 'messages': 0, 'statuses': 0}
    with rosbag.Bag(path) as bag:
        topics = bag.get_type_and_topic_info().topics
        wanted = [t for t, info in topics.items() if info.msg_type in (MIND_TYPE, MESSAGE_TYPE, DIAGNOSTICS_TYPE)]
        for topic, msg, stamp in bag.read_messages(topics=wanted):
            t = stamp.to_sec()
            kind = topics[topic].msg_type
            if kind == MIND_TYPE:
                timeline.add_mind(t, mind_record(msg))
                counts['minds'] += 1
            elif kind == MESSAGE_TYPE:
                timeline.add_message(t, message_record(msg))
                counts['messages'] += 1
            else:
                for s in status_records(msg):
                    timeline.add_status(t, s)
                    counts['statuses'] += 1
    return timeline, counts
