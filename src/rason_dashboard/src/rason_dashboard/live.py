"""The live dashboard's ROS side: every jason/mind topic on the master and every robot's
/<robot>/true_pose and /<robot>/odom (looked for again every second, so robots that start
later appear), /tf_static, the messages between robots and /diagnostics, each at the ROS time
it arrived. Subscribes only: the dashboard never publishes."""
import rospy
from diagnostic_msgs.msg import DiagnosticArray
from geometry_msgs.msg import PoseStamped
from nav_msgs.msg import Odometry
from rason_msgs.msg import AgentMessage, MindState
from tf2_msgs.msg import TFMessage

from rason_dashboard.poses import pose_records, pose_topic_kind
from rason_dashboard.records import message_record, mind_record, status_records
from rason_dashboard.replay import MIND_TYPE

DISCOVERY_PERIOD = 1.0
_POSE_TYPES = {'true': PoseStamped, 'odom': Odometry, 'origin': TFMessage}


class LiveFeed(object):

    def __init__(self, timeline, messages_topic='/rason/messages'):
        self._timeline = timeline
        self._minds = {}
        self._poses = {}
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
            pose_kind = pose_topic_kind(topic, kind)
            if pose_kind and topic not in self._poses:
                self._poses[topic] = rospy.Subscriber(topic, _POSE_TYPES[pose_kind], self._on_pose,
                                                      callback_args=(pose_kind, topic), queue_size=5)

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

    def _on_pose(self, msg, kind_topic):
        kind, topic = kind_topic
        t = self._now()
        for robot, pose in pose_records(kind, topic, msg):
            if not self._timeline.add_pose(t, kind, robot, pose):
                rospy.logwarn_throttle(10, 'dashboard: a pose on %s is not finite: left out' % topic)
