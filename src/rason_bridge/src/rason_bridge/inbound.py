"""ROS -> agents: the subscriptions of rason_mas, each message handed to Java as it comes
(rospy plumbing; parsing and checking are Java's)."""
import threading
import time

import rospy
from rason_msgs.msg import AgentMessage, Event, Perception, Presence, Pulse
from rosgraph_msgs.msg import Clock

from rason_bridge import java_config
from rason_bridge.clock_watch import ClockWatch
from rason_bridge.fleet_auth import to_int64
from rason_bridge.perception_wire import SourceReader, max_message_bytes
from rason_bridge.ros_links import publisher

#: How often at most a dropped perception message is logged (s).
DROPPED_PERIOD = 10


class Inbound(object):
    """
    :param java_bridge: Java's ``Bridge``
    :param channel: its ``RosTopicChannel``, which takes the fleet's messages and presence
    :param perceptions: the :class:`rason_bridge.perception_pump.PerceptionPump`
    :param now_ns: ``now_ns()`` -> the ROS time in nanoseconds
    :param settings: :data:`rason_bridge.params.Settings` (the input limits)
    """

    def __init__(self, java_bridge, channel, mas_id, perceptions, now_ns, settings):
        self._bridge = java_bridge
        self._channel = channel
        self._mas_id = mas_id
        self._perceptions = perceptions
        max_source_length = java_config.max_source_length()
        self._sources = SourceReader(max_message_bytes(settings.max_literals, settings.max_literal_length,
                                                       max_source_length), max_source_length, Perception._md5sum)
        self._now_ns = now_ns
        self.events = None  # the jason/event subscriber, once subscribed
        self._peer_heard = lambda node: None

    def subscribe(self):
        self.events = rospy.Subscriber('jason/event', Event, self._on_event, queue_size=None, tcp_nodelay=True)
        # serialized: Java reads the literals (perceiveSerialized), no Python strings per message
        rospy.Subscriber('jason/perception', rospy.AnyMsg, self._on_perception, queue_size=100, tcp_nodelay=True)

    def subscribe_fleet(self, settings, peer_heard):
        """The fleet over ROS topics (not with ``fleet_channel: mqtt``, whose channel is Java's);
        ``peer_heard(node)`` for each message, pulse and presence of another process. Returns the subscribers."""
        self._peer_heard = peer_heard
        return (rospy.Subscriber(settings.messages_topic, AgentMessage, self._on_message, queue_size=None,
                                 tcp_nodelay=True),
                rospy.Subscriber(settings.presence_topic, Presence, self._on_presence, queue_size=100,
                                 tcp_nodelay=True),
                rospy.Subscriber(settings.pulse_topic, Pulse, self._on_pulse, queue_size=100, tcp_nodelay=True))

    def follow_clock(self, java_error):
        """Under /use_sim_time, Jason's .wait, .at, deadlines and .send timeouts follow /clock
        (each message is pushed to Java, so a wait ends within one clock step of its time)."""
        sim_time = bool(rospy.get_param('/use_sim_time', False))
        try:
            self._bridge.agentsOnRosTime(sim_time)
        except java_error as e:
            rospy.logerr('the agents keep the wall clock for .wait and timeouts: %s', e.getMessage())
            return
        if sim_time:
            self._clock_watch = ClockWatch()
            rospy.Subscriber('/clock', Clock, self._on_clock, queue_size=1, tcp_nodelay=True)
            rospy.loginfo('agents on ROS time: .wait and Jason timeouts follow /clock')
            threading.Thread(target=self._watch_clock, name='rason_clock_watch', daemon=True).start()

    def _on_clock(self, msg):
        now = msg.clock.to_nsec()
        self._clock_watch.heard(now)
        self._bridge.clockAdvanced(now)

    def _watch_clock(self):
        # on the wall clock: rospy's timers stand still with /clock
        while not rospy.is_shutdown():
            time.sleep(1.0)
            line = self._clock_watch.due()
            if line:
                rospy.logwarn('%s', line)

    def _on_perception(self, msg):
        source, why = self._sources.source(msg._buff, getattr(msg, '_connection_header', None))
        if why is not None:
            rospy.logwarn_throttle(DROPPED_PERIOD, 'dropped a message on jason/perception from %s: %s',
                                   publisher(msg) or 'an unknown node', why)
            return
        self._perceptions.put(source, msg._buff, self._now_ns())

    def _on_event(self, msg):
        # parsed and checked in Java; the publisher is the decomposer to watch after action_started
        self._bridge.actions().event(msg.agent, msg.event_type, msg.parameters, publisher(msg))

    def _on_message(self, msg):
        if msg.sender_mas == self._mas_id:
            return
        self._peer_heard(publisher(msg))
        if msg.receiver_mas and msg.receiver_mas != self._mas_id:
            return  # for another process: the common case, kept out of Java
        try:
            # checked (authentication, then form) and parsed in Java
            self._channel.deliver(msg.sender_mas, msg.sender, msg.receiver_mas, msg.receiver,
                                  msg.performative, msg.content, msg.msg_id, msg.in_reply_to,
                                  to_int64(msg.incarnation), to_int64(msg.sequence), to_int64(msg.stamp),
                                  msg.key_id, msg.mac, publisher(msg))
        except Exception as e:  # a bug must not kill the subscriber thread
            rospy.logerr('could not deliver message from %s (%s): %s', msg.sender, msg.sender_mas, e)

    def _on_presence(self, msg):
        if msg.mas_id == self._mas_id:
            return
        self._peer_heard(publisher(msg))
        if msg.incarnation >= 2 ** 63:
            rospy.logwarn_throttle(10, 'ignored presence of %r: incarnation %d out of range',
                                   msg.mas_id, msg.incarnation)
            return
        try:
            self._channel.presenceAnnounced(msg.mas_id, msg.incarnation, msg.agents, msg.df_agents,
                                            msg.df_services, msg.period, msg.leaving, to_int64(msg.sequence),
                                            to_int64(msg.stamp), msg.key_id, msg.mac, publisher(msg))
        except Exception as e:
            rospy.logerr('could not handle presence of %r: %s', msg.mas_id, e)

    def _on_pulse(self, msg):
        if msg.mas_id == self._mas_id:
            return
        self._peer_heard(publisher(msg))
        try:
            self._channel.pulseArrived(msg.mas_id, to_int64(msg.incarnation), to_int64(msg.sequence),
                                       to_int64(msg.stamp), msg.key_id, msg.mac, publisher(msg))
        except Exception as e:  # a bug must not kill the subscriber thread
            rospy.logerr_throttle(10, 'could not handle a pulse of %r: %s', msg.mas_id, e)
