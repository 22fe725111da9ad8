"""The motion_decomp node: executes the agents' move/turn actions (thesis §5.3, §6.3).

rospy plumbing only; every decision is in :mod:`motion_decomp.monitor` (read its
docstring for the results and the SIGN CONVENTION: ``turn(D)`` with D > 0 turns
RIGHT/clockwise, i.e. negative ``angular.z``).

Topics (relative names: run one node per robot, in the robot's namespace or with remapping):

- subscribes ``jason/action`` (rason_msgs/Action): ``move(Metres)``, ``turn(Degrees)``;
  every other action is left to other decomposers (logged at debug level only)
- subscribes ``odom`` (nav_msgs/Odometry): the robot's pose; messages with NaN/inf are
  ignored with a throttled warning
- publishes ``cmd_vel`` (geometry_msgs/Twist) at ``~rate`` while a motion runs, and one
  zero Twist when it ends; nothing while idle
- publishes ``jason/event`` (rason_msgs/Event): ``action_started [action_id]`` when a motion
  is taken (not for ``bad_parameters``), then one ``action_feedback`` per handled action,
  parameters ``[result, str(action_id)]``
- takes motions back (rason_decomposer): an ``Action.CANCEL`` (one id, or 0 = all of the
  agent) or the loss of the requesting agent's link (checked at 10 Hz) removes a queued
  motion, or stops the running one with a zero Twist at once; the answer is ``cancelled``
  and the next queued motion starts at the next control tick

Private parameters (defaults suit a TurtleBot 2 / Kobuki):

- ``~linear_speed`` (0.2 m/s), ``~angular_speed`` (0.5 rad/s): commanded speeds
- ``~rate`` (20 Hz): control and cmd_vel rate
- ``~no_progress_time`` (1.0 s): pose unchanged this long -> ``no_progress``
- ``~bad_move_min_distance`` (0.05 m), ``~bad_move_min_cos`` (0.99): ``bad_move`` check
- ``~max_duration`` (50 s, below rason_mas's 60 s ~action_timeout): any motion longer than this -> ``timeout``
- ``~agents`` (empty): when set (list, or comma-separated string), only these agents'
  actions are executed, so robots can share one ``jason/action`` topic

One motion runs at a time; motions arriving meanwhile wait in FIFO order.
All times are ROS time (``/use_sim_time`` works).
"""
import threading

import rospy
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from rason_decomposer.node import Decomposer
from rason_msgs.msg import Event

from motion_decomp import monitor


def pose_from_odometry(msg):
    """``(x, y, yaw)`` of a nav_msgs/Odometry, or ``None`` when a field is NaN/inf.

    :param msg: nav_msgs/Odometry
    """
    p = msg.pose.pose.position
    q = msg.pose.pose.orientation
    pose = (p.x, p.y, monitor.yaw_from_quaternion(q.x, q.y, q.z, q.w))
    return pose if monitor.is_finite_pose(pose) else None


def feedback_event(feedback):
    """The rason_msgs/Event reporting a :class:`monitor.Feedback`.

    :param feedback: agent, action id and result
    """
    return Event(agent=feedback.agent, event_type=Event.ACTION_FEEDBACK,
                 parameters=[feedback.result, str(feedback.action_id)])


def twist(linear_x, angular_z):
    """A geometry_msgs/Twist for a planar robot.

    :param linear_x: m/s
    :param angular_z: rad/s
    """
    msg = Twist()
    msg.linear.x = linear_x
    msg.angular.z = angular_z
    return msg


def action_text(action):
    """An action as Jason-like text for logs, e.g. ``move(1)``.

    :param action: a taken action (``name``, ``parameters``) or a rason_msgs/Action
    """
    name = getattr(action, 'name', None) or getattr(action, 'action', '?')
    return '%s(%s)' % (name, ', '.join(action.parameters))


def agent_filter(value):
    """The ``~agents`` parameter as a set of names (empty: all agents).

    :param value: list of names or a comma/blank-separated string
    """
    if isinstance(value, str):
        value = value.replace(',', ' ').split()
    return {str(v).strip() for v in value or () if str(v).strip()}


class MotionDecompNode(object):
    """Wires a :class:`monitor.MotionScheduler` to ROS topics, through a
    :class:`rason_decomposer.node.Decomposer` (jason/action, jason/event, cancels).

    :param options: motion tuning, keys of :data:`monitor.DEFAULTS`
    :param rate: control rate, Hz
    :param agents: names of the agents to serve; empty serves all
    """

    def __init__(self, options, rate=20.0, agents=()):
        self._lock = threading.Lock()
        self._scheduler = monitor.MotionScheduler(**options)
        self._pose = None
        self._actions = {}      # (agent, action_id) -> the Decomposer's action, queued or running
        self._cmd_pub = rospy.Publisher('cmd_vel', Twist, queue_size=10)
        rospy.Subscriber('odom', Odometry, self._on_odom, queue_size=10)
        # registered before the Decomposer's hook: the control loop stops before the
        # Decomposer stops (on_cancel) and answers every held motion with shutdown
        rospy.on_shutdown(self._on_shutdown)
        self._decomposer = Decomposer(monitor.MOTION_ACTIONS, self._on_start, self._on_cancel,
                                      agents=agents)
        self._timer = rospy.Timer(rospy.Duration(1.0 / rate), self._tick)

    def _on_odom(self, msg):
        pose = pose_from_odometry(msg)
        if pose is None:
            rospy.logwarn_throttle(5.0, 'motion_decomp: ignoring odometry with NaN/inf in the pose')
            return
        with self._lock:
            self._pose = pose

    def _on_start(self, action):
        with self._lock:
            feedback = self._scheduler.submit(action.agent, action.action_id, action.name,
                                              action.parameters)
            if feedback is None:
                self._actions[action.key] = action
            pending = self._scheduler.pending
        if feedback is not None:
            rospy.logwarn('motion_decomp: %s: %s (id %d) fails %s', action.agent,
                          action_text(action), action.action_id, feedback.result)
            self._decomposer.refuse(action, feedback.result)
        else:
            rospy.loginfo('motion_decomp: %s: %s (id %d) queued (%d in the queue)', action.agent,
                          action_text(action), action.action_id, pending)

    def _on_cancel(self, action, reason):
        with self._lock:
            command, cancelled = self._scheduler.cancel(action.agent, action.action_id)
            self._actions.pop(action.key, None)
            if command is not None:
                # at once, and under the lock so no command of the cancelled motion follows
                self._cmd_pub.publish(twist(*command))
        if cancelled:
            rospy.loginfo('motion_decomp: %s: %s (id %d) %s (%s)', action.agent, action_text(action),
                          action.action_id, 'stopped' if command else 'taken out of the queue',
                          reason)

    def _tick(self, _event):
        with self._lock:
            command, feedback = self._scheduler.step(self._pose, rospy.get_time())
            action = None
            if feedback is not None:
                action = self._actions.pop((feedback.agent, feedback.action_id), None)
            if command is not None:
                self._cmd_pub.publish(twist(*command))
        if feedback is not None:
            rospy.loginfo('motion_decomp: %s: action %d ended: %s',
                          feedback.agent, feedback.action_id, feedback.result)
            if action is not None:
                self._decomposer.finish(action, feedback.result)

    def _on_shutdown(self):
        self._timer.shutdown()


def main():
    """Entry point of ``motion_decomp_node``: reads ~params, then spins."""
    rospy.init_node('motion_decomp')
    options = {key: rospy.get_param('~' + key, default) for key, default in monitor.DEFAULTS.items()}
    rate = float(rospy.get_param('~rate', 20.0))
    agents = agent_filter(rospy.get_param('~agents', []))
    if not rate > 0:
        rospy.logfatal('motion_decomp: ~rate must be positive, got %r', rate)
        raise SystemExit(2)
    try:
        MotionDecompNode(options, rate, agents)
    except ValueError as e:
        rospy.logfatal('motion_decomp: bad parameter: %s', e)
        raise SystemExit(2)
    rospy.loginfo('motion_decomp: ready (%s, %.0f Hz, agents: %s)',
                  ', '.join('%s=%g' % kv for kv in sorted(options.items())), rate,
                  ', '.join(sorted(agents)) or 'all')
    rospy.spin()
