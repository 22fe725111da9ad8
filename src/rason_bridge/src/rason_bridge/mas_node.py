"""The rason_mas node: runs a Jason project's agents on ROS topics (thesis §5.2),
and lets them talk to the agents of other rason_mas processes (thesis §5.6).

rospy plumbing only. The tables live on the Java side (jason_lib, the ports of ``rason.bridge.Bridge``);
the ~params are in :mod:`rason_bridge.params` and reach Java through :mod:`rason_bridge.java_config`;
the node's threads are the parts :mod:`~rason_bridge.perception_pump`,
:mod:`~rason_bridge.outbound_pump`, :mod:`~rason_bridge.held_flusher`,
:mod:`~rason_bridge.presence_loop`, :mod:`~rason_bridge.mind_publisher` and
:mod:`~rason_bridge.log_pump` (with :mod:`~rason_bridge.rosout_writer`).
"""
import logging
import os
import sys
import threading
import time

import jpype
import rospkg
import rason_rospy
import rospy
from rospy.impl.rosout import RosOutHandler
from rason_msgs.msg import Action, Event, MindState

from rason_bridge import java_config, jvm, ros_links
from rason_bridge.action_sender import DEFERRED, NO_DECOMPOSER, ActionSender
from rason_bridge.coalesce import PerceptionCoalescer
from rason_bridge.exits import exit_for_shutdown
from rason_bridge.fleet_key import make_new_key
from rason_bridge.fleet_auth import OFF, default_key_file, first_run_key, no_key_help
from rason_bridge.held_flusher import HeldFlusher
from rason_bridge.inbound import Inbound
from rason_bridge.jvm import JvmError, jason_lib_classpath, start_jvm
from rason_bridge.log_pump import LogPump
from rason_bridge.mind_publisher import MindPublisher
from rason_bridge.outbound_pump import OutboundItems, OutboundPump
from rason_bridge.params import MQTT, ParamError, read_settings
from rason_bridge.perception_pump import PerceptionPump
from rason_bridge.presence_loop import PresenceLoop
from rason_bridge.project_classpath import project_classpath
from rason_bridge.ros_log import rosout_writer
from rason_bridge.ros_fleet import RosFleet
from rason_bridge.source_watch import SourceWatch
from rason_bridge.start_barrier import StartBarrier, hold

def _ros_now_ns():
    return rospy.get_rostime().to_nsec()


def _alive():
    return not rospy.is_shutdown()


class RasonMasNode(object):
    """Hosts one Jason MAS in this rospy process and wires it to the jason/* topics
    and to the other rason_mas processes.

    :param settings: :data:`rason_bridge.params.Settings`
    :raises ParamError: a value Java refuses (the message says why)
    """

    def __init__(self, settings):
        #: the checked ~params (rason_bridge.params.Settings)
        self.settings = s = settings
        self.mas_id = rospy.get_name()  # unique on a master, so it is the MAS id
        self._bridge = java_config.bridge()
        self._channel = self._bridge.rosChannel()  # the fleet over /rason/messages and /rason/presence
        java_config.push(self._bridge, s, self.mas_id, time.time_ns())
        self._mas = None
        self._stopping = False
        self._start_released = threading.Event()  # set at stop: a held start ends at once
        #: exit status of the process (set by .stopMAS(Deadline, StopJVM, Code))
        self.exit_code = 0
        self._action_topic = rospy.resolve_name('jason/action')
        self._action_pub = rospy.Publisher('jason/action', Action, queue_size=1000, tcp_nodelay=True)
        self._graph = ros_links.Graph(rospy.get_name())
        self._actions = ActionSender(
            publish=self._action_pub.publish, connected=self._action_pub.get_num_connections,
            listed=lambda: self._graph.listed_subscribers(self._action_topic, self._action_pub),
            fail=self._action_not_sent, connect_wait=s.connect_wait)
        # with fleet_channel mqtt, Java's MQTT channel carries messages and presence: no fleet topics here
        self._fleet = None if s.fleet_channel == MQTT else RosFleet(
            self._channel, self._bridge.agentNames, s, self.mas_id, lambda: self._held.wake())
        self._held = HeldFlusher(self._actions, self._fleet and self._fleet.messages,
                                 self._fleet and self._fleet.warn_unlinked, alive=_alive)
        self._presence = PresenceLoop(self._publish_presence, self._presence_tick, s.presence_period,
                                      error=lambda *a: rospy.logerr_throttle(10, *a), alive=_alive)
        items = OutboundItems(jpype.JClass)
        self._outbound = OutboundPump(self._bridge.outbox().take, lambda item: items.dispatch(item, self), rospy.logerr)
        self._perceptions = PerceptionPump(
            PerceptionCoalescer(s.max_sources, java_config.max_source_length()),
            self._bridge.perception().perceiveSerialized, self._bridge.releaseMemory, rospy.logwarn, rospy.logerr,
            alive=self._running, watch=SourceWatch(s.expected_sources, s.expect_within))
        self._inbound = Inbound(self._bridge, self._channel, self.mas_id, self._perceptions, _ros_now_ns, s)
        self._mind = None
        if s.mind_period > 0:
            publisher = rospy.Publisher('jason/mind', MindState, queue_size=2, latch=True)
            self._mind = MindPublisher(self._bridge.mind(), publisher, self.mas_id, s.mind_period, _ros_now_ns,
                                       rospy.ROSException, rospy.logdebug, alive=self._running)
        self._log = LogPump(self._bridge.log(), rosout_writer().write)
        self._bridge.attach()  # the agents' outbox and log are ours from now on
        self._log.start()

    def _running(self):
        return not self._stopping and _alive()

    # ---- life cycle -----------------------------------------------------------------

    def load(self, mas2j_path):
        """Load and create the project's agents; returns their names.

        :raises RuntimeError: the project or all of its agents could not be loaded
        """
        self._mas = java_config.load_mas(self._bridge, self.settings, mas2j_path)
        names = [str(n) for n in self._bridge.agentNames()]
        if not names:
            raise RuntimeError('no agent of %s could be created (see the errors above)' % mas2j_path)
        return names

    def configure_auth(self):
        """Sign and check with the fleet key, or not at all, and take the fleet channel (after
        :meth:`load`, before :meth:`start`).

        :raises java_config.FleetKeyError: authentication is required and the key cannot be loaded
        :raises ParamError: MQTT settings Java refuses
        """
        if self.settings.fleet_auth != OFF and self.settings.fleet_key is not None:
            rospy.logwarn('the fleet key comes from ~fleet_key: anyone who reaches the ROS master can read the '
                          'parameter server, and with it command these agents; prefer ~fleet_key_file')
        made = first_run_key(self.settings, default_key_file(rospkg.get_ros_home()), make_new_key)
        if made:
            rospy.loginfo(made)
        java_config.push_auth(self._bridge, self.settings)
        java_config.use_channel(self._bridge, self.settings)

    def start(self):
        """Subscribe to the jason/* topics and start the agents' reasoning."""
        self._actions.refresh_listed()
        self._perceptions.start()
        if self._fleet:
            self._fleet.repair_links(self._inbound.subscribe_fleet(self.settings, self._fleet.peer_heard))
        self._inbound.subscribe()
        # feedback from a decomposer not connected yet would be lost: let the running ones connect first
        self._graph.wait_for_publishers(self._inbound.events, self.settings.connect_wait)
        for part in (self._outbound, self._held, self._presence) + ((self._mind,) if self._mind else ()):
            part.start()
        self._inbound.follow_clock(jpype.JException)
        self._bridge.tick(_ros_now_ns())  # the agents' clock is known before their first action
        rospy.Timer(rospy.Duration(0.05), lambda _: self._bridge.tick(_ros_now_ns()))
        # whatever an earlier run of this node left running stops, before the agents' first action
        for agent in self._bridge.agentNames():
            self.publish_cancel(str(agent), 0, Event.RESTART)
        s, fleet = self.settings, self._bridge.fleet()  # the start barrier: presence flows, the agents wait
        hold(StartBarrier(s.await_agents, s.await_robots, s.await_timeout),
             lambda: (set(map(str, fleet.names().allNames())), int(fleet.fleet().reachableProcesses())),
             rospy.loginfo, rospy.logwarn, self._start_released.wait, self._running)
        if not self._stopping:  # a shutdown may have ended the barrier's wait
            self._mas.start()

    def close_log(self):
        """Write what Java still has queued and log to stderr from now on (before the node exits)."""
        self._log.close(self._bridge.detach)

    def stop(self, join_timeout=3.0):
        """Fail pending actions with ``shutdown``, let failure plans run for ``shutdown_grace`` s, stop the agents."""
        if self._stopping:
            return
        self._stopping = True
        self._start_released.set()
        self._presence.leave()  # first, so the other processes stop counting on our agents at once
        if not self._fleet:
            self._bridge.leaveFleet(1000)
        self._perceptions.stop()
        self._bridge.shutdown('shutdown')
        time.sleep(self.settings.shutdown_grace)
        if self._mind is not None:  # the state the agents end in, .stopMAS's included
            self._mind.finish()
        if self._mas is not None and not self._mas.stopAgents(int(join_timeout * 1000)):
            rospy.logwarn('some agents did not stop within %.1f s', join_timeout)
        self._outbound.stop(join_timeout)  # what the agents queued before they stopped still goes out
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

    # ---- presence -------------------------------------------------------------------

    def _presence_tick(self):
        if self._fleet:  # the MQTT channel checks silences itself
            self._fleet.presence_tick()
        self._bridge.actions().decomposersTick(ros_links.event_publishers(self._inbound.events))

    def _publish_presence(self, leaving):
        if self._fleet:  # the MQTT channel announces itself
            self._fleet.publish_presence(leaving)

    # ---- agents -> ROS: the receiver of OutboundItems ---------------------------------

    def publish_action(self, agent, action_id, functor, parameters):
        msg = Action(agent=agent, action_id=action_id, action=functor, parameters=parameters)
        outcome = self._actions.submit(msg)
        if outcome == NO_DECOMPOSER:
            rospy.logwarn('[%s] %s%s failed: no node subscribes to %s', agent, functor,
                          tuple(parameters), self._action_topic)
            self._bridge.actions().fail(agent, action_id, Event.NO_DECOMPOSER)
        elif outcome == DEFERRED:
            self._held.wake()

    def publish_cancel(self, agent, action_id, reason):
        # on jason/action, through the same sender: it never overtakes the action it cancels
        msg = Action(agent=agent, action_id=action_id, action=Action.CANCEL, parameters=[reason])
        if self._actions.submit(msg) == DEFERRED:
            self._held.wake()

    def publish_message(self, *fields):
        if self._fleet:  # over MQTT, Java's channel takes the agents' messages itself
            self._fleet.publish_message(*fields)

    def announce(self):
        self._presence.announce()  # our agents or their registrations changed: others hear of it now

    def stop_requested(self, exit_value):
        self.exit_code = exit_value
        # not on this thread: shutting down joins it
        threading.Thread(target=rospy.signal_shutdown, args=('an agent ran .stopMAS',)).start()

    def _action_not_sent(self, action, reason):
        if action.action != Action.CANCEL:  # a cancel nobody can hear has nothing left to stop
            self._bridge.actions().fail(action.agent, action.action_id, reason)


def main(argv=None):
    """``rosrun rason_bridge rason_mas FILE.mas2j``; its ~params: ``src/rason_bridge/PARAMETERS.md``.
    Publishes the hosted agents' names on the ``~agents`` parameter."""
    args = rospy.myargv(argv if argv is not None else sys.argv)
    rason_rospy.init_node('rason_mas')
    if len(args) != 2:
        rospy.logfatal('usage: rosrun rason_bridge rason_mas FILE.mas2j')
        return 2
    mas2j = args[1]
    try:
        settings = read_settings(lambda name, default: rospy.get_param('~' + name, default), rospkg.get_ros_home())
        classes = project_classpath(mas2j, settings.classpath)
        start_jvm(jason_lib_classpath() + classes)  # with the project's classes: Jason loads them from its class path
        rospy.loginfo(jvm.cds_decision)
        node = RasonMasNode(settings)
    except ParamError as e:
        rospy.logfatal('bad parameter: %s', e)
        return 1
    except JvmError as e:
        rospy.logfatal(str(e))
        return 1
    if classes:
        rospy.loginfo('the project\'s own classes: %s', os.pathsep.join(classes))
    try:
        names = node.load(mas2j)
    except RuntimeError as e:
        node.close_log()  # Jason's own errors first: the reason is among them
        rospy.logfatal('cannot run %s: %s', mas2j, e)
        return 1
    try:
        node.configure_auth()  # after load: Java's log lines reach rosout from then on
    except ParamError as e:
        node.close_log()
        rospy.logfatal('bad parameter: %s', e)
        return 1
    except java_config.FleetKeyError as e:
        node.close_log()
        rospy.logfatal('fleet authentication is required (~fleet_auth) but there is no usable fleet key: %s. %s',
                       e, no_key_help(node.settings))
        return 1
    rospy.set_param('~agents', names)
    rospy.loginfo('running %s with agents %s', os.path.basename(mas2j), ', '.join(names))
    rospy.core.add_preshutdown_hook(node.shutdown_requested)
    rospy.on_shutdown(node.stop)
    node.start()
    rospy.spin()
    node.stop()
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
