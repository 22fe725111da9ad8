"""The rason_mas node: runs a Jason project's agents on ROS topics (thesis §5.2).

rospy plumbing only: the tables, queues and action bookkeeping live on the Java
side (jason_lib: RasonHub, RosAgArch); the decisions that are Python's are in
:mod:`rason_bridge.events` and :mod:`rason_bridge.outbox`.
"""
import logging
import os
import sys
import threading
import time

import rosgraph
import rospy
from rason_msgs.msg import Action, Event, Perception

from rason_bridge import events
from rason_bridge.jvm import JvmError, start_jvm
from rason_bridge.outbox import DEFERRED, NO_DECOMPOSER, SENT, ActionOutbox

_JAVA_SEVERE = 1000
_JAVA_WARNING = 900
_JAVA_INFO = 800


def _ros_now_ns():
    return rospy.get_rostime().to_nsec()


class RasonMasNode(object):
    """Hosts one Jason MAS in this rospy process and wires it to the jason/* topics.

    :param action_timeout: seconds (ROS time) before an action without feedback fails ``timeout``; 0 disables
    :param perception_ttl: seconds (ROS time) before a silent source's perceptions are dropped; 0 disables
    :param connect_wait: seconds an action waits for listed decomposers to connect
    """

    def __init__(self, action_timeout=60.0, perception_ttl=2.0, connect_wait=2.0):
        import jpype  # the JVM is started by main() before this point
        self._jpype = jpype
        self._hub = jpype.JClass('rason.RasonHub').get()
        self._hub.setActionTimeoutNanos(int(action_timeout * 1e9))
        self._hub.setPerceptionTtlNanos(int(perception_ttl * 1e9))
        self._mas = None
        self._warned_agents = set()
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
            fail=lambda action, reason: self._hub.actionFeedback(action.agent, action.action_id, reason),
            connect_wait=connect_wait)
        self._outbox_wakeup = threading.Event()
        self._connect_wait = connect_wait
        self._hub.setConnector(_make_connector(self))

    # ---- life cycle -----------------------------------------------------------------

    def load(self, mas2j_path):
        """Load and create the project's agents; returns their names.

        :raises RuntimeError: the project or all of its agents could not be loaded
        """
        mas_class = self._jpype.JClass('rason.RasonLocalMAS')
        self._mas = mas_class()
        try:
            self._mas.load(mas2j_path)
            self._mas.create()
        except self._jpype.JException as e:
            raise RuntimeError(str(e.getMessage()))
        names = [str(n) for n in self._hub.agentNames()]
        if not names:
            raise RuntimeError('no agent of %s could be created (see the errors above)' % mas2j_path)
        return names

    def start(self):
        """Subscribe to the jason/* topics and start the agents' reasoning."""
        self._outbox.refresh_listed()
        events_sub = rospy.Subscriber('jason/event', Event, self._on_event,
                                      queue_size=None, tcp_nodelay=True)
        rospy.Subscriber('jason/perception', Perception, self._on_perception,
                         queue_size=100, tcp_nodelay=True)
        # Feedback from a decomposer that is not connected yet would be lost:
        # let the running ones connect before the agents act.
        self._wait_for_publishers(events_sub, self._connect_wait)
        threading.Thread(target=self._outbox_loop, name='rason_outbox', daemon=True).start()
        rospy.Timer(rospy.Duration(0.05), self._on_tick)
        self._mas.start()

    def stop(self, grace=0.5, join_timeout=3.0):
        """Fail pending actions with ``shutdown``, let failure plans run for ``grace`` s, stop the agents."""
        if self._stopping:
            return
        self._stopping = True
        self._hub.shutdown('shutdown')
        time.sleep(grace)
        if self._mas is not None:
            ended = self._mas.stopAgents(int(join_timeout * 1000))
            if not ended:
                rospy.logwarn('some agents did not stop within %.1f s', join_timeout)
        self._hub.setConnector(None)

    # ---- ROS -> agents -------------------------------------------------------------

    def _on_perception(self, msg):
        self._hub.perceive(msg.source, msg.perception, _ros_now_ns())

    def _on_event(self, msg):
        if not self._hub.hosts(msg.agent):
            if msg.agent not in self._warned_agents:
                self._warned_agents.add(msg.agent)
                rospy.loginfo('ignoring events for agent %r: not hosted here (logged once)', msg.agent)
            return
        try:
            fb = events.parse_action_feedback(msg.agent, msg.event_type, msg.parameters)
        except events.BadEvent as e:
            rospy.logwarn('ignored event for %s: %s', msg.agent, e)
            return
        self._hub.actionFeedback(fb.agent, fb.action_id, fb.result)

    def _on_tick(self, _event):
        self._hub.tick(_ros_now_ns())

    # ---- agents -> ROS -------------------------------------------------------------

    def publish_action(self, agent, action_id, functor, parameters):
        """Called on an agent's thread by RosAgArch.act; returns the ROS time or -1 (no decomposer)."""
        msg = Action(agent=agent, action_id=action_id, action=functor, parameters=parameters)
        outcome = self._outbox.submit(msg)
        if outcome == NO_DECOMPOSER:
            rospy.logwarn('[%s] %s%s failed: no node subscribes to %s', agent, functor,
                          tuple(parameters), self._action_topic)
            return -1
        if outcome == DEFERRED:
            self._outbox_wakeup.set()
        return _ros_now_ns()

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
        # Sends actions held back while decomposers connect; also refreshes the
        # master's subscriber count once a second.
        while not rospy.is_shutdown():
            woken = self._outbox_wakeup.wait(1.0)
            self._outbox_wakeup.clear()
            if woken or self._outbox.has_held():
                while self._outbox.flush() and not rospy.is_shutdown():
                    time.sleep(0.01)
            else:
                self._outbox.refresh_listed()

    def log(self, level, agent, message):
        """Called by Java's RosLogHandler: one log line to rosout."""
        text = '[%s] %s' % (agent, message) if agent else message
        if level >= _JAVA_SEVERE:
            rospy.logerr(text)
        elif level >= _JAVA_WARNING:
            rospy.logwarn(text)
        elif level >= _JAVA_INFO:
            rospy.loginfo(text)
        else:
            rospy.logdebug(text)


def _make_connector(node):
    from jpype import JImplements, JOverride

    @JImplements('rason.RosConnector')
    class Connector(object):
        @JOverride
        def publishAction(self, agent, action_id, action, parameters):
            return node.publish_action(str(agent), int(action_id), str(action),
                                       [str(p) for p in parameters])

        @JOverride
        def log(self, level, agent, message):
            node.log(int(level), str(agent), str(message))

        @JOverride
        def stopRequested(self, exit_value):
            node.exit_code = int(exit_value)
            # not on the agent's thread: shutting down joins the agent threads
            threading.Thread(target=rospy.signal_shutdown, args=('an agent ran .stopMAS',)).start()

    return Connector()


def main(argv=None):
    """``rosrun rason_bridge rason_mas FILE.mas2j``.

    ~params: ``action_timeout`` (float s, 60), ``perception_ttl`` (float s, 2; 0 disables),
    ``connect_wait`` (float s, 2), ``shutdown_grace`` (float s, 0.5).
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
    node = RasonMasNode(action_timeout=rospy.get_param('~action_timeout', 60.0),
                        perception_ttl=rospy.get_param('~perception_ttl', 2.0),
                        connect_wait=rospy.get_param('~connect_wait', 2.0))
    try:
        names = node.load(mas2j)
    except RuntimeError as e:
        rospy.logfatal('cannot run %s: %s', mas2j, e)
        return 1
    rospy.set_param('~agents', names)
    rospy.loginfo('running %s with agents %s', os.path.basename(mas2j), ', '.join(names))
    grace = rospy.get_param('~shutdown_grace', 0.5)
    rospy.on_shutdown(lambda: node.stop(grace=grace))
    node.start()
    rospy.spin()
    node.stop(grace=grace)
    return node.exit_code


def run():
    """Entry point of the installed script: exit without waiting for stray JVM threads."""
    code = main()
    logging.shutdown()
    sys.stdout.flush()
    sys.stderr.flush()
    os._exit(code)
