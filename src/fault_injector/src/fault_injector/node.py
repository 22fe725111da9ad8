"""The fault_injector node (thesis §6.3): rospy plumbing around :mod:`fault_injector.faults`.

It sits between the motion decomposer and the robot base::

    decomposer --cmd_vel_in-->  fault_injector --cmd_vel_out--> base
    decomposer <--odom_out----  fault_injector <--odom_in------ base

Topics and services (relative names, so remap them in the launch file,
e.g. ``cmd_vel_in:=cmd_vel_mux cmd_vel_out:=cmd_vel odom_in:=odom
odom_out:=odom_filtered``; see ``launch/fault_injector.launch``):

``cmd_vel_in`` (geometry_msgs/Twist, subscribed)
    commands from the decomposer.
``cmd_vel_out`` (geometry_msgs/Twist, published)
    the same commands, transformed by the active actuator fault.
``odom_in`` (nav_msgs/Odometry, subscribed)
    odometry from the base.
``odom_out`` (nav_msgs/Odometry, published)
    the same odometry, or the frozen one under the ``odometry`` fault. While
    frozen, ``header.stamp`` and ``header.seq`` keep following the incoming
    messages (the sensor still "reports", with stuck values) so consumers do not
    drop the messages as stale; frame ids, pose and twist are frozen.
``inject_fault`` (rason_msgs/FaultInjector, service)
    ``left_actuator``, ``right_actuator``, ``both_actuators``, ``odometry``,
    or ``cancel`` (alias ``none``).
``active_fault`` (std_msgs/String, latched)
    the active fault, ``none`` when none.
``/diagnostics`` (diagnostic_msgs/DiagnosticArray)
    one status named after this node: OK with message ``none``, or WARN with
    the fault's name.

Both status topics are published when the fault changes and every
``~status_period`` seconds.

Parameters:

``~initial_fault`` (string, default ``none``)
    fault active from start-up, or, with ``~fault_at``, the fault injected mid-mission.
``~fault_at`` (float, default 0)
    > 0: ``~initial_fault`` is injected that many seconds (ROS time) after the mission
    starts, i.e. after the first command that moves the robot, instead of at start-up.
``~status_period`` (float, default 1.0)
    seconds between periodic status messages; 0 disables them.

A command or odometry with NaN is passed on (as the fault model says) and
logged with a throttled warning; it never stops the node.
"""
import threading

import rason_rospy
import rospy
from diagnostic_msgs.msg import DiagnosticArray, DiagnosticStatus, KeyValue
from geometry_msgs.msg import Twist, Vector3
from nav_msgs.msg import Odometry
from std_msgs.msg import Header, String
from rason_msgs.srv import FaultInjector, FaultInjectorResponse

from fault_injector import faults

_WARN_PERIOD = 5.0  # seconds between repeated warnings about bad input


def odom_numbers(msg):
    """The pose and twist numbers of an Odometry (covariances are not checked).

    :param msg: nav_msgs/Odometry
    :return: tuple of 13 floats: position, orientation, linear, angular
    """
    p, q = msg.pose.pose.position, msg.pose.pose.orientation
    v, w = msg.twist.twist.linear, msg.twist.twist.angular
    return (p.x, p.y, p.z, q.x, q.y, q.z, q.w, v.x, v.y, v.z, w.x, w.y, w.z)


def frozen_odometry(frozen, incoming):
    """The message to publish while odometry is frozen.

    Pose, twist and frame ids come from ``frozen``; the header's stamp and seq
    follow ``incoming`` (see module docstring). Sub-messages are shared with
    ``frozen``, which is never mutated.

    :param frozen: nav_msgs/Odometry received before the fault
    :param incoming: nav_msgs/Odometry just received
    :return: a new nav_msgs/Odometry
    """
    if frozen is incoming:
        return incoming
    header = Header(seq=incoming.header.seq, stamp=incoming.header.stamp,
                    frame_id=frozen.header.frame_id)
    return Odometry(header=header, child_frame_id=frozen.child_frame_id,
                    pose=frozen.pose, twist=frozen.twist)


def _publish(publisher, msg):
    """Publishes msg; a message that arrives while the node shuts down is dropped quietly
    (rospy closes its topics before is_shutdown() turns true, while a shutdown is only
    requested)."""
    try:
        publisher.publish(msg)
    except rospy.ROSException:
        if not (rospy.is_shutdown() or rospy.core.is_shutdown_requested()):
            raise


class FaultInjectorNode(object):
    """Owns the publishers, subscribers, service and timer of the node.

    :param initial_fault: fault active from start-up (see :data:`faults.VALID_REQUESTS`)
    :param status_period: seconds between periodic status messages; <= 0 disables them
    :param severity: of the actuator faults, in (0, 1] (1: the thesis's)
    :raises faults.UnknownFaultError: if ``initial_fault`` is not valid
    :raises ValueError: if ``severity`` is not in (0, 1]
    """

    def __init__(self, initial_fault=faults.NONE, status_period=1.0, fault_at=0.0, severity=1.0):
        # Callbacks of each subscriber, the service and the timer run on
        # different threads.
        self._lock = threading.Lock()
        self._mid_mission = None
        if fault_at > 0 and faults.parse_fault(initial_fault) != faults.NONE:
            self._mid_mission = faults.MidMissionFault(initial_fault, fault_at)
            initial_fault = faults.NONE
        self._state = faults.FaultState(initial_fault, severity)
        self._cmd_pub = rospy.Publisher('cmd_vel_out', Twist, queue_size=10)
        self._odom_pub = rospy.Publisher('odom_out', Odometry, queue_size=10)
        self._fault_pub = rospy.Publisher('active_fault', String, queue_size=1, latch=True)
        self._diag_pub = rospy.Publisher('/diagnostics', DiagnosticArray, queue_size=10)
        self._publish_status()
        rospy.Subscriber('cmd_vel_in', Twist, self._on_cmd_vel, queue_size=10)
        rospy.Subscriber('odom_in', Odometry, self._on_odom, queue_size=10)
        self._service = rospy.Service('inject_fault', FaultInjector, self._on_inject)
        self._timer = None
        if status_period > 0:
            self._timer = rospy.Timer(rospy.Duration(status_period),
                                      lambda _event: self._publish_status())

    @property
    def fault(self):
        """The active fault."""
        with self._lock:
            return self._state.fault

    def _on_inject(self, req):
        with self._lock:
            ok, message = self._state.request(req.fault)
        if ok:
            rospy.loginfo('fault_injector: %s', message)
            self._publish_status()
        else:
            rospy.logwarn('fault_injector: %s', message)
        return FaultInjectorResponse(return_message=message)

    def _on_cmd_vel(self, msg):
        lin = (msg.linear.x, msg.linear.y, msg.linear.z)
        ang = (msg.angular.x, msg.angular.y, msg.angular.z)
        if faults.has_nan(lin + ang):
            rospy.logwarn_throttle(_WARN_PERIOD, 'fault_injector: NaN in %s: %s'
                                   % (rospy.resolve_name('cmd_vel_in'), lin + ang))
        with self._lock:
            inject_at = None
            if self._mid_mission is not None:
                inject_at = self._mid_mission.on_command(lin, ang, rospy.get_time())
            lin, ang = self._state.twist(lin, ang)
        _publish(self._cmd_pub, Twist(linear=Vector3(*lin), angular=Vector3(*ang)))
        if inject_at is not None:
            rospy.loginfo('fault_injector: the mission started; %s at %.2f s',
                          self._mid_mission.fault, inject_at)
            rospy.Timer(rospy.Duration(self._mid_mission.delay), self._inject_mid_mission,
                        oneshot=True)

    def _inject_mid_mission(self, _event):
        with self._lock:
            now = rospy.get_time()
            fault = self._mid_mission.due(now)
            message = self._state.request(fault)[1] if fault is not None else None
            early = self._mid_mission.waiting(now)
        if early is not None:  # the timer woke before the fault's time: wait the rest
            rospy.Timer(rospy.Duration(early), self._inject_mid_mission, oneshot=True)
        if message is not None:
            rospy.loginfo('fault_injector: mid-mission: %s', message)
            self._publish_status()

    def _on_odom(self, msg):
        if faults.has_nan(odom_numbers(msg)):
            rospy.logwarn_throttle(_WARN_PERIOD, 'fault_injector: NaN in pose or twist on %s'
                                   % rospy.resolve_name('odom_in'))
        with self._lock:
            out = self._state.odom(msg)
        _publish(self._odom_pub, frozen_odometry(out, msg))

    def _publish_status(self):
        fault = self.fault
        self._fault_pub.publish(String(data=fault))
        status = DiagnosticStatus(
            level=DiagnosticStatus.OK if fault == faults.NONE else DiagnosticStatus.WARN,
            name=rospy.get_name(), message=fault, hardware_id='',
            values=[KeyValue(key='active_fault', value=fault),
                    KeyValue(key='severity', value='%g' % self._state.severity)])
        array = DiagnosticArray(status=[status])
        array.header.stamp = rospy.Time.now()
        self._diag_pub.publish(array)


def main():
    """Entry point of ``rosrun fault_injector fault_injector_node``."""
    rason_rospy.init_node('fault_injector')
    initial = rospy.get_param('~initial_fault', faults.NONE)
    period = float(rospy.get_param('~status_period', 1.0))
    fault_at = rospy.get_param('~fault_at', 0.0)
    severity = rospy.get_param('~severity', 1.0)
    try:
        FaultInjectorNode(initial_fault=initial, status_period=period, fault_at=float(fault_at),
                          severity=severity)
    except (faults.UnknownFaultError, ValueError, TypeError) as e:
        rospy.logfatal('fault_injector: ~initial_fault / ~fault_at / ~severity: %s', e)
        raise SystemExit(2)
    rospy.loginfo('fault_injector: ready, service %s', rospy.resolve_name('inject_fault'))
    rospy.spin()
