"""The node adapter with rospy's publisher/subscriber replaced by fakes (no ROS master)."""
import numpy as np
import pytest
import rospy
from rason_msgs.msg import RobotSightings
from sensor_msgs.msg import CameraInfo, Image
from std_msgs.msg import Header

import vision_scene as vs
from vision_synth import cloud, detector, geometry, literals, node


class FakePublisher(object):
    def __init__(self, topic, msg_class, queue_size=None, **_):
        self.topic, self.msg_class, self.sent = topic, msg_class, []

    def publish(self, msg):
        self.sent.append(msg)


class Ros(object):
    """Records what the node publishes, subscribes and warns."""

    def __init__(self, monkeypatch):
        self.publishers, self.subscribers, self.warnings = {}, {}, []

        def publisher(topic, msg_class, **kw):
            self.publishers[topic] = FakePublisher(topic, msg_class, **kw)
            return self.publishers[topic]

        def subscriber(topic, msg_class, callback, **kw):
            self.subscribers[topic] = (callback, kw)

        monkeypatch.setattr(rospy, 'Publisher', publisher)
        monkeypatch.setattr(rospy, 'Subscriber', subscriber)
        monkeypatch.setattr(rospy, 'logwarn_throttle',
                            lambda _period, text: self.warnings.append(text))
        monkeypatch.setattr(rospy, 'logdebug_throttle', lambda period, text: None)

    def feed(self, topic, msg):
        self.subscribers[topic][0](msg)

    @property
    def sent(self):
        return self.publishers['jason/perception'].sent

    @property
    def seen(self):
        return self.publishers['robots_seen'].sent


@pytest.fixture
def ros(monkeypatch):
    return Ros(monkeypatch)


POINTS = 'camera/depth_registered/points'
IMAGE = 'camera/rgb/image_raw'


def scene_cloud(robot=(-10.0, 2.0, 30.0), stamp=1.0, with_rgb=True, frame_id='cam_optical'):
    rgb, xyz = vs.Scene(robot).render()
    msg = cloud.arrays_to_cloud(xyz, rgb if with_rgb else None, frame_id=frame_id,
                                stamp=rospy.Time.from_sec(stamp))
    return msg, rgb


def robots(msg):
    """The robot(...) literals of a perception message (without its cameraFrame(N, T))."""
    return [text for text in msg.perception if text.startswith('robot(')]


def image_msg(rgb, stamp):
    msg = Image(height=rgb.shape[0], width=rgb.shape[1], encoding='rgb8',
                step=rgb.shape[1] * 3, data=rgb.tobytes())
    msg.header.stamp = rospy.Time.from_sec(stamp)
    return msg


@pytest.mark.parametrize('name, source', [
    ('/vision_synth', 'vision_synth_robots'), ('/helper/vision_synth', 'vision_synth_robots'),
    ('/helper/eyes/', 'eyes_robots')])
def test_default_source(name, source):
    assert node.default_source(name) == source


def test_intrinsics_from_camera_info():
    info = CameraInfo(K=[589.4, 0, 319.5, 0, 589.0, 239.5, 0, 0, 1])
    k = node.intrinsics_from_info(info)
    assert (k.fx, k.fy, k.cx, k.cy) == (589.4, 589.0, 319.5, 239.5)
    assert node.intrinsics_from_info(CameraInfo()) is None  # K all zero: not calibrated


def test_subscriptions_drop_stale_clouds(ros):
    node.VisionSynthNode(detector.Detector(), 'vision_synth_robots')
    callback, kw = ros.subscribers[POINTS]
    assert kw['queue_size'] == 1 and kw['buff_size'] >= 640 * 480 * 32
    assert IMAGE not in ros.subscribers  # colours come from the cloud by default


def test_one_perception_per_cloud(ros):
    node.VisionSynthNode(detector.Detector(), 'vision_synth_robots')
    msg, _ = scene_cloud()
    ros.feed(POINTS, msg)
    ros.feed(POINTS, scene_cloud(robot=None)[0])
    assert [m.source for m in ros.sent] == ['vision_synth_robots'] * 2
    assert len(robots(ros.sent[0])) == 1
    text = robots(ros.sent[0])[0]
    angle, depth, yaw = (float(v) for v in text[len('robot(faulty,'):-1].split(','))
    assert abs(angle + 10) < 2 and abs(depth - 2) < 0.05 and abs(yaw - 20) < 10
    assert robots(ros.sent[1]) == []  # nobody in view clears the source
    assert ros.warnings == []


def test_every_message_counts_the_clouds_processed_usable_or_not(ros):
    node.VisionSynthNode(detector.Detector(), 'src')
    ros.feed(POINTS, scene_cloud(stamp=1.0)[0])
    broken = scene_cloud(stamp=1.1)[0]
    broken.height = 0
    ros.feed(POINTS, broken)
    ros.feed(POINTS, scene_cloud(robot=None, stamp=1.2)[0])
    assert [m.perception[-1] for m in ros.sent] == ['cameraFrame(1,1000)', 'cameraFrame(2,1100)',
                                                  'cameraFrame(3,1200)']
    # the same robot in the same place twice: only the counter tells the frames apart
    ros.feed(POINTS, scene_cloud(stamp=1.0)[0])
    assert robots(ros.sent[3]) == robots(ros.sent[0])
    assert ros.sent[3].perception != ros.sent[0].perception


def test_without_the_frame_counter_only_robots_are_perceived(ros):
    node.VisionSynthNode(detector.Detector(), 'src', frame_counter=False)
    ros.feed(POINTS, scene_cloud()[0])
    ros.feed(POINTS, scene_cloud(robot=None)[0])
    assert len(ros.sent[0].perception) == 1 and ros.sent[0].perception[0].startswith('robot(')
    assert ros.sent[1].perception == []


def test_robots_seen_has_the_clouds_header_and_the_perceptions_values(ros):
    node.VisionSynthNode(detector.Detector(), 'vision_synth_robots')
    ros.feed(POINTS, scene_cloud(stamp=12.25, frame_id='helper/camera_rgb_optical_frame')[0])
    ros.feed(POINTS, scene_cloud(robot=None, stamp=12.5)[0])
    assert ros.publishers['robots_seen'].msg_class is RobotSightings
    first, second = ros.seen
    assert first.header.stamp == rospy.Time.from_sec(12.25)
    assert first.header.frame_id == 'helper/camera_rgb_optical_frame'
    assert [r.name for r in first.robots] == ['faulty']
    robot = first.robots[0]
    # the same numbers as the literal, before its rounding
    assert robots(ros.sent[0]) == [literals.robot_literal(robot.name, robot.angle,
                                                             robot.depth, robot.yaw)]
    assert abs(robot.angle + 10) < 2 and abs(robot.depth - 2) < 0.05
    assert second.robots == [] and second.header.stamp == rospy.Time.from_sec(12.5)


def test_sightings_message_keeps_every_detection_unrounded():
    header = Header(stamp=rospy.Time(3, 5), frame_id='f')
    found = [detector.Detection('alpha', geometry.Pose(-1.23456, 2.34567, 170.987654, 0, 0.227),
                                None, None),
             detector.Detection('beta', geometry.Pose(20.5, 1.0, -3.0, 0, 0.227), None, None)]
    msg = node.sightings_message(header, found)
    assert msg.header is header
    assert [(r.name, r.angle, r.depth, r.yaw) for r in msg.robots] == [
        ('alpha', -1.23456, 2.34567, 170.987654), ('beta', 20.5, 1.0, -3.0)]


@pytest.mark.parametrize('break_it', [
    lambda m: setattr(m, 'data', m.data[:100]),
    lambda m: setattr(m, 'fields', m.fields[:3]),  # no rgb
    lambda m: setattr(m, 'height', 0),
])
def test_bad_cloud_publishes_an_empty_list_and_warns(ros, break_it):
    node.VisionSynthNode(detector.Detector(), 'src')
    msg, _ = scene_cloud()
    break_it(msg)
    ros.feed(POINTS, msg)
    assert [m.perception for m in ros.sent] == [['cameraFrame(1,1000)']]
    assert [m.robots for m in ros.seen] == [[]]
    assert len(ros.warnings) == 1 and 'unusable frame' in ros.warnings[0]


def test_all_nan_cloud_is_nothing_seen(ros):
    node.VisionSynthNode(detector.Detector(), 'src')
    rgb, xyz = vs.Scene((0, 2.0, 0)).render()
    ros.feed(POINTS, cloud.arrays_to_cloud(np.full_like(xyz, np.nan), rgb))
    assert [m.perception for m in ros.sent] == [['cameraFrame(1,0)']]


@pytest.mark.parametrize('secs, nsecs, ms', [(0, 0, 0), (12, 345499999, 12345),
                                               (12, 345500000, 12346), (1795516398, 999600000,
                                                                        1795516399000)])
def test_stamp_in_whole_milliseconds(secs, nsecs, ms):
    assert node.stamp_ms(rospy.Time(secs, nsecs)) == ms


def test_with_image_colours_come_from_the_image_paired_by_stamp(ros):
    node.VisionSynthNode(detector.Detector(), 'src', use_image=True, max_stamp_diff=0.05)
    msg, rgb = scene_cloud(stamp=10.0, with_rgb=False)
    ros.feed(POINTS, msg)                      # no image yet
    ros.feed(IMAGE, image_msg(rgb, 9.5))
    ros.feed(POINTS, msg)                      # image 0.5 s old
    ros.feed(IMAGE, image_msg(rgb, 10.02))
    ros.feed(POINTS, msg)                      # paired
    assert [len(robots(m)) for m in ros.sent] == [0, 0, 1]
    assert len(ros.warnings) == 2


DEPTH = 'camera/depth_registered/image_raw'
INFO = 'camera/rgb/camera_info'


def depth_msg(xyz, stamp):
    """The registered depth image (16UC1, mm) of a rendered scene."""
    z = xyz[..., 2]
    mm = np.where(np.isnan(z), 0, np.round(z * 1000)).astype('<u2')
    msg = Image(height=mm.shape[0], width=mm.shape[1], encoding='16UC1', step=mm.shape[1] * 2,
                data=mm.tobytes())
    msg.header.stamp = rospy.Time.from_sec(stamp)
    msg.header.frame_id = 'cam_optical'
    return msg


def scene_info():
    k = vs.Intrinsics()
    return CameraInfo(K=[k.fx, 0, k.cx, 0, k.fy, k.cy, 0, 0, 1])


def depth_node(ros):
    node.VisionSynthNode(detector.Detector(), 'src', depth_image=True, max_stamp_diff=0.05)
    assert POINTS not in ros.subscribers  # no cloud to receive
    ros.feed(INFO, scene_info())


def test_with_depth_images_a_robot_is_seen_as_in_the_cloud_whichever_comes_first(ros):
    depth_node(ros)
    rgb, xyz = vs.Scene((-10.0, 2.0, 30.0)).render()
    ros.feed(IMAGE, image_msg(rgb, 1.0))
    ros.feed(DEPTH, depth_msg(xyz, 1.0))        # the image came first
    ros.feed(DEPTH, depth_msg(xyz, 1.1))
    ros.feed(IMAGE, image_msg(rgb, 1.1))        # the depth image came first
    assert [m.perception[-1] for m in ros.sent] == ['cameraFrame(1,1000)', 'cameraFrame(2,1100)']
    from_cloud = detector.Detector().detect(rgb, xyz, None)[0].pose
    for sent in ros.seen:
        seen = sent.robots[0]
        assert sent.header.frame_id == 'cam_optical'
        assert abs(seen.angle - from_cloud.angle) < 0.05
        assert abs(seen.depth - from_cloud.depth) < 0.002
        assert abs(seen.yaw - from_cloud.yaw) < 0.5
    assert ros.warnings == []


def test_a_depth_image_whose_colours_never_come_is_dropped(ros):
    depth_node(ros)
    rgb, xyz = vs.Scene((-10.0, 2.0, 30.0)).render()
    ros.feed(DEPTH, depth_msg(xyz, 1.0))
    ros.feed(IMAGE, image_msg(rgb, 1.2))        # its image was dropped: 1.0 never pairs
    ros.feed(IMAGE, image_msg(rgb, 1.3))
    assert ros.sent == []
    ros.feed(DEPTH, depth_msg(xyz, 1.3))
    assert [m.perception[-1] for m in ros.sent] == ['cameraFrame(1,1300)']


def test_a_depth_image_before_any_camera_info_is_an_unusable_frame(ros):
    node.VisionSynthNode(detector.Detector(), 'src', depth_image=True)
    rgb, xyz = vs.Scene((-10.0, 2.0, 30.0)).render()
    ros.feed(IMAGE, image_msg(rgb, 1.0))
    ros.feed(DEPTH, depth_msg(xyz, 1.0))
    assert [m.perception for m in ros.sent] == [['cameraFrame(1,1000)']]
    assert len(ros.warnings) == 1 and 'camera_info' in ros.warnings[0]


def test_a_depth_image_of_another_size_or_encoding_is_an_unusable_frame(ros):
    depth_node(ros)
    rgb, xyz = vs.Scene((-10.0, 2.0, 30.0)).render()
    ros.feed(IMAGE, image_msg(rgb[:100], 1.0))
    ros.feed(DEPTH, depth_msg(xyz, 1.0))
    bad = depth_msg(xyz, 2.0)
    bad.encoding = 'rgb8'
    ros.feed(IMAGE, image_msg(rgb, 2.0))
    ros.feed(DEPTH, bad)
    assert [robots(m) for m in ros.sent] == [[], []]
    assert len(ros.warnings) == 2 and 'differ' in ros.warnings[0] and 'rgb8' in ros.warnings[1]


def test_bad_image_is_ignored_with_a_warning(ros):
    node.VisionSynthNode(detector.Detector(), 'src', use_image=True)
    ros.feed(IMAGE, Image(height=2, width=2, encoding='mono16', step=4, data=bytes(8)))
    assert len(ros.warnings) == 1 and 'mono16' in ros.warnings[0]


def test_pinhole_angle_follows_camera_info(ros):
    node.VisionSynthNode(detector.Detector(angle_method='pinhole'), 'src')
    msg, _ = scene_cloud(robot=(12.0, 2.0, 0.0))
    ros.feed(POINTS, msg)
    ros.feed('camera/rgb/camera_info',
             CameraInfo(K=[vs.FX, 0, vs.CX + 60, 0, vs.FY, vs.CY, 0, 0, 1]))
    ros.feed(POINTS, msg)
    first, second = (float(robots(m)[0].split(',')[1]) for m in ros.sent)
    assert abs(first - 12.0) < 2 and second < first - 4


def test_a_frame_during_shutdown_is_dropped_not_an_error(ros, monkeypatch):
    node.VisionSynthNode(detector.Detector(), 'src')

    def closed(msg):
        raise rospy.ROSException('publish() to a closed topic')

    monkeypatch.setattr(ros.publishers['jason/perception'], 'publish', closed)
    monkeypatch.setattr(rospy.core, 'is_shutdown_requested', lambda: True)
    ros.feed(POINTS, scene_cloud()[0])  # no exception
    monkeypatch.setattr(rospy.core, 'is_shutdown_requested', lambda: False)
    with pytest.raises(rospy.ROSException):
        ros.feed(POINTS, scene_cloud()[0])
