"""move_base_server: a ``move_base_msgs/MoveBaseAction`` server (action ``move_base``) that
drives the robot to a goal pose in its odometry frame, so agents and wiring written for a
ROS navigation stack run on the simulated robots unchanged. Every decision is in
:mod:`motion_decomp.goto`; this is the rospy plumbing.

- subscribes ``odom`` (nav_msgs/Odometry), publishes ``cmd_vel`` (geometry_msgs/Twist) at
  ``~rate`` while a goal runs, a zero Twist when it ends, nothing while idle (other nodes,
  motion_decomp, may drive then);
- a goal is rejected when its frame is not the odometry frame (``''``, ``odom`` or the
  frame_id of the odom messages, e.g. ``faulty/odom``), a value is not finite or its
  orientation is not a unit quaternion about z; a zero quaternion means "any heading";
- feedback ``base_position`` (the odometry pose) at ``~feedback_rate``;
- succeeded within ``~xy_tolerance`` (and ``~yaw_tolerance``); aborted with the text
  ``no_progress`` or ``timeout`` (see goto); preempted by a cancel or a newer goal, and then
  the zero Twist goes out at once, inside the cancel.

Parameters: ``~rate`` (50 Hz, the simulator's odometry rate), ``~feedback_rate`` (5 Hz) and
goto's ``~linear_speed`` 0.2, ``~angular_speed`` 0.5, ``~xy_tolerance`` 0.05,
``~yaw_tolerance`` 0.05, ``~no_progress_time`` 2.0, ``~max_duration`` 50. Times are ROS time.
"""
import actionlib
import rason_rospy
import rospy
from geometry_msgs.msg import PoseStamped, Twist
from move_base_msgs.msg import MoveBaseAction, MoveBaseFeedback
from nav_msgs.msg import Odometry

from motion_decomp import goto
from motion_decomp.node import pose_from_odometry, twist


class MoveBaseServer(object):

    def __init__(self, options, rate, feedback_rate):
        self._options = options
        self._feedback_period = 1.0 / feedback_rate
        self._odom = None            # the last odometry message with a finite pose
        self._current = None         # (goal handle, GotoController) of the running goal
        self._last_feedback = None
        self._cmd = rospy.Publisher('cmd_vel', Twist, queue_size=10)
        rospy.Subscriber('odom', Odometry, self._on_odom, queue_size=10)
        self._server = actionlib.ActionServer('move_base', MoveBaseAction, self._on_goal,
                                              self._on_cancel, auto_start=False)
        # One lock for everything: the action server's own RLock, which it holds around our
        # goal and cancel callbacks, so the control tick and a cancel never interleave.
        self._lock = self._server.lock
        rospy.on_shutdown(self._on_shutdown)
        self._server.start()
        self._timer = rospy.Timer(rospy.Duration(1.0 / rate), self._tick)

    def _on_odom(self, msg):
        if pose_from_odometry(msg) is None:
            rospy.logwarn_throttle(5.0, 'move_base_server: ignoring odometry with NaN/inf in the pose')
            return
        self._odom = msg

    def _frame_ok(self, frame):
        odom = self._odom
        accepted = {'', 'odom'} | ({odom.header.frame_id.lstrip('/')} if odom else set())
        return frame.lstrip('/') in accepted

    # ------------------------------------------------------------------ actionlib callbacks

    def _on_goal(self, handle):
        target = handle.get_goal().target_pose
        p, q = target.pose.position, target.pose.orientation
        try:
            if not self._frame_ok(target.header.frame_id):
                raise ValueError('frame %r is not the odometry frame' % target.header.frame_id)
            goal = goto.goal_from_pose(p.x, p.y, q.x, q.y, q.z, q.w)
        except ValueError as e:
            rospy.logwarn('move_base_server: goal rejected: %s', e)
            handle.set_rejected(text=str(e))
            return
        with self._lock:
            if self._current is not None:
                self._current[0].set_canceled(text='preempted by a newer goal')
            handle.set_accepted()
            self._current = (handle, goto.GotoController(goal, rospy.get_time(), **self._options))
            self._last_feedback = None
        rospy.loginfo('move_base_server: goal (%.3f, %.3f%s) accepted', goal.x, goal.y,
                      '' if goal.yaw is None else ', %.3f rad' % goal.yaw)

    def _on_cancel(self, handle):
        with self._lock:
            if self._current is None or self._current[0] != handle:
                return
            self._cmd.publish(twist(0.0, 0.0))       # at once, not at the next tick
            self._current = None
            handle.set_canceled(text='cancelled')
        rospy.loginfo('move_base_server: goal cancelled, the robot stopped')

    # ------------------------------------------------------------------ control

    def _tick(self, _event):
        with self._lock:
            if self._current is None:
                return
            handle, controller = self._current
            odom = self._odom
            now = rospy.get_time()
            result = controller.update(pose_from_odometry(odom) if odom else None, now)
            self._cmd.publish(twist(*controller.command()))
            if result is None:
                if odom is not None and (self._last_feedback is None or now < self._last_feedback
                                         or now - self._last_feedback >= self._feedback_period):
                    self._last_feedback = now
                    handle.publish_feedback(MoveBaseFeedback(
                        base_position=PoseStamped(header=odom.header, pose=odom.pose.pose)))
                return
            self._current = None
            if result == goto.SUCCEEDED:
                handle.set_succeeded(text=result)
            else:
                handle.set_aborted(text=result)
        rospy.loginfo('move_base_server: goal ended: %s (%.3f m from it)', result,
                      controller.distance if controller.distance is not None else float('nan'))

    def _on_shutdown(self):
        self._timer.shutdown()
        with self._lock:
            if self._current is not None:
                self._cmd.publish(twist(0.0, 0.0))
                self._current[0].set_aborted(text='shutdown')
                self._current = None


def main():
    """Entry point of ``move_base_server``: reads ~params, then spins."""
    rason_rospy.init_node('move_base_server')
    options = {key: rospy.get_param('~' + key, default) for key, default in goto.DEFAULTS.items()}
    try:
        rate = float(rospy.get_param('~rate', 50.0))
        feedback_rate = float(rospy.get_param('~feedback_rate', 5.0))
        if not (0 < rate < 1e4 and 0 < feedback_rate < 1e4):
            raise ValueError('~rate and ~feedback_rate must be positive numbers of Hz')
        options = goto.check_options(options)
    except (TypeError, ValueError) as e:
        rospy.logfatal('move_base_server: bad parameter: %s', e)
        raise SystemExit(2)
    MoveBaseServer(options, rate, feedback_rate)
    rospy.loginfo('move_base_server: ready (%s)', ', '.join('%s=%g' % kv for kv in sorted(options.items())))
    rospy.spin()
