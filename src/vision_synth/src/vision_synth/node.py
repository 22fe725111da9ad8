"""The vision_synth node: robot perceptions from a Kinect-like camera (thesis §6.2, §6.2.1).

rospy plumbing only; detection is in :mod:`vision_synth.detector`, angle/depth/yaw in
:mod:`vision_synth.geometry` (read its docstring for the SIGNS: Angle and Yaw are degrees,
positive to the RIGHT), formatting in :mod:`vision_synth.literals`.

Topics (relative names: run one node per robot, in the robot's namespace):

- subscribes ``camera/depth_registered/points`` (sensor_msgs/PointCloud2, organized, with
  ``rgb``): one perception message per cloud processed; stale clouds are dropped
  (queue of 1), so processing never lags behind the camera
- subscribes ``camera/rgb/camera_info`` (sensor_msgs/CameraInfo): intrinsics for
  ``~angle_method: pinhole`` (until one arrives, the ``~fov`` is used)
- subscribes ``camera/rgb/image_raw`` (sensor_msgs/Image, rgb8/bgr8) only with
  ``~use_image: true``: colours then come from the latest image whose stamp is within
  ``~max_stamp_diff`` of the cloud's (the cloud may then lack ``rgb``)
- with ``~depth_image: true``, subscribes ``camera/depth_registered/image_raw``
  (sensor_msgs/Image, 16UC1 mm or 32FC1 m, registered to the colour camera) and
  ``camera/rgb/image_raw`` instead of the cloud: each depth image is paired with the image
  of the same stamp (within ``~max_stamp_diff``) and turned into points with the
  camera_info's K; a third of the cloud's bytes, and receiving a 4.9 MB cloud is most of
  what this node's CPU goes to
- publishes ``jason/perception`` (rason_msgs/Perception): ``source`` = ``<node name>_robots``
  (or ``~source``), ``perception`` = ``robot(Name,Angle,Depth,Yaw)`` literals, then
  ``cameraFrame(N, T)`` (the N-th cloud processed, taken at T ms of ROS time;
  ``~frame_counter: false`` leaves it out).
  No robot literal when no robot is seen, and also when a frame is unusable (with a
  throttled warning): a perception the node cannot back must not linger in the agent's
  beliefs
- publishes ``robots_seen`` (rason_msgs/RobotSightings), for every cloud processed, next to
  the perception: the cloud's header (stamp, optical frame) and the same robots as
  RobotSighting (name, angle, depth, yaw: the perception's values before rounding); an empty
  list whenever the perception is one. For nodes that need numbers and the frame's time
  (robot_guide locates the seen robots in the odometry frame with them)

Private parameters (defaults in ``config/vision_synth.yaml`` and :data:`detector.DEFAULTS`):

- ``~robots`` (dict): agent name -> ``{left: colour, right: colour[, back: colour]}``,
  default ``{faulty: {left: green, right: orange, back: blue}}`` (a robot without the
  third, ``back`` cylinder is found by the other two)
- ``~world`` (dict): a simulator world file (rason_sim's parameters) loaded here; when set,
  the robots table is its robots' cylinders instead of ``~robots`` (every robot with a left
  and a right one but this node's own, whose name is its namespace's last part); refused
  when two robots share two colours (:mod:`vision_synth.world_markers`)
- ``~colors`` (dict): colour -> ``{h: [lo, hi], s: [lo, hi], v: [lo, hi]}``, OpenCV HSV
  (H 0–180); see :data:`detector.DEFAULT_COLORS`
- ``~pair_min`` 0.22, ``~pair_max`` 0.25, ``~pair_nominal`` 0.227 (m): cylinder pairing
- ``~back_offset`` 0.12 (m): the third cylinder, behind the middle of the other two
- ``~min_blob_area`` 30 (px), ``~min_valid_points`` 10, ``~kernel_size`` 3 (px)
- ``~cylinder_radius`` 0.02 (m): visible surface -> axis correction
- ``~angle_method`` ``cloud`` (3-D bearing; or ``pinhole``, ``thesis``), ``~fov`` 57 (deg)
- ``~use_image`` false, ``~depth_image`` false, ``~max_stamp_diff`` 0.05 (s)
- ``~source`` (str): perception source, default ``<node name>_robots``
- ``~frame_counter`` true: add ``cameraFrame(N, T)`` to every perception message
"""
import threading
import time

import rason_rospy
import rospy
from rason_msgs.msg import Perception, RobotSighting, RobotSightings
from sensor_msgs.msg import CameraInfo, Image, PointCloud2

from vision_synth import cloud, detector, literals, world_markers

WARN_PERIOD = 5.0  # s between repeated warnings about bad input
CLOUD_BUFF = 1 << 25  # bytes: several 640x480 clouds, so a queue of 1 really drops stale ones


def default_source(node_name):
    """``<node name>_robots`` from a resolved node name (``/faulty/vision_synth`` ->
    ``vision_synth_robots``).

    :param node_name: e.g. rospy.get_name()
    """
    return node_name.rstrip('/').rsplit('/', 1)[-1] + '_robots'


def intrinsics_from_info(msg):
    """:class:`detector.Intrinsics` of a sensor_msgs/CameraInfo, or None if K is unset."""
    try:
        return detector.Intrinsics(msg.K[0], msg.K[4], msg.K[2], msg.K[5])
    except (ValueError, IndexError):
        return None


def stamp_ms(stamp):
    """A header stamp (rospy Time: secs, nsecs) in whole milliseconds, rounded."""
    return int(stamp.secs) * 1000 + (int(stamp.nsecs) + 500000) // 1000000


def sightings_message(header, found):
    """The rason_msgs/RobotSightings of one cloud: its ``header`` and a RobotSighting per
    :class:`detector.Detection` (values as computed: degrees clockwise-positive, metres).

    :param header: the cloud's std_msgs/Header (stamp and optical frame)
    :param found: list of :class:`detector.Detection`
    """
    return RobotSightings(header=header, robots=[
        RobotSighting(name=d.name, angle=d.pose.angle, depth=d.pose.depth, yaw=d.pose.yaw)
        for d in found])


class VisionSynthNode(object):
    """Wires a :class:`detector.Detector` to ROS topics.

    :param det: the detector
    :param source: perception source name
    :param use_image: colours from ``camera/rgb/image_raw`` instead of the cloud's ``rgb``
    :param max_stamp_diff: s, image/cloud pairing tolerance with ``use_image``
    :param frame_counter: add ``cameraFrame(N, T)`` to every perception message
    :param depth_image: points from ``camera/depth_registered/image_raw`` and the camera_info
        instead of the cloud, colours from ``camera/rgb/image_raw`` (paired by stamp within
        ``max_stamp_diff``): a third of the cloud's bytes to receive
    """

    def __init__(self, det, source, use_image=False, max_stamp_diff=0.05, frame_counter=True,
                 depth_image=False):
        self._detector = det
        self._frame_counter = frame_counter
        self._frames = 0  # clouds processed, usable or not
        self._source = source
        self._use_image = use_image
        self._max_stamp_diff = max_stamp_diff
        self._lock = threading.Lock()
        self._intrinsics = None
        self._image = None  # (stamp, rgb) of the latest image, with use_image or depth_image
        self._depth = None  # the depth image waiting for its colours, with depth_image
        self._depth_image = depth_image
        self._pub = rospy.Publisher('jason/perception', Perception, queue_size=1)
        self._seen_pub = rospy.Publisher('robots_seen', RobotSightings, queue_size=1)
        rospy.Subscriber('camera/rgb/camera_info', CameraInfo, self._on_info, queue_size=1)
        if use_image or depth_image:
            rospy.Subscriber('camera/rgb/image_raw', Image, self._on_image, queue_size=1,
                             buff_size=CLOUD_BUFF)
        if depth_image:
            rospy.Subscriber('camera/depth_registered/image_raw', Image, self._on_depth,
                             queue_size=1, buff_size=CLOUD_BUFF)
        else:
            rospy.Subscriber('camera/depth_registered/points', PointCloud2, self._on_cloud,
                             queue_size=1, buff_size=CLOUD_BUFF)

    def _on_info(self, msg):
        k = intrinsics_from_info(msg)
        if k is None:
            rospy.logwarn_throttle(WARN_PERIOD, 'vision_synth: camera_info without a usable K')
        with self._lock:
            self._intrinsics = k

    def _on_image(self, msg):
        try:
            rgb = cloud.image_to_rgb(msg)
        except cloud.CloudError as e:
            rospy.logwarn_throttle(WARN_PERIOD, 'vision_synth: ignoring image: %s' % e)
            return
        with self._lock:
            self._image = (msg.header.stamp, rgb)
            pair = self._take_pair()
        if pair:
            self._on_depth_pair(*pair)

    def _on_depth(self, msg):
        with self._lock:
            self._depth = msg
            pair = self._take_pair()
        if pair:
            self._on_depth_pair(*pair)

    def _take_pair(self):
        """(depth message, rgb) once the latest depth image and image have the same stamp
        (within max_stamp_diff), whichever came second; a depth image older than the latest
        image will never get its colours and is dropped. Called under the lock."""
        if self._depth is None or self._image is None:
            return None
        image_stamp, rgb = self._image
        gap = (image_stamp - self._depth.header.stamp).to_sec()
        if abs(gap) <= self._max_stamp_diff:
            depth, self._depth = self._depth, None
            return depth, rgb
        if gap > 0:
            self._depth = None
        return None

    def _on_depth_pair(self, depth, rgb):
        def frame():
            with self._lock:
                intrinsics = self._intrinsics
            if intrinsics is None:
                raise ValueError('no camera_info received yet (the depth image needs it)')
            points = cloud.DepthPoints(cloud.depth_image_to_metres(depth), intrinsics)
            if points.shape[:2] != rgb.shape[:2]:
                raise ValueError('depth image %dx%d and image %dx%d differ' % (
                    points.shape[1], points.shape[0], rgb.shape[1], rgb.shape[0]))
            return rgb, points
        self._process(depth.header, frame)

    def _frame(self, msg):
        """(rgb, xyz) of a cloud message, or raise ValueError saying why not."""
        xyz, rgb = cloud.cloud_to_arrays(msg, need_color=not self._use_image)
        if self._use_image:
            with self._lock:
                image = self._image
            if image is None:
                raise ValueError('no image received yet on camera/rgb/image_raw')
            gap = abs((image[0] - msg.header.stamp).to_sec())
            if gap > self._max_stamp_diff:
                raise ValueError('latest image is %.3f s away from the cloud' % gap)
            rgb = image[1]
        return rgb, xyz

    def _on_cloud(self, msg):
        self._process(msg.header, lambda: self._frame(msg))

    def _process(self, header, frame):
        """Detects robots in frame() -> (rgb, xyz), taken at header, and publishes them."""
        start = time.perf_counter()
        perception, found = [], []
        try:
            rgb, xyz = frame()
            with self._lock:
                intrinsics = self._intrinsics
            found = self._detector.detect(rgb, xyz, intrinsics)
            perception = [d.literal() for d in found]
        except ValueError as e:  # CloudError, FrameError, bad literal values
            rospy.logwarn_throttle(WARN_PERIOD, 'vision_synth: unusable frame: %s' % e)
            perception, found = [], []
        self._frames += 1
        if self._frame_counter:
            perception.append(literals.frame_literal(self._frames, stamp_ms(header.stamp)))
        try:
            self._pub.publish(Perception(source=self._source, perception=perception))
            self._seen_pub.publish(sightings_message(header, found))
        except rospy.ROSException:
            # rospy closes its topics while a shutdown is only requested: a frame that
            # arrives then is dropped, not an error
            if not (rospy.is_shutdown() or rospy.core.is_shutdown_requested()):
                raise
        rospy.logdebug_throttle(WARN_PERIOD, 'vision_synth: %.1f ms per frame; %s'
                                % ((time.perf_counter() - start) * 1e3, perception))


def main():
    """Entry point of ``vision_synth_node``: reads ~params, then spins."""
    rason_rospy.init_node('vision_synth')
    options = {key: rospy.get_param('~' + key, default)
               for key, default in detector.DEFAULTS.items()}
    colors = rospy.get_param('~colors', detector.DEFAULT_COLORS)
    robots = rospy.get_param('~robots', detector.DEFAULT_ROBOTS)
    world = rospy.get_param('~world', None)
    source = str(rospy.get_param('~source', '') or default_source(rospy.get_name()))
    use_image = bool(rospy.get_param('~use_image', False))
    max_stamp_diff = float(rospy.get_param('~max_stamp_diff', 0.05))
    try:
        if world is not None:
            robots = world_markers.world_robots(
                world, exclude={world_markers.robot_of_namespace(rospy.get_namespace())})
        det = detector.Detector(colors, robots, **options)
    except detector.ConfigError as e:
        rospy.logfatal('vision_synth: bad parameter: %s' % e)
        raise SystemExit(2)
    frame_counter = bool(rospy.get_param('~frame_counter', True))
    depth_image = bool(rospy.get_param('~depth_image', False))
    VisionSynthNode(det, source, use_image, max_stamp_diff, frame_counter, depth_image)
    rospy.loginfo('vision_synth: ready, source %s, robots %s, %s'
                  % (source, ', '.join('%s=%s' % (m.name, m.describe())
                                       for m in det.markers),
                     'points from camera/depth_registered/image_raw, colours from '
                     'camera/rgb/image_raw' if depth_image else 'colours from %s' % (
                         'camera/rgb/image_raw' if use_image else 'the cloud')))
    rospy.spin()
