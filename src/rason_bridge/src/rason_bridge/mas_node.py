"""The rason_mas node: runs a Jason project's agents on ROS topics (thesis §5.2),
and lets them talk to the agents of other rason_mas processes (thesis §5.6).

rospy plumbing only. The tables (actions, perceptions, presence, remote asks)
live on the Java side (jason_lib, behind ``rason.bridge.Bridge``); this node
pushes ROS input and the ROS time in, and one thread of it publishes what the
agents queued in the Java ``Outbox``, so an agent's thread never calls Python.
The decisions that are Python's are in :mod:`rason_bridge.outbox` and
:mod:`rason_bridge.peers`; the fleet authentication's parameters in
:mod:`rason_bridge.fleet_auth` (signing and checking are Java's).
"""
import logging
import os
import sys
import threading
import time

import rosgraph
import rospkg
import rospy
from rospy.impl.rosout import RosOutHandler
from rason_msgs.msg import Action, AgentMessage, Event, MindState, Perception, Presence
from rosgraph_msgs.msg import Clock

from rason_bridge.coalesce import FloodEnd, PerceptionCoalescer
from rason_bridge.exits import exit_for_shutdown
from rason_bridge.fleet_auth import OFF, auth_settings, no_key_help, to_int64, to_uint64
from rason_bridge.jvm import JvmError, start_jvm
from rason_bridge.limits import apply_input_limits, seconds_to_nanos
from rason_bridge.mind import MindSwitch, mind_settings, to_msg as mind_msg
from rason_bridge.outbox import DEFERRED, NO_DECOMPOSER, ActionOutbox
from rason_bridge.peers import HELD, MessageOutbox
from rason_bridge.trust import apply_trust

_JAVA_SEVERE = 1000
_JAVA_WARNING = 900
_JAVA_INFO = 800


def _ros_now_ns():
    return rospy.get_rostime().to_nsec()


def _publisher(msg):
    """The node that published msg (its connection's callerid), '' if unknown."""
    header = msg._connection_header
    return header.get('callerid', '') if header else ''


class FleetKeyError(RuntimeError):
    """Fleet authentication is required and no usable key could be loaded."""


#: Presence: how often the fleet checks links and silences (wall clock, seconds).
_PRESENCE_TICK = 0.05
#: How often the log thread looks for lines queued by the agents (seconds), and how many it takes at once.
_LOG_POLL = 0.02
_LOG_BATCH = 500
#: How long the outbound thread blocks in Java waiting for the agents' next action or message (ms).
_OUTBOUND_WAIT_MS = 200
#: How long the perception thread waits for a message before it looks at its stop flag (s),
#: and how often at most it logs what a flood made it skip (s, wall clock).
_PERCEIVE_WAIT = 0.2
_COALESCED_LOG_PERIOD = 10.0
#: How long a message from a new source may hold its connection back while max_sources
#: others wait, before it is dropped (s).
_ROOM_WAIT = 1.0


class RasonMasNode(object):
    """Hosts one Jason MAS in this rospy process and wires it to the jason/* topics
    and to the other rason_mas processes.

    :param action_timeout: seconds (ROS time) before an action without feedback fails ``timeout``; 0 disables
    :param perception_ttl: seconds (ROS time) before a silent source's perceptions are dropped; 0 disables
    :param connect_wait: seconds an action waits for listed decomposers to connect, and a message
        for a process just heard of waits for the link to it
    :param messages_topic: topic shared by all processes for agent messages
    :param presence_topic: topic shared by all processes for presence announcements
    :param presence_period: seconds between our announcements
    :param presence_timeout: seconds of silence after which another process has left
    :param presence_beliefs: whether agents get ``present(Name)`` percepts
    :param ask_timeout: seconds (ROS time) a synchronous ask to a remote agent may wait; 0 disables
    :param agent_prefix: prepended to every agent name of the project
    :param perception_manager: default perception strategy (``per_source``, ``accumulate`` or a class)
    :param decomposer_grace: seconds (wall clock) the decomposer that took an action may be
        unreachable before the action fails ``decomposer_lost``
    :raises ValueError: a parameter that cannot be used (the message says why)
    """

    def __init__(self, action_timeout=60.0, perception_ttl=2.0, connect_wait=2.0,
                 messages_topic='/rason/messages', presence_topic='/rason/presence',
                 presence_period=0.5, presence_timeout=2.0, presence_beliefs=True,
                 ask_timeout=60.0, agent_prefix='', perception_manager='per_source',
                 decomposer_grace=0.5):
        import jpype  # the JVM is started by main() before this point
        self._jpype = jpype
        self._bridge = jpype.JClass('rason.bridge.Bridge').get()
        self._bridge.setActionTimeoutNanos(seconds_to_nanos('action_timeout', action_timeout))
        self._bridge.setPerceptionTtlNanos(seconds_to_nanos('perception_ttl', perception_ttl))
        if presence_period <= 0 or presence_timeout <= presence_period:
            raise ValueError('presence_timeout (%s s) must be longer than presence_period (%s s) > 0'
                             % (presence_timeout, presence_period))
        self._bridge.setPresenceTimeoutNanos(seconds_to_nanos('presence_timeout', presence_timeout))
        self._bridge.setAskTimeoutNanos(seconds_to_nanos('ask_timeout', ask_timeout))
        if decomposer_grace < 0:
            raise ValueError('decomposer_grace must be 0 s or more, not %s' % decomposer_grace)
        self._bridge.setDecomposerGraceNanos(seconds_to_nanos('decomposer_grace', decomposer_grace))
        self._bridge.setPresenceBeliefs(bool(presence_beliefs))
        try:
            self._bridge.setDefaultPerceptionManager(perception_manager)
        except jpype.JException as e:
            raise ValueError('perception_manager: %s' % e.getMessage())
        self._agent_prefix = agent_prefix
        self._mas = None
        self._stopping = False
        #: exit status of the process (set by .stopMAS(Deadline, StopJVM, Code))
        self.exit_code = 0

        self._action_topic = rospy.resolve_name('jason/action')
        self._action_pub = rospy.Publisher('jason/action', Action, queue_size=1000, tcp_nodelay=True)
        self._master = rosgraph.Master(rospy.get_name())
        self._outbox = ActionOutbox(
            publish=self._action_pub.publish,
            connected=self._action_pub.get_num_connections,
            listed=self._listed_action_subscribers,
            fail=self._action_not_sent,
            connect_wait=connect_wait)
        self._outbox_wakeup = threading.Event()
        self._connect_wait = connect_wait

        # Between processes: the node name is unique on a master, so it is the MAS id;
        # the start time tells a restarted process from the one before.
        self.mas_id = rospy.get_name()
        self._incarnation = time.time_ns()
        self._bridge.setMasId(self.mas_id)
        self._bridge.setIncarnation(self._incarnation)
        self._presence_period = presence_period
        self._presence_stop = threading.Event()
        self._announce_lock = threading.Lock()
        self._messages_topic = messages_topic
        self._message_pub = rospy.Publisher(messages_topic, AgentMessage, queue_size=1000, tcp_nodelay=True)
        self._presence_pub = rospy.Publisher(presence_topic, Presence, queue_size=10, tcp_nodelay=True)
        self._presence_topic = presence_topic
        # signed when published, in publishing order, so the sequence numbers arrive increasing
        self._messages = MessageOutbox(publish=self._sign_and_publish, linked=self._linked,
                                       connect_wait=connect_wait)
        self._log_lines = jpype.JClass('rason.infra.RosLogHandler')
        self._log_stop = threading.Event()
        self._outbound_stop = threading.Event()
        self._outbound_thread = None
        outbound = 'rason.bridge.Outbound$'
        self._action_item = jpype.JClass(outbound + 'Action')
        self._cancel_item = jpype.JClass(outbound + 'Cancel')
        self._events_sub = None
        self._perceptions = None  # the coalescer, made in start() once the limits are set
        self._perceive_thread = None
        self._message_item = jpype.JClass(outbound + 'AgentMessage')
        self._stop_item = jpype.JClass(outbound + 'Stop')
        self._announce_item = jpype.JClass(outbound + 'Announce')
        self._mind = None  # (settings, publisher, switch) once configure_mind() was called
        self._bridge.attach()  # the agents' outbox and log are ours from now on
        threading.Thread(target=self._log_loop, name='rason_log', daemon=True).start()

    def input_limits(self):
        """The bounds on perceptions and messages (Java's InputLimits; see :mod:`rason_bridge.limits`)."""
        return self._bridge.limits()

    def set_trust(self, value):
        """Rules of the ~trust parameter (see :mod:`rason_bridge.trust`); ValueError if one is bad."""
        apply_trust(self._bridge, value, self._jpype.JException)

    def configure_auth(self, settings):
        """Sign and check messages and presence with the fleet key, or not at all (before :meth:`start`).

        :param settings: :class:`rason_bridge.fleet_auth.AuthSettings`
        :raises FleetKeyError: authentication is required and the key cannot be loaded (the message says why)
        """
        if settings.mode == OFF:
            self._bridge.fleetAuthOff()
            return
        self._bridge.setAuthWindowNanos(seconds_to_nanos('auth_window', settings.window))
        try:
            if settings.key_text is not None:
                rospy.logwarn('the fleet key comes from ~fleet_key: anyone who reaches the ROS master can read the '
                              'parameter server, and with it command these agents; prefer ~fleet_key_file')
                self._bridge.requireFleetKeyText(settings.key_text, '~fleet_key')
            else:
                self._bridge.requireFleetKeyFile(settings.key_file)
        except self._jpype.JException as e:
            raise FleetKeyError(str(e.getMessage()))

    def configure_mind(self, settings):
        """Publish the agents' mental state on jason/mind (:mod:`rason_bridge.mind`; before :meth:`start`).

        :param settings: :class:`rason_bridge.mind.MindSettings`; period 0 publishes nothing
        """
        if settings.period <= 0:
            return
        self._bridge.setMindLimits(settings.max_items, settings.max_chars)
        self._bridge.setMindPeriodNanos(0)  # read only once somebody subscribes
        publisher = rospy.Publisher('jason/mind', MindState, queue_size=2, latch=True)
        self._mind = (settings, publisher, MindSwitch(seconds_to_nanos('mind_period', settings.period)))

    # ---- life cycle -----------------------------------------------------------------

    def load(self, mas2j_path):
        """Load and create the project's agents; returns their names.

        :raises RuntimeError: the project or all of its agents could not be loaded
        """
        mas_class = self._jpype.JClass('rason.infra.RasonLocalMAS')
        self._mas = mas_class()
        try:
            self._mas.setAgentPrefix(self._agent_prefix)
            self._mas.load(mas2j_path)
            self._mas.create()
        except self._jpype.JException as e:
            raise RuntimeError(str(e.getMessage()))
        names = [str(n) for n in self._bridge.agentNames()]
        if not names:
            raise RuntimeError('no agent of %s could be created (see the errors above)' % mas2j_path)
        return names

    def start(self):
        """Subscribe to the jason/* topics and start the agents' reasoning."""
        self._outbox.refresh_listed()
        self._perceptions = PerceptionCoalescer(
            max_sources=int(self._bridge.limits().maxSources()),
            max_source_length=int(self._jpype.JClass('rason.bridge.InputLimits').MAX_SOURCE_LENGTH))
        self._perceive_thread = threading.Thread(target=self._perceive_loop, name='rason_perceive', daemon=True)
        self._perceive_thread.start()
        self._events_sub = events_sub = rospy.Subscriber('jason/event', Event, self._on_event,
                                      queue_size=None, tcp_nodelay=True)
        rospy.Subscriber('jason/perception', Perception, self._on_perception,
                         queue_size=100, tcp_nodelay=True)
        rospy.Subscriber(self._messages_topic, AgentMessage, self._on_message,
                         queue_size=None, tcp_nodelay=True)
        rospy.Subscriber(self._presence_topic, Presence, self._on_presence,
                         queue_size=100, tcp_nodelay=True)
        # Feedback from a decomposer that is not connected yet would be lost:
        # let the running ones connect before the agents act.
        self._wait_for_publishers(events_sub, self._connect_wait)
        self._outbound_thread = threading.Thread(target=self._outbound_loop, name='rason_outbound', daemon=True)
        self._outbound_thread.start()
        threading.Thread(target=self._outbox_loop, name='rason_outbox', daemon=True).start()
        threading.Thread(target=self._presence_loop, name='rason_presence', daemon=True).start()
        if self._mind is not None:
            threading.Thread(target=self._mind_loop, name='rason_mind', daemon=True).start()
        self._use_ros_time_for_agents()
        self._bridge.tick(_ros_now_ns())  # the agents' clock is known before their first action
        rospy.Timer(rospy.Duration(0.05), self._on_tick)
        # whatever an earlier run of this node left running stops, before the agents' first action
        for agent in self._bridge.agentNames():
            self._publish_cancel(str(agent), 0, Event.RESTART)
        self._mas.start()

    def close_log(self):
        """Write what Java still has queued and log to stderr from now on (before the node exits)."""
        self._log_stop.set()
        self._bridge.detach()
        while self._drain_log():
            pass

    def stop(self, grace=0.5, join_timeout=3.0):
        """Fail pending actions with ``shutdown``, let failure plans run for ``grace`` s, stop the agents."""
        if self._stopping:
            return
        self._stopping = True
        # first, so the other processes stop counting on our agents at once
        self._presence_stop.set()
        self._announce(leaving=True)
        if self._perceptions is not None:
            self._perceptions.close()
        self._bridge.shutdown('shutdown')
        time.sleep(grace)
        if self._mas is not None:
            ended = self._mas.stopAgents(int(join_timeout * 1000))
            if not ended:
                rospy.logwarn('some agents did not stop within %.1f s', join_timeout)
        # what the agents queued before they stopped still goes out
        self._outbound_stop.set()
        if self._outbound_thread is not None:
            self._outbound_thread.join(join_timeout)
        self.close_log()

    def shutdown_requested(self, reason):
        """rospy is shutting down for ``reason``: a node that took our name ends us with an error."""
        code, why = exit_for_shutdown(reason)
        if code:
            self.exit_code = code
            # rospy asks the master for a parameter on every rosout line (rosout_disable_topics_generation),
            # and that call, made under our name, would make the master shut the new node down in turn
            rosout = logging.getLogger('rosout')
            for handler in list(rosout.handlers):
                if isinstance(handler, RosOutHandler):
                    rosout.removeHandler(handler)
            rospy.logfatal(why)  # stderr and the log file only

    # ---- ROS -> agents -------------------------------------------------------------

    def _on_perception(self, msg):
        # Only stored: the newest message of its source wins (see rason_bridge.coalesce), so
        # a flood never queues up here, in TCP or in the publisher in front of the agents.
        self._perceptions.put(msg.source, msg.perception, _ros_now_ns(), wait=_ROOM_WAIT)

    def _perceive_loop(self):
        # The one thread that hands perceptions to Java (parsed there, then to every agent).
        next_summary = time.monotonic() + _COALESCED_LOG_PERIOD
        flood = FloodEnd()
        while not self._stopping and not rospy.is_shutdown():
            if flood.ended(self._perceptions.overtaken(), time.monotonic()):
                self._bridge.releaseMemory()  # what the flood made the JVM grow goes back now
            item = self._perceptions.take(_PERCEIVE_WAIT)
            if item is not None:
                source, literals, stamp = item
                try:
                    self._bridge.perceive(source, literals, stamp)
                except Exception as e:  # a bug must not end the thread every perception goes through
                    rospy.logerr('could not hand the perception of %r to the agents: %s', source[:100], e)
            if time.monotonic() >= next_summary:
                next_summary = time.monotonic() + _COALESCED_LOG_PERIOD
                line = self._perceptions.summary()
                if line:
                    rospy.logwarn('perceptions come faster than the agents take them: %s in the last %.0f s',
                                  line, _COALESCED_LOG_PERIOD)

    def _on_event(self, msg):
        # parsed and checked in Java; the publisher is the decomposer to watch after action_started
        publisher = msg._connection_header.get('callerid', '') if msg._connection_header else ''
        self._bridge.event(msg.agent, msg.event_type, msg.parameters, publisher)

    def _on_tick(self, _event):
        self._bridge.tick(_ros_now_ns())

    def _use_ros_time_for_agents(self):
        """Under /use_sim_time, Jason's .wait, .at, deadlines and .send timeouts follow /clock
        (each message is pushed to Java, so a wait ends within one clock step of its time)."""
        sim_time = bool(rospy.get_param('/use_sim_time', False))
        try:
            self._bridge.agentsOnRosTime(sim_time)
        except self._jpype.JException as e:
            rospy.logerr('the agents keep the wall clock for .wait and timeouts: %s', e.getMessage())
            return
        if sim_time:
            rospy.Subscriber('/clock', Clock, self._on_clock, queue_size=1, tcp_nodelay=True)
            rospy.loginfo('agents on ROS time: .wait and Jason timeouts follow /clock')

    def _on_clock(self, msg):
        self._bridge.clockAdvanced(msg.clock.to_nsec())

    def _on_message(self, msg):
        if msg.sender_mas == self.mas_id or (msg.receiver_mas and msg.receiver_mas != self.mas_id):
            return  # our own, or for another process: the common case, kept out of Java
        try:
            # checked (authentication, then form) and parsed in Java
            self._bridge.deliverMessage(msg.sender_mas, msg.sender, msg.receiver_mas, msg.receiver,
                                        msg.performative, msg.content, msg.msg_id, msg.in_reply_to,
                                        to_int64(msg.incarnation), to_int64(msg.sequence), to_int64(msg.stamp),
                                        msg.key_id, msg.mac, _publisher(msg))
        except Exception as e:  # a bug must not kill the subscriber thread
            rospy.logerr('could not deliver message from %s (%s): %s', msg.sender, msg.sender_mas, e)

    def _on_presence(self, msg):
        if msg.mas_id == self.mas_id:
            return
        if msg.incarnation >= 2 ** 63:
            rospy.logwarn_throttle(10, 'ignored presence of %r: incarnation %d out of range',
                                   msg.mas_id, msg.incarnation)
            return
        try:
            self._bridge.presenceAnnounced(msg.mas_id, msg.incarnation, msg.agents, msg.df_agents, msg.df_services,
                                           msg.period, msg.leaving, to_int64(msg.sequence), to_int64(msg.stamp),
                                           msg.key_id, msg.mac, _publisher(msg))
        except Exception as e:
            rospy.logerr('could not handle presence of %r: %s', msg.mas_id, e)

    # ---- presence --------------------------------------------------------------------

    def _presence_loop(self):
        # Wall clock on purpose: presence is about processes and links, and must
        # keep working when /clock is paused or runs faster than real time.
        next_announcement = 0.0
        while not self._presence_stop.is_set() and not rospy.is_shutdown():
            now = time.monotonic()
            if now >= next_announcement:
                self._announce(leaving=False)
                next_announcement = now + self._presence_period
            try:
                self._bridge.presenceTick(self._linked_processes())
                self._bridge.decomposersTick(self._event_publishers())
            except Exception as e:
                rospy.logerr_throttle(10, 'presence tick failed: %s', e)
            self._presence_stop.wait(_PRESENCE_TICK)

    def _announce(self, leaving):
        # The lock and the check keep a periodic announcement from following the leaving one.
        with self._announce_lock:
            if self._presence_stop.is_set() and not leaving:
                return
            self._publish_presence(leaving)

    def _publish_presence(self, leaving):
        # under _announce_lock: signed in publishing order
        try:
            # dfAnnounced first: it clears the "announce at once" flag, so an agent or registration
            # changing after it queues another announcement instead of going unannounced
            df = self._bridge.dfAnnounced()
            agents = [str(n) for n in self._bridge.agentNames()]
            df_agents, df_services = [str(a) for a in df.agents()], [str(s) for s in df.services()]
            signed = self._bridge.signPresence(agents, df_agents, df_services, self._presence_period, leaving)
            self._presence_pub.publish(Presence(
                mas_id=self.mas_id, incarnation=to_uint64(signed.incarnation()), agents=agents,
                df_agents=df_agents, df_services=df_services,
                period=self._presence_period, leaving=leaving, sequence=to_uint64(signed.sequence()),
                stamp=to_uint64(signed.stamp()), key_id=str(signed.keyId()), mac=bytes(signed.mac())))
        except Exception as e:  # topic closed at shutdown
            rospy.logdebug('presence not announced: %s', e)

    def _linked_processes(self):
        """Node names our message publisher is connected to (rospy keeps them as endpoint ids)."""
        impl = self._message_pub.impl
        return [] if impl is None else [c.endpoint_id for c in list(impl.connections)]

    def _event_publishers(self):
        """Nodes whose jason/event link to us is up (a decomposer that died has none)."""
        impl = self._events_sub.impl if self._events_sub is not None else None
        return [] if impl is None else [c.header.get('callerid', '') for c in list(impl.connections)
                                        if getattr(c, 'header', None)]

    def _linked(self, mas_id):
        impl = self._message_pub.impl
        return impl is not None and impl.has_connection(mas_id)

    # ---- agents -> ROS -------------------------------------------------------------

    def _outbound_loop(self):
        # Publishes what the agents queued in Java: this thread blocks in Java
        # (JPype lets the other Python threads run), never an agent's thread.
        outbox = self._bridge.outbox()
        while True:
            item = outbox.take(_OUTBOUND_WAIT_MS)
            if item is None:
                if self._outbound_stop.is_set():
                    return
                continue
            try:
                self._dispatch(item)
            except Exception as e:  # a bug must not end the thread that publishes every action
                rospy.logerr('could not publish %s: %s', item, e)

    def _dispatch(self, item):
        if isinstance(item, self._action_item):
            self._publish_action(str(item.agent()), int(item.actionId()), str(item.action()),
                                 [str(p) for p in item.parameters()])
        elif isinstance(item, self._cancel_item):
            self._publish_cancel(str(item.agent()), int(item.actionId()), str(item.reason()))
        elif isinstance(item, self._message_item):
            self._publish_message(AgentMessage(
                sender_mas=self.mas_id, sender=str(item.sender()), receiver_mas=str(item.receiverMas()),
                receiver=str(item.receiver()), performative=str(item.performative()),
                content=str(item.content()), msg_id=str(item.msgId()), in_reply_to=str(item.inReplyTo())))
        elif isinstance(item, self._announce_item):
            self._announce(leaving=False)  # our agents or their registrations changed: others hear of it now
        elif isinstance(item, self._stop_item):
            self.exit_code = int(item.exitValue())
            # not on this thread: shutting down joins it
            threading.Thread(target=rospy.signal_shutdown, args=('an agent ran .stopMAS',)).start()

    def _publish_action(self, agent, action_id, functor, parameters):
        msg = Action(agent=agent, action_id=action_id, action=functor, parameters=parameters)
        outcome = self._outbox.submit(msg)
        if outcome == NO_DECOMPOSER:
            rospy.logwarn('[%s] %s%s failed: no node subscribes to %s', agent, functor,
                          tuple(parameters), self._action_topic)
            self._bridge.actionFailed(agent, action_id, Event.NO_DECOMPOSER)
        elif outcome == DEFERRED:
            self._outbox_wakeup.set()

    def _action_not_sent(self, action, reason):
        if action.action != Action.CANCEL:  # a cancel nobody can hear has nothing left to stop
            self._bridge.actionFailed(action.agent, action.action_id, reason)

    def _publish_cancel(self, agent, action_id, reason):
        # on jason/action, through the same outbox: it never overtakes the action it cancels
        msg = Action(agent=agent, action_id=action_id, action=Action.CANCEL, parameters=[reason])
        if self._outbox.submit(msg) == DEFERRED:
            self._outbox_wakeup.set()

    def _sign_and_publish(self, msg):
        """Fills in the authentication fields and publishes (the message outbox calls it in publishing order)."""
        signed = self._bridge.signMessage(msg.receiver_mas, msg.sender, msg.receiver, msg.performative, msg.content,
                                          msg.msg_id, msg.in_reply_to)
        msg.incarnation = to_uint64(signed.incarnation())
        msg.sequence = to_uint64(signed.sequence())
        msg.stamp = to_uint64(signed.stamp())
        msg.key_id = str(signed.keyId())
        msg.mac = bytes(signed.mac())
        self._message_pub.publish(msg)

    def _publish_message(self, msg):
        try:
            if self._messages.submit(msg, msg.receiver_mas) == HELD:
                self._outbox_wakeup.set()
        except Exception as e:  # topic closed at shutdown
            rospy.logwarn('[%s] could not send %s to %s: %s', msg.sender, msg.performative,
                          msg.receiver or 'everyone', e)

    def _registered(self, topic, publishers):
        """Nodes the master lists as publishers (or subscribers) of topic; None if unreachable."""
        try:
            pubs, subs, _ = self._master.getSystemState()
        except Exception as e:
            rospy.logwarn_throttle(10, 'cannot ask the master who uses %s: %s', topic, e)
            return None
        return sum(len(nodes) for t, nodes in (pubs if publishers else subs) if t == topic)

    def _listed_action_subscribers(self):
        listed = self._registered(self._action_topic, publishers=False)
        # master unreachable: trust the connections we have
        return self._action_pub.get_num_connections() if listed is None else listed

    def _wait_for_publishers(self, subscriber, timeout):
        deadline = time.monotonic() + timeout
        while not rospy.is_shutdown():
            listed = self._registered(subscriber.resolved_name, publishers=True)
            if listed is None or subscriber.get_num_connections() >= listed \
                    or time.monotonic() > deadline:
                return
            time.sleep(0.02)

    def _outbox_loop(self):
        # Sends actions held back while decomposers connect, and agent messages
        # held back while the link to their process comes up; also refreshes the
        # master's subscriber count once a second.
        while not rospy.is_shutdown():
            woken = self._outbox_wakeup.wait(1.0)
            self._outbox_wakeup.clear()
            if woken or self._outbox.has_held() or self._messages.held_count():
                while (self._outbox.flush() + self._flush_messages()) and not rospy.is_shutdown():
                    time.sleep(0.01)
            else:
                self._outbox.refresh_listed()

    def _flush_messages(self):
        held, unlinked = self._messages.flush()
        for m in unlinked:
            rospy.logwarn('[%s] %s to %s published although %s is still not connected after %.1f s: '
                          'it is probably lost', m.sender, m.performative, m.receiver, m.receiver_mas,
                          self._connect_wait)
        return held

    def _mind_loop(self):
        # Java's agents read their own state; this thread only switches that on while
        # jason/mind has subscribers, and publishes what changed.
        settings, publisher, switch = self._mind
        while not self._stopping and not rospy.is_shutdown():
            period = switch.update(publisher.get_num_connections())
            if period is not None:
                self._bridge.setMindPeriodNanos(period)
            if switch.on:
                minds = self._bridge.mindChanges()
                if minds is not None:
                    try:
                        publisher.publish(mind_msg(self.mas_id, _ros_now_ns(), minds,
                                                   str(self._bridge.mindInspectorUrl())))
                    except rospy.ROSException as e:  # shutting down
                        rospy.logdebug('jason/mind not published: %s', e)
            time.sleep(settings.period)

    def _log_loop(self):
        # The agents' .print and Jason's log, queued on the Java side: written here,
        # off the agents' threads, so printing never makes an agent wait for Python.
        while not self._log_stop.is_set():
            if not self._drain_log():
                self._log_stop.wait(_LOG_POLL)

    def _drain_log(self):
        """Writes the lines queued by Java's RosLogHandler; returns how many there were."""
        lines = self._log_lines.drain(_LOG_BATCH)
        for line in lines:
            self.log(int(line.level()), str(line.agent()), str(line.message()))
        dropped = int(self._log_lines.takeDropped())
        if dropped:
            rospy.logwarn('%d log lines of the agents were dropped: they came faster than rosout took them', dropped)
        return len(lines)

    def log(self, level, agent, message):
        """One log line of Java's RosLogHandler to rosout."""
        text = '[%s] %s' % (agent, message) if agent else message
        if level >= _JAVA_SEVERE:
            rospy.logerr(text)
        elif level >= _JAVA_WARNING:
            rospy.logwarn(text)
        elif level >= _JAVA_INFO:
            rospy.loginfo(text)
        else:
            rospy.logdebug(text)


def main(argv=None):
    """``rosrun rason_bridge rason_mas FILE.mas2j``.

    ~params: ``action_timeout`` (float s, 60), ``perception_ttl`` (float s, 2; 0 disables),
    ``connect_wait`` (float s, 2), ``shutdown_grace`` (float s, 0.5),
    ``agent_prefix`` (str, ''), ``messages_topic`` (str, /rason/messages),
    ``presence_topic`` (str, /rason/presence), ``presence_period`` (float s, 0.5),
    ``presence_timeout`` (float s, 2), ``presence_beliefs`` (bool, true),
    ``ask_timeout`` (float s, 60; 0 disables), ``perception_manager`` (str, per_source),
    ``decomposer_grace`` (float s, 0.5), and the input limits ``max_literal_length`` (int, 4096),
    ``max_content_length`` (int, 65536), ``max_nesting`` (int, 32), ``max_term_depth`` (int, 512),
    ``max_literals`` (int, 1000), ``max_sources`` (int, 100) (see :mod:`rason_bridge.limits`), and the
    fleet authentication's ``fleet_auth`` (required or off), ``fleet_key_file`` (str,
    $ROS_HOME/rason/fleet.key), ``fleet_key`` (str), ``auth_window`` (float s, 60; 0 disables)
    (see :mod:`rason_bridge.fleet_auth`), and the mental state's ``mind_period`` (float s, 0.5;
    0: no jason/mind), ``mind_max_items`` (int, 200), ``mind_max_chars`` (int, 500)
    (see :mod:`rason_bridge.mind`).
    Publishes the hosted agents' names on the ``~agents`` parameter.
    """
    args = rospy.myargv(argv if argv is not None else sys.argv)
    rospy.init_node('rason_mas')
    if len(args) != 2:
        rospy.logfatal('usage: rosrun rason_bridge rason_mas FILE.mas2j')
        return 2
    mas2j = args[1]
    try:
        start_jvm()
    except JvmError as e:
        rospy.logfatal(str(e))
        return 1
    node = None
    try:
        node = RasonMasNode(action_timeout=rospy.get_param('~action_timeout', 60.0),
                            perception_ttl=rospy.get_param('~perception_ttl', 2.0),
                            connect_wait=rospy.get_param('~connect_wait', 2.0),
                            messages_topic=rospy.get_param('~messages_topic', '/rason/messages'),
                            presence_topic=rospy.get_param('~presence_topic', '/rason/presence'),
                            presence_period=float(rospy.get_param('~presence_period', 0.5)),
                            presence_timeout=float(rospy.get_param('~presence_timeout', 2.0)),
                            presence_beliefs=rospy.get_param('~presence_beliefs', True),
                            ask_timeout=float(rospy.get_param('~ask_timeout', 60.0)),
                            agent_prefix=str(rospy.get_param('~agent_prefix', '')),
                            perception_manager=str(rospy.get_param('~perception_manager', 'per_source')),
                            decomposer_grace=float(rospy.get_param('~decomposer_grace', 0.5)))
        apply_input_limits(node.input_limits(), lambda name, default: rospy.get_param('~' + name, default))
        node.set_trust(rospy.get_param('~trust', {}))
        auth = auth_settings(lambda name, default: rospy.get_param('~' + name, default), rospkg.get_ros_home())
        node.configure_mind(mind_settings(lambda name, default: rospy.get_param('~' + name, default)))
    except ValueError as e:
        if node is not None:
            node.close_log()
        rospy.logfatal('bad parameter: %s', e)
        return 1
    try:
        names = node.load(mas2j)
    except RuntimeError as e:
        node.close_log()  # Jason's own errors first: the reason is among them
        rospy.logfatal('cannot run %s: %s', mas2j, e)
        return 1
    try:
        node.configure_auth(auth)  # after load: Java's log lines reach rosout from then on
    except FleetKeyError as e:
        node.close_log()
        rospy.logfatal('fleet authentication is required (~fleet_auth) but there is no usable fleet key: %s. %s',
                       e, no_key_help(auth))
        return 1
    rospy.set_param('~agents', names)
    rospy.loginfo('running %s with agents %s', os.path.basename(mas2j), ', '.join(names))
    grace = rospy.get_param('~shutdown_grace', 0.5)
    rospy.core.add_preshutdown_hook(node.shutdown_requested)
    rospy.on_shutdown(lambda: node.stop(grace=grace))
    node.start()
    rospy.spin()
    node.stop(grace=grace)
    return node.exit_code


def run():
    """Entry point of the installed script: exit without waiting for stray JVM threads."""
    code = main()
    if not rospy.core.is_shutdown() and rospy.core.is_initialized():
        # a start-up error (bad parameter, no key): leave the master's lists as a clean stop does
        rospy.signal_shutdown('exiting with status %d' % code)
    logging.shutdown()
    sys.stdout.flush()
    sys.stderr.flush()
    os._exit(code)
