"""The motion_decomp node: executes the agents' motion actions (thesis §5.3, §6.3; issue 15).

rospy plumbing only; every decision is in :mod:`motion_decomp.monitor` (read its
docstring for the actions, the results and the SIGN CONVENTION: ``turn(D)`` with D > 0 turns
RIGHT/clockwise, i.e. negative ``angular.z``), :mod:`motion_decomp.goto`,
:mod:`motion_decomp.arc`, :mod:`motion_decomp.pose_source` and
:mod:`motion_decomp.commanded_odometry`.

Topics (relative names: run one node per robot, in the robot's namespace or with remapping):

- subscribes ``jason/action`` (rason_msgs/Action): ``move(Metres)``, ``turn(Degrees)``,
  ``goto(X, Y)``, ``compensate(Side, Gain)``, ``pose_source(Name)``,
  ``pose_source(guided, Topic)``; every other action is
  left to other decomposers (logged at debug level only)
- subscribes ``odom`` (nav_msgs/Odometry): the robot's pose; messages with NaN/inf are
  ignored with a throttled warning
- subscribes ``guided_pose`` (geometry_msgs/PoseStamped): the robot's pose as someone else
  sees it, used after ``pose_source(guided)`` while at most ``~guided_max_age`` old (a zero
  stamp counts as the time it arrived); NaN/inf means "no pose". After
  ``pose_source(guided, Topic)`` the guided poses are read from ``Topic`` instead (subscribed
  when the setting takes effect, until another ``pose_source``), e.g. ``/r1/located/r4``:
  the robot of a fleet that watches this one
- publishes ``cmd_vel`` (geometry_msgs/Twist) at ``~rate`` while a motion runs, and one
  zero Twist when it ends; nothing while idle
- publishes ``odom_commanded`` (nav_msgs/Odometry, frame ``~odom_commanded_frame``, child
  ``~base_frame``): the dead reckoning of the twists this node commanded, from the zero pose,
  at every control tick while a motion runs, when one is taken back, and at 1 Hz while idle
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
- ``~goto_tolerance`` (0.05 m): ``goto`` is OK this close to its point
- ``~segment_length`` (0.3 m): the longest arc while compensating
- ``~guided_linear_speed`` (0.1 m/s), ``~guided_angular_speed`` (0.3 rad/s): the speeds while
  the pose source is guided; ``~guided_max_age`` (0.5 s): an older guided pose is no pose
- ``~odom_commanded_frame`` (``odom_commanded``), ``~base_frame`` (``base_footprint``): the
  frame ids of ``odom_commanded``
- ``~agents`` (empty): when set (list, or comma-separated string), only these agents'
  actions are executed, so robots can share one ``jason/action`` topic
- ``~actions`` (all five): the actions this node takes (list, or comma-separated string), so
  that another decomposer can have one: ``robot.launch move_base:=true`` leaves ``goto`` to
  the move_base wiring of ``generic_decomposer`` (agents/patrol)

One motion (or setting) runs at a time; those arriving meanwhile wait in FIFO order.
All times are ROS time (``/use_sim_time`` works).
"""
import math
import threading

import rason_rospy
import rospy
from geometry_msgs.msg import PoseStamped, Twist
from nav_msgs.msg import Odometry
from rason_decomposer.node import Decomposer
from rason_msgs.msg import Event

from motion_decomp import monitor
from motion_decomp.commanded_odometry import CommandedOdometry
from motion_decomp.geometry import is_finite_pose, yaw_from_quaternion
from motion_decomp.pose_source import CommandedTrail, carried_forward, stamped_pose

#: The guided poses' topic unless pose_source(guided, Topic) names another.
GUIDED_POSE = 'guided_pose'

#: Seconds between two odom_commanded messages while no motion runs.
IDLE_ODOM_PERIOD = 1.0


def pose_from_odometry(msg):
    """``(x, y, yaw)`` of a nav_msgs/Odometry, or ``None`` when a field is NaN/inf.

    :param msg: nav_msgs/Odometry
    """
    return pose_from_pose(msg.pose.pose)


def pose_from_pose(msg):
    """``(x, y, yaw)`` of a geometry_msgs/Pose, or ``None`` when a field is NaN/inf.

    :param msg: geometry_msgs/Pose
    """
    p, q = msg.position, msg.orientation
    pose = (p.x, p.y, yaw_from_quaternion(q.x, q.y, q.z, q.w))
    return pose if is_finite_pose(pose) else None


def odometry_message(pose, twist, stamp, frame_id, child_frame_id):
    """A nav_msgs/Odometry of a planar pose and twist.

    :param pose: ``(x, y, yaw)``
    :param twist: ``(linear_x, angular_z)``
    :param stamp: rospy.Time
    """
    msg = Odometry()
    msg.header.stamp = stamp
    msg.header.frame_id = frame_id
    msg.child_frame_id = child_frame_id
    msg.pose.pose.position.x, msg.pose.pose.position.y = pose[0], pose[1]
    msg.pose.pose.orientation.z = math.sin(pose[2] / 2.0)
    msg.pose.pose.orientation.w = math.cos(pose[2] / 2.0)
    msg.twist.twist.linear.x, msg.twist.twist.angular.z = twist
    return msg


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


def action_filter(value):
    """The ``~actions`` parameter as a tuple of action names, in :data:`monitor.MOTION_ACTIONS`
    order.

    :param value: list of names or a comma/blank-separated string
    :raises ValueError: empty, or a name this node does not execute
    """
    names = agent_filter(value)
    unknown = names - set(monitor.MOTION_ACTIONS)
    if unknown or not names:
        raise ValueError('~actions must name some of %s, got %r'
                         % (', '.join(monitor.MOTION_ACTIONS), value))
    return tuple(a for a in monitor.MOTION_ACTIONS if a in names)


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
    :param frames: ``(frame_id, child_frame_id)`` of ``odom_commanded``
    :param actions: the action names to take, some of :data:`monitor.MOTION_ACTIONS`
    """

    def __init__(self, options, rate=20.0, agents=(), frames=('odom_commanded', 'base_footprint'),
                 actions=monitor.MOTION_ACTIONS):
        self._lock = threading.Lock()
        self._scheduler = monitor.MotionScheduler(**options)
        self._pose = None
        self._guided = None     # the latest guided StampedPose, or None
        self._guided_topic = GUIDED_POSE    # where the guided poses used now come from
        self._named_guide = None            # the Subscriber of pose_source(guided, Topic)
        self._actions = {}      # (agent, action_id) -> the Decomposer's action, queued or running
        self._commanded = CommandedOdometry()
        # how the robot moved since a guided pose's stamp: a fresh one is carried forward by it
        self._trail = CommandedTrail(span=self._scheduler.options['guided_max_age'] + 1.0)
        self._frames = frames
        self._commanded_sent = None     # ROS time of the last odom_commanded
        self._cmd_pub = rospy.Publisher('cmd_vel', Twist, queue_size=10)
        self._commanded_pub = rospy.Publisher('odom_commanded', Odometry, queue_size=10)
        rospy.Subscriber('odom', Odometry, self._on_odom, queue_size=10)
        rospy.Subscriber(GUIDED_POSE, PoseStamped, self._guided_pose_from(GUIDED_POSE), queue_size=10)
        # registered before the Decomposer's hook: the control loop stops before the
        # Decomposer stops (on_cancel) and answers every held motion with shutdown
        rospy.on_shutdown(self._on_shutdown)
        self._decomposer = Decomposer(actions, self._on_start, self._on_cancel, agents=agents)
        self._timer = rospy.Timer(rospy.Duration(1.0 / rate), self._tick)

    def _on_odom(self, msg):
        pose = pose_from_odometry(msg)
        if pose is None:
            rospy.logwarn_throttle(5.0, 'motion_decomp: ignoring odometry with NaN/inf in the pose')
            return
        with self._lock:
            self._pose = pose

    def _guided_pose_from(self, topic):
        return lambda msg: self._on_guided_pose(msg, topic)

    def _on_guided_pose(self, msg, topic):
        pose = pose_from_pose(msg.pose)
        guided = None if pose is None else stamped_pose(pose, msg.header.stamp.to_sec(), rospy.get_time())
        if guided is None:
            rospy.logwarn_throttle(5.0, 'motion_decomp: a guided pose with NaN/inf: no guided pose')
        with self._lock:
            if topic == self._guided_topic:     # not a pose from a topic no longer used
                self._guided = guided

    def _follow_guided_topic(self):
        # the topic the guided poses come from, after a pose_source setting took effect
        with self._lock:
            topic = self._scheduler.guided_topic or GUIDED_POSE
            if topic == self._guided_topic:
                return
            self._guided_topic, self._guided = topic, None
            old, self._named_guide = self._named_guide, None
        if old is not None:
            old.unregister()
        if topic != GUIDED_POSE:
            subscriber = rospy.Subscriber(topic, PoseStamped, self._guided_pose_from(topic), queue_size=10)
            with self._lock:
                self._named_guide = subscriber
        rospy.loginfo('motion_decomp: guided poses from %s', topic)

    def _send(self, command, now):
        # with the lock held: a twist on cmd_vel, and into the commanded odometry
        self._cmd_pub.publish(twist(*command))
        self._commanded.command(command[0], command[1], now)

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
                now = rospy.get_time()
                self._send(command, now)
                # reported like a tick that stops: a simulator in lockstep with this loop
                # (rason_sim ~control_ack_topic) then stops waiting for its next tick
                self._publish_commanded(now, running=True)
        if cancelled:
            rospy.loginfo('motion_decomp: %s: %s (id %d) %s (%s)', action.agent, action_text(action),
                          action.action_id, 'stopped' if command else 'taken out of the queue',
                          reason)

    def _tick(self, _event):
        with self._lock:
            now = rospy.get_time()
            self._trail.record(now, self._commanded.advance(now))
            guided = carried_forward(self._guided, self._trail, now)
            command, feedback = self._scheduler.step(self._pose, now, guided)
            action = None
            if feedback is not None:
                action = self._actions.pop((feedback.agent, feedback.action_id), None)
            if command is not None:
                self._send(command, now)
            self._publish_commanded(now, running=command is not None)
            setting = self._setting_text() if feedback is not None and command is None else None
        if setting is not None:
            self._follow_guided_topic()
        if feedback is not None:
            rospy.loginfo('motion_decomp: %s: action %d ended: %s%s', feedback.agent,
                          feedback.action_id, feedback.result, setting or '')
            if action is not None:
                self._decomposer.finish(action, feedback.result)

    def _publish_commanded(self, now, running):
        # with the lock held: at every tick of a motion, else at IDLE_ODOM_PERIOD (give or
        # take a millisecond: ticks come at multiples of the control period)
        last = self._commanded_sent
        if not (running or last is None or now < last or now - last >= IDLE_ODOM_PERIOD - 1e-3):
            return
        self._commanded_sent = now
        pose = self._commanded.advance(now)
        self._commanded_pub.publish(odometry_message(
            pose, self._commanded.twist(now), rospy.Time.from_sec(now), *self._frames))

    def _setting_text(self):
        # with the lock held
        c = self._scheduler.compensation
        topic = self._scheduler.guided_topic
        return ' (now: compensate(%s, %g), pose_source(%s%s))' % (
            c.side, c.gain, self._scheduler.pose_source, ', %s' % topic if topic else '')

    def _on_shutdown(self):
        self._timer.shutdown()


def main():
    """Entry point of ``motion_decomp_node``: reads ~params, then spins."""
    rason_rospy.init_node('motion_decomp')
    options = {key: rospy.get_param('~' + key, default) for key, default in monitor.DEFAULTS.items()}
    rate = float(rospy.get_param('~rate', 20.0))
    agents = agent_filter(rospy.get_param('~agents', []))
    frames = (str(rospy.get_param('~odom_commanded_frame', 'odom_commanded')),
              str(rospy.get_param('~base_frame', 'base_footprint')))
    if not rate > 0:
        rospy.logfatal('motion_decomp: ~rate must be positive, got %r', rate)
        raise SystemExit(2)
    try:
        actions = action_filter(rospy.get_param('~actions', list(monitor.MOTION_ACTIONS)))
        MotionDecompNode(options, rate, agents, frames, actions)
    except (TypeError, ValueError) as e:
        rospy.logfatal('motion_decomp: bad parameter: %s', e)
        raise SystemExit(2)
    rospy.loginfo('motion_decomp: ready (%s, %.0f Hz, actions: %s, agents: %s)',
                  ', '.join('%s=%g' % kv for kv in sorted(options.items())), rate,
                  ', '.join(actions), ', '.join(sorted(agents)) or 'all')
    rospy.spin()
