"""The Python half of the ROS-topic fleet channel (Java's ``RosTopicChannel``): publishes our
agents' messages on ``messages_topic``, our presence on ``presence_topic`` and our pulses on
``pulse_topic``, signed by Java in
publishing order, and tells Java which processes our message publisher reaches (rospy
plumbing; what arrives is :mod:`rason_bridge.inbound`'s). With ``~fleet_channel: mqtt`` Java's
MQTT channel does all of it and this part is not made."""
import rospy
from rason_msgs.msg import AgentMessage, Presence, Pulse

from rason_bridge import ros_links, signed
from rason_bridge.link_repair import LinkRepair
from rason_bridge.link_tuning import LinkTuner
from rason_bridge.message_sender import HELD, MessageSender


class RosFleet(object):
    """
    :param channel: Java's ``RosTopicChannel``
    :param agent_names: ``agent_names()`` -> our agents, as presence announces them
    :param settings: :data:`rason_bridge.params.Settings`
    :param wake_held: wakes the thread that flushes held messages
    """

    def __init__(self, channel, agent_names, settings, mas_id, wake_held):
        self._channel = channel
        self._agent_names = agent_names
        self._settings = s = settings
        self._mas_id = mas_id
        self._wake_held = wake_held
        self._message_pub = rospy.Publisher(s.messages_topic, AgentMessage, queue_size=1000, tcp_nodelay=True)
        self._presence_pub = rospy.Publisher(s.presence_topic, Presence, queue_size=10, tcp_nodelay=True)
        self._pulse_pub = rospy.Publisher(s.pulse_topic, Pulse, queue_size=10, tcp_nodelay=True)
        self._links = LinkTuner(rospy.logwarn)
        self._links.watch(self._message_pub)
        self._links.watch(self._presence_pub)
        self._links.watch(self._pulse_pub)
        self._repair = LinkRepair(s.presence_timeout)
        self._repair.publishers(self._message_pub, self._presence_pub, self._pulse_pub)
        _cache_rosout_setting()
        # signed when published, in publishing order, so the sequence numbers arrive increasing
        self.messages = MessageSender(publish=self._sign_and_publish,
                                      linked=lambda mas: ros_links.linked(self._message_pub, mas),
                                      connect_wait=s.connect_wait)

    def repair_links(self, subscribers):
        """Make the fleet subscribers' connections again when they end (rospy does not)."""
        self._repair.subscribers(*subscribers)

    def peer_heard(self, node):
        """A pulse or presence of node arrived (the link to it works)."""
        self._repair.heard(node)

    def presence_tick(self):
        self._links.tune()
        self._repair.check()
        self._channel.presenceTick(ros_links.linked_processes(self._message_pub))

    def publish_presence(self, leaving):
        """Announce our agents (called under the presence loop's lock: signed in publishing order)."""
        try:
            self._presence_pub.publish(signed.presence(self._channel, self._agent_names(), self._mas_id,
                                                       self._settings.presence_period, leaving))
            if not leaving:  # over a connection of its own: see docs/guides/fleet-channel.md, Pulses
                self._pulse_pub.publish(signed.pulse(self._channel, self._mas_id))
        except Exception as e:  # topic closed at shutdown
            rospy.logdebug('presence not announced: %s', e)

    def publish_message(self, sender, receiver_mas, receiver, performative, content, msg_id, in_reply_to):
        msg = AgentMessage(sender_mas=self._mas_id, sender=sender, receiver_mas=receiver_mas, receiver=receiver,
                           performative=performative, content=content, msg_id=msg_id, in_reply_to=in_reply_to)
        try:
            if self.messages.submit(msg, receiver_mas) == HELD:
                self._wake_held()
        except Exception as e:  # topic closed at shutdown
            rospy.logwarn('[%s] could not send %s to %s: %s', sender, performative, receiver or 'everyone', e)

    def _sign_and_publish(self, msg):
        # the message sender calls it in publishing order
        self._message_pub.publish(signed.sign_message(self._channel, msg))

    def warn_unlinked(self, m):
        rospy.logwarn('[%s] %s to %s published although %s is still not connected after %.1f s: '
                      'it is probably lost', m.sender, m.performative, m.receiver, m.receiver_mas,
                      self._settings.connect_wait)


#: rospy reads this parameter at every log line; while it is not set, rospy does not cache the
#: answer and asks the master each time (a TCP connection per line): across a lossy link to the
#: master's host, 40 lines took 7 to 34 s, and every thread that logs waits that long.
ROSOUT_TOPICS_PARAM = '/rosout_disable_topics_generation'


def _cache_rosout_setting():
    """Set the parameter to its default (false) if nobody did, so that every node caches it."""
    try:
        if not rospy.has_param(ROSOUT_TOPICS_PARAM):
            rospy.set_param(ROSOUT_TOPICS_PARAM, False)
    except Exception as e:  # the master is unreachable: log lines still work, only slower
        rospy.logwarn('could not set %s: %s', ROSOUT_TOPICS_PARAM, e)
