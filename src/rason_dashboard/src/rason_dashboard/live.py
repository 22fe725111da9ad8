"""The live dashboard's ROS side: every jason/mind topic on the master (looked for again every
second, so robots that start later appear), the messages between robots and /diagnostics,
each at the ROS time it arrived. Subscribes only: the dashboard never publishes."""
import rospy
from diagnostic_msgs.msg import DiagnosticArray
from rason_msgs.msg import AgentMessage, MindState

from rason_dashboard.records import message_record, mind_record, status_records
from rason_dashboard.replay import MIND_TYPE

DISCOVERY_PERIOD = 1.0


class LiveFeed(object):

    def __init__(self, timeline, messages_topic='/rason/messages'):
        self._timeline = timeline
        self._minds = {}
        rospy.Subscriber(messages_topic, AgentMessage, self._on_message, queue_size=100)
        rospy.Subscriber('/diagnostics', DiagnosticArray, self._on_diagnostics, queue_size=100)
        self._discover()
        rospy.Timer(rospy.Duration(DISCOVERY_PERIOD), lambda _e: self._discover())

    def _discover(self):
        try:
            topics = rospy.get_published_topics()
        except Exception as e:  # the master is gone for a moment: look again next time
            rospy.logwarn_throttle(10, 'cannot list the topics: %s' % e)
            return
        for topic, kind in topics:
            if kind == MIND_TYPE and topic not in self._minds:
                rospy.loginfo('dashboard: watching %s', topic)
                self._minds[topic] = rospy.Subscriber(topic, MindState, self._on_mind, queue_size=10)

    @staticmethod
    def _now():
        return rospy.get_rostime().to_sec()

    def _on_mind(self, msg):
        self._timeline.add_mind(self._now(), mind_record(msg))

    def _on_message(self, msg):
        self._timeline.add_message(self._now(), message_record(msg))

    def _on_diagnostics(self, msg):
        for s in status_records(msg):
            self._timeline.add_status(self._now(), s)
