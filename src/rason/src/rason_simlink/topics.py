"""The topics the sim link carries, and the checks on a peer's channel announcement.

Names without a leading slash are in the robot's namespace (e.g. /rover/odom on both
masters); the others are global.
"""
import collections

Topic = collections.namedtuple('Topic', 'name type to_robot latched on_demand ack')

CAMERA_TOPICS = ('camera/rgb/image_raw', 'camera/depth_registered/image_raw',
                 'camera/depth_registered/points', 'camera/rgb/camera_info')
ACK_TOPICS = ('robots_seen', 'odom_filtered', 'odom_commanded')


def _topics():
    def to_robot(name, type_, latched=False, on_demand=False):
        return Topic(name, type_, True, latched, on_demand, False)

    def to_world(name, type_, ack=False):
        return Topic(name, type_, False, False, False, ack)

    return (
        to_robot('odom', 'nav_msgs/Odometry'),
        to_robot('true_pose', 'geometry_msgs/PoseStamped'),
        to_robot('camera/rgb/image_raw', 'sensor_msgs/Image', on_demand=True),
        to_robot('camera/depth_registered/image_raw', 'sensor_msgs/Image', on_demand=True),
        to_robot('camera/depth_registered/points', 'sensor_msgs/PointCloud2', on_demand=True),
        to_robot('camera/rgb/camera_info', 'sensor_msgs/CameraInfo', on_demand=True),
        to_robot('/clock', 'rosgraph_msgs/Clock'),
        to_robot('/tf', 'tf2_msgs/TFMessage'),
        to_robot('/tf_static', 'tf2_msgs/TFMessage', latched=True),
        to_world('cmd_vel', 'geometry_msgs/Twist'),
        to_world('set_pose', 'geometry_msgs/Pose2D'),
        to_world('robots_seen', 'rason_msgs/RobotSightings', ack=True),
        to_world('odom_filtered', 'nav_msgs/Odometry', ack=True),
        to_world('odom_commanded', 'nav_msgs/Odometry', ack=True),
    )


TOPICS = _topics()
BY_NAME = {topic.name: topic for topic in TOPICS}


def sent_by(side):
    """The topics side ('world' or 'robot') reads on its master and sends over the link."""
    return [t for t in TOPICS if t.to_robot == (side == 'world')]


def received_by(side):
    """The topics side publishes on its master from what the link brings."""
    return [t for t in TOPICS if t.to_robot == (side == 'robot')]


def check_announcement(side, announcement, local_md5):
    """Why side must refuse a peer's channel announcement, or None to accept it.

    local_md5(type) is the md5 of that type as built here (None: not known here).
    """
    name = announcement.get('topic')
    topic = BY_NAME.get(name)
    if topic is None or topic not in received_by(side):
        return 'topic %r is not one the %s side receives' % (name, side)
    if announcement.get('type') != topic.type:
        return '%s has type %r over the link, %r expected' % (name, announcement.get('type'),
                                                               topic.type)
    mine = local_md5(topic.type)
    if mine is None:
        return '%s: type %s is not built on the %s side' % (name, topic.type, side)
    if announcement.get('md5') != mine:
        return ('%s: %s differs between the two sides (md5 %s over the link, %s here): '
                'build both from the same message definitions'
                % (name, topic.type, announcement.get('md5'), mine))
    return None


def check_sender(topic, connection_type, connection_md5, expected_md5):
    """Why a message read on the sending side must not be relayed, or None.

    The subscriber takes any type (it relays bytes), so a publisher of another type under
    the same name would otherwise reach the other master.
    """
    if connection_type != topic.type or connection_md5 != expected_md5:
        return ('%s: a publisher sends %s (md5 %s), %s (md5 %s) expected: not relayed'
                % (topic.name, connection_type, connection_md5, topic.type, expected_md5))
    return None
