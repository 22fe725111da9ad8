"""robot_guide_node: where the robots this robot's camera sees are, and ``guide(Name, Seconds)``.

rospy plumbing only: poses in :mod:`robot_guide.locate` (read its docstring for the frames and
SIGNS), the turn in :mod:`robot_guide.centring`, the action in :mod:`robot_guide.guide`, the
literal in :mod:`robot_guide.perception`, parameters and frames in :mod:`robot_guide.settings`.
Run it in the seeing robot's namespace (relative names):

- subscribes ``robots_seen`` (rason_msgs/RobotSightings, vision_synth's; queue of 1);
- looks up (tf2) the camera's pose in ``~odom_frame`` at each sightings message's stamp
  (waiting up to ``~tf_timeout``); without it that frame locates nobody (throttled warning);
- publishes ``located/<name>`` (geometry_msgs/PoseStamped) for every robot of every frame:
  in the odometry frame, stamped with the cloud's stamp, on the floor (z = 0);
- publishes ``jason/perception`` (rason_msgs/Perception), source ``<node name>_located``:
  ``located(Name, X, Y, Yaw)`` for the robots of the newest frame, an empty list when it has
  none, at most ``~max_rate`` lists a second (rason_wiring's Gate: the newest list held back
  goes out once the interval is over);
- takes ``guide(Name, Seconds)`` from ``jason/action`` (rason_decomposer's Decomposer): for
  Seconds of ROS time it publishes ``cmd_vel`` (geometry_msgs/Twist, ``angular.z`` only) at
  ``~rate``, turning toward where Name was last located, as the camera sees that point from
  the newest odometry (:mod:`robot_guide.guide` says why), and ends ``OK``; fails
  ``Event.LOST`` when Name was not seen for ``~lost_after``; refused at once with
  ``Event.BAD_PARAMETERS`` for bad arguments and ``Event.BUSY`` while another guide runs;
  a cancel (``Action.CANCEL``, the agent gone, shutdown) stops it. Every end publishes one
  zero twist at once; while no guide runs nothing is published on ``cmd_vel`` (the motion
  decomposer owns the base then).
"""
import math
import sys
import threading

import rason_rospy
import rospy
import tf2_ros
from geometry_msgs.msg import PoseStamped, Twist
from rason_decomposer.node import Decomposer
from rason_msgs.msg import Event, Perception, RobotSightings
from rason_wiring.synth import Gate
from vision_synth.literals import is_atom

from robot_guide import guide, locate, settings
from robot_guide.perception import located_literal

WARN_PERIOD = 5.0      # s between repeated warnings about the same trouble
MAX_NAMES = 100        # located/<name> publishers at most (names come from the camera's config)


def turn(angular_z):
    """A geometry_msgs/Twist turning in place (REP 103: counter-clockwise positive)."""
    msg = Twist()
    msg.angular.z = angular_z
    return msg


def pose_stamped(located, frame, stamp):
    """geometry_msgs/PoseStamped of a :class:`locate.Located` on the floor of ``frame``."""
    msg = PoseStamped()
    msg.header.frame_id = frame
    msg.header.stamp = stamp
    msg.pose.position.x, msg.pose.position.y = located.x, located.y
    msg.pose.orientation.z = math.sin(located.yaw / 2.0)
    msg.pose.orientation.w = math.cos(located.yaw / 2.0)
    return msg


class RobotGuideNode(object):
    """Wires the pure modules to ROS.

    :param options: the checked ~params (:func:`settings.check`)
    :param tf_buffer: a tf2_ros.Buffer with a listener filling it
    """

    def __init__(self, options, tf_buffer):
        self._options = options
        self._tf = tf_buffer
        self._lock = threading.Lock()       # the guide run and cmd_vel
        self._run = None                    # (the Decomposer's action, GuideRun) while a guide runs
        self._camera = options['camera_frame']   # the camera's frame (the sightings' by default)
        self._gate_lock = threading.Lock()  # the perception's gate and publisher
        self._gate = Gate(options['max_rate'], only_changed=False, refresh=0.0)
        self._poses_lock = threading.Lock()
        self._poses = {}                    # name -> located/<name> publisher
        self._cmd_pub = rospy.Publisher('cmd_vel', Twist, queue_size=10)
        self._perception_pub = rospy.Publisher('jason/perception', Perception, queue_size=10)
        rospy.Subscriber('robots_seen', RobotSightings, self._on_sightings, queue_size=1)
        self._decomposer = Decomposer([guide.ACTION], self._on_start, self._on_cancel)
        self._timer = rospy.Timer(rospy.Duration(1.0 / options['rate']), self._tick)

    # ------------------------------------------------------------------ the guide action

    def _on_start(self, action):
        try:
            name, seconds = guide.parse_arguments(action.parameters)
        except guide.BadGuide as e:
            rospy.logwarn('robot_guide: %s: %s', action.agent, e)
            return self._decomposer.refuse(action, Event.BAD_PARAMETERS)
        o = self._options
        run = guide.GuideRun(name, seconds, rospy.get_time(), o['lost_after'],
                             o['centre_deadband'], o['centre_gain'], o['angular_speed'])
        with self._lock:
            running = self._run
            if running is None:
                self._run = (action, run)
        if running is not None:
            rospy.logwarn('robot_guide: %s: guide(%s) refused: guide(%s) of %s runs',
                          action.agent, ', '.join(action.parameters),
                          ', '.join(running[0].parameters), running[0].agent)
            return self._decomposer.refuse(action, Event.BUSY)
        rospy.loginfo('robot_guide: %s: keeping %s centred for %g s', action.agent, name, seconds)

    def _on_cancel(self, action, reason):
        with self._lock:
            if self._run is None or self._run[0] is not action:
                return      # finished on another thread a moment ago: nothing runs
            self._run = None
            self._publish_turn(0.0)
        rospy.loginfo('robot_guide: %s: guide(%s) stopped (%s)', action.agent,
                      ', '.join(action.parameters), reason)

    def _publish_turn(self, angular_z):
        # with self._lock held, so no command of a guide follows its final zero
        try:
            self._cmd_pub.publish(turn(angular_z))
        except rospy.ROSException as e:    # closing at shutdown
            rospy.logwarn('robot_guide: could not publish cmd_vel: %s', e)

    def _tick(self, _event=None):
        """At ~rate: a running guide's end, or its turn; the perception held by the gate."""
        now = rospy.get_time()
        camera = self._camera_now() if self._run is not None else None
        ended = None
        with self._lock:
            if self._run is not None:
                action, run = self._run
                result = run.outcome(now)
                if result is not None:
                    ended = (action, result)
                    self._run = None
                    self._publish_turn(0.0)
                else:
                    self._publish_turn(run.command(
                        now, lambda x, y: None if camera is None else locate.bearing(x, y, *camera)))
        if ended is not None:
            self._decomposer.finish(*ended)
        with self._gate_lock:
            literals = self._gate.poll(now)
            if literals is not None:
                self._publish_perception(literals)

    # ------------------------------------------------------------------ what the camera sees

    def _camera_now(self):
        """(translation, rotation) of the camera in the odometry frame from the newest
        transforms, or None (warned)."""
        if not self._camera:
            return None             # no sightings yet: nothing to aim at either
        try:
            t = self._tf.lookup_transform(self._options['odom_frame'], self._camera, rospy.Time(0))
        except tf2_ros.TransformException as e:
            rospy.logwarn_throttle(WARN_PERIOD, 'robot_guide: no pose of %s in %s now: %s'
                                   % (self._camera, self._options['odom_frame'], e))
            return None
        p, q = t.transform.translation, t.transform.rotation
        return (p.x, p.y, p.z), (q.x, q.y, q.z, q.w)

    def _on_sightings(self, msg):
        now = rospy.get_time()
        if not self._options['camera_frame']:
            self._camera = msg.header.frame_id.lstrip('/')
        located = self._locate(msg)
        with self._lock:
            if self._run is not None:
                run = self._run[1]
                angle = next((r.angle for r in msg.robots if r.name == run.name), None)
                point = next(((f.x, f.y) for f in located if f.name == run.name), None)
                run.frame(now, angle, point, msg.header.stamp.to_sec())
        frame = self._options['odom_frame']
        for found in located:
            self._pose_publisher(found.name).publish(pose_stamped(found, frame, msg.header.stamp))
        with self._gate_lock:
            literals = self._gate.offer([located_literal(f) for f in located], now)
            if literals is not None:
                self._publish_perception(literals)

    def _locate(self, msg):
        """The robots of one sightings message in the odometry frame (those that can be)."""
        robots = []
        with self._poses_lock:
            named = set(self._poses)
        for robot in msg.robots:
            if not is_atom(robot.name):
                rospy.logwarn_throttle(WARN_PERIOD, 'robot_guide: ignoring a robot named %r: '
                                       'not a Jason atom' % robot.name)
            elif robot.name not in named and len(named) >= MAX_NAMES:
                rospy.logwarn_throttle(WARN_PERIOD, 'robot_guide: ignoring %s: already %d robots '
                                       'named' % (robot.name, MAX_NAMES))
            else:
                robots.append(robot)
        if not robots:
            return []
        camera = self._camera
        try:
            t = self._tf.lookup_transform(self._options['odom_frame'], camera, msg.header.stamp,
                                          rospy.Duration(self._options['tf_timeout']))
        except tf2_ros.TransformException as e:    # lookup, connectivity, extrapolation, timeout
            rospy.logwarn_throttle(WARN_PERIOD, 'robot_guide: no pose of %s in %s at %.3f: %s'
                                   % (camera, self._options['odom_frame'],
                                      msg.header.stamp.to_sec(), e))
            return []
        p, q = t.transform.translation, t.transform.rotation
        located = []
        for robot in robots:
            try:
                located.append(locate.locate(robot.name, robot.angle, robot.depth, robot.yaw,
                                             (p.x, p.y, p.z), (q.x, q.y, q.z, q.w)))
            except locate.BadSighting as e:
                rospy.logwarn_throttle(WARN_PERIOD, 'robot_guide: ignoring a sighting: %s' % e)
        return located

    def _pose_publisher(self, name):
        with self._poses_lock:
            pub = self._poses.get(name)
            if pub is None:
                pub = self._poses[name] = rospy.Publisher('located/' + name, PoseStamped,
                                                          queue_size=10)
            return pub

    def _publish_perception(self, literals):
        self._perception_pub.publish(Perception(source=self._options['source'],
                                                perception=literals))


def main():
    """Entry point of ``robot_guide_node``: reads ~params, then spins."""
    rason_rospy.init_node('robot_guide')
    values = {key: rospy.get_param('~' + key, default)
              for key, default in settings.DEFAULTS.items()}
    try:
        options = settings.check(values, rospy.get_namespace(), rospy.get_name())
    except settings.BadSetting as e:
        rospy.logfatal('robot_guide: bad parameter: %s', e)
        rospy.signal_shutdown('bad parameter')
        sys.exit(1)
    tf_buffer = tf2_ros.Buffer()
    listener = tf2_ros.TransformListener(tf_buffer)  # noqa: F841 (fills tf_buffer while referenced)
    RobotGuideNode(options, tf_buffer)
    rospy.loginfo('robot_guide: ready: poses in %s from %s, perception source %s, guide at %g Hz '
                  'with dead band %g deg, gain %g, at most %g rad/s, lost after %g s',
                  options['odom_frame'], options['camera_frame'] or 'the sightings\' frame',
                  options['source'], options['rate'], options['centre_deadband'],
                  options['centre_gain'], options['angular_speed'], options['lost_after'])
    rospy.spin()
