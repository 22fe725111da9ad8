"""generic_decomposer: agents' actions mapped by ``~actions`` (see :mod:`rason_wiring.config`)
to topic publications, service calls and actionlib goals.

The rospy plumbing only: jason/action and jason/event go through rason_decomposer's
Decomposer (one answer per action, cancels, lost requesters, shutdown); what a message holds
and what a reply means is decided by the checked :class:`~rason_wiring.config.Mapping`.

- topic: publish, answer ``OK``;
- service: call on a worker thread (a slow service holds up nothing else); ``OK`` or the
  reason from the response, ``service_unavailable`` when the service is not there within
  ``~server_wait``, ``service_error`` when the call raises;
- actionlib: send the goal (actionlib.ActionClient, so that goals of several agents are each
  followed to their end); feedback -> literals on jason/perception (the mapping's source,
  cleared when the goal ends); the terminal state -> the answer; a cancel of the action
  (take-back, lost agent, shutdown) -> cancel of the goal, so the server sees it.
"""
import sys
import threading

import actionlib
import rason_rospy
import rospy
from actionlib_msgs.msg import GoalStatus
from rason_decomposer.node import Decomposer
from rason_msgs.msg import Event, Perception

from rason_wiring import config, fields, layout
from rason_wiring.ros_types import Resolver

_STATUS_NAMES = {getattr(GoalStatus, n): n for n in
                 ('SUCCEEDED', 'ABORTED', 'REJECTED', 'PREEMPTED', 'RECALLED', 'LOST')}


class _Goal(object):
    """An actionlib action in flight: its mapping, and its goal handle once sent."""

    def __init__(self, mapping):
        self.mapping = mapping
        self.handle = None


class GenericDecomposer(object):

    def __init__(self, mappings, server_wait):
        self._server_wait = float(server_wait)
        self._by_signature = {(m.functor, n): m for m in mappings for n in m.arities}
        self._lock = threading.Lock()
        self._goals = {}       # HeldAction -> _Goal
        self._publishers, self._clients = {}, {}
        for m in mappings:
            if m.kind == 'topic':
                self._publishers[m] = rospy.Publisher(m.name, m.ros_class, queue_size=10)
            elif m.kind == 'actionlib':
                self._clients[m] = actionlib.ActionClient(m.name, m.ros_class)
        self._perception = rospy.Publisher('jason/perception', Perception, queue_size=100)
        functors = sorted({m.functor for m in mappings})
        self._decomposer = Decomposer(functors, self._on_start, self._on_cancel)
        rospy.loginfo('generic_decomposer: %s', '; '.join(
            '%s -> %s %s (%s)' % (m.entry, m.kind, rospy.resolve_name(m.name), m.type_name)
            for m in mappings))

    # ------------------------------------------------------------------ Decomposer handlers

    def _on_start(self, action):
        mapping = self._by_signature.get((action.name, len(action.parameters)))
        if mapping is None:
            rospy.logwarn('generic_decomposer: %s/%d is not mapped (mapped: %s)', action.name,
                          len(action.parameters), ', '.join(sorted(
                              '%s/%d' % k for k in self._by_signature if k[0] == action.name)))
            return self._decomposer.refuse(action, Event.BAD_PARAMETERS)
        try:
            msg = mapping.build(action.parameters)
        except fields.BadValue as e:
            rospy.logwarn('generic_decomposer: %s: %s', mapping.entry, e)
            return self._decomposer.refuse(action, 'bad_value("%s")' % e.path)
        if mapping.kind == 'topic':
            self._publishers[mapping].publish(msg)
            self._decomposer.finish(action, Event.OK)
        elif mapping.kind == 'service':
            threading.Thread(target=self._call, args=(action, mapping, msg), daemon=True,
                             name='call_%s' % mapping.functor).start()
        else:
            with self._lock:
                self._goals[action] = _Goal(mapping)
            threading.Thread(target=self._send_goal, args=(action, mapping, msg), daemon=True,
                             name='goal_%s' % mapping.functor).start()

    def _on_cancel(self, action, reason):
        with self._lock:
            goal = self._goals.pop(action, None)
        if goal is None:
            return     # a topic or a service call: nothing can be stopped any more
        # never while holding our lock: actionlib calls the transition callback inside cancel()
        if goal.handle is not None:
            self._cancel_goal(goal.handle)
        self._clear_feedback(goal.mapping)

    # ------------------------------------------------------------------ services

    def _call(self, action, mapping, request):
        try:
            rospy.wait_for_service(mapping.name, timeout=self._server_wait)
        except rospy.ROSException:
            rospy.logwarn('generic_decomposer: %s: service %s is not there', mapping.entry,
                          rospy.resolve_name(mapping.name))
            self._decomposer.finish(action, config.SERVICE_UNAVAILABLE)
            return
        try:
            response = rospy.ServiceProxy(mapping.name, mapping.ros_class)(request)
        except Exception as e:    # ServiceException, a broken link, the server's own failure
            rospy.logwarn('generic_decomposer: %s: the call of %s failed: %s', mapping.entry,
                          rospy.resolve_name(mapping.name), e)
            self._decomposer.finish(action, config.SERVICE_ERROR)
            return
        self._decomposer.finish(action, mapping.outcome(response))

    # ------------------------------------------------------------------ actionlib

    def _send_goal(self, action, mapping, goal_msg):
        client = self._clients[mapping]
        if not client.wait_for_server(rospy.Duration(self._server_wait)):
            rospy.logwarn('generic_decomposer: %s: action server %s is not there', mapping.entry,
                          rospy.resolve_name(mapping.name))
            with self._lock:
                self._goals.pop(action, None)
            self._decomposer.finish(action, config.SERVER_UNAVAILABLE)
            return
        handle = client.send_goal(
            goal_msg, transition_cb=lambda gh: self._on_transition(action, mapping, gh),
            feedback_cb=lambda gh, feedback: self._on_feedback(action, mapping, feedback))
        with self._lock:
            goal = self._goals.get(action)
            if goal is not None:
                goal.handle = handle     # keeps actionlib's record of the goal alive too
        if goal is None:                 # taken back while the goal was on its way
            self._cancel_goal(handle)

    def _cancel_goal(self, handle):
        try:
            handle.cancel()
        except Exception as e:    # shutting down: the server sees our link go instead
            rospy.logwarn('generic_decomposer: could not cancel a goal: %s', e)

    def _on_transition(self, action, mapping, handle):
        if handle.get_comm_state() != actionlib.CommState.DONE:
            return
        with self._lock:
            goal = self._goals.pop(action, None)
        if goal is None:
            return     # answered already (cancelled, or a repeated DONE)
        status = _STATUS_NAMES.get(handle.get_goal_status(), 'LOST')
        self._clear_feedback(mapping)
        self._decomposer.finish(action, mapping.goal_outcome(status, handle.get_result()))

    def _on_feedback(self, action, mapping, feedback):
        with self._lock:
            active = action in self._goals
        if active and mapping.has_feedback:
            try:
                literals = mapping.feedback_literals(feedback)
            except Exception as e:
                rospy.logwarn('generic_decomposer: %s: feedback not read: %s', mapping.entry, e)
                return
            if literals:
                self._perception.publish(Perception(source=mapping.feedback_source,
                                                    perception=literals))

    def _clear_feedback(self, mapping):
        if mapping.has_feedback:
            self._perception.publish(Perception(source=mapping.feedback_source, perception=[]))


def main():
    rason_rospy.init_node('generic_decomposer')
    node = rospy.get_name().split('/')[-1]
    try:
        mappings = config.parse(layout.wiring_param('actions', rospy), Resolver(),
                                default_source=lambda functor: '%s_%s' % (node, functor))
        server_wait = float(rospy.get_param('~server_wait', 1.0))
        if not 0 < server_wait < 1e6:
            raise config.ConfigError('~server_wait: a number of seconds above 0 is needed, not %r'
                                     % server_wait)
    except (config.ConfigError, ValueError, TypeError) as e:
        rospy.logfatal('generic_decomposer: bad configuration: %s', e)
        rospy.signal_shutdown('bad configuration')
        sys.exit(1)
    GenericDecomposer(mappings, server_wait)
    rospy.spin()
