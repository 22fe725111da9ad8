"""Robots' poses as the dashboard's plain records {'x', 'y', 'yaw'} (metres, radians, in the
world frame of the simulator or the robot's own odometry frame): the simulator's ground truth
(geometry_msgs/PoseStamped on /<robot>/true_pose, frame world), each robot's odometry
(nav_msgs/Odometry on /<robot>/odom, frame <robot>/odom) and where that frame sits in the
world (world -> <robot>/odom on /tf_static). No rospy: a subscriber or a bag delivers them."""
import math

TRUE_POSE_TYPE = 'geometry_msgs/PoseStamped'
ODOM_TYPE = 'nav_msgs/Odometry'
TF_TYPE = 'tf2_msgs/TFMessage'
TF_STATIC = '/tf_static'
WORLD = 'world'


def robot_of(name):
    """The robot a topic or a node's name belongs to: its first namespace ('r1' of /r1/odom
    and of /r1/rason_mas); '' for a name in the root namespace."""
    parts = name.strip('/').split('/')
    return parts[0] if len(parts) > 1 else ''


def pose_topic_kind(topic, msg_type):
    """'true' for /<robot>/true_pose, 'odom' for /<robot>/odom, 'origin' for /tf_static, else None."""
    if msg_type == TRUE_POSE_TYPE and topic.endswith('/true_pose'):
        return 'true'
    if msg_type == ODOM_TYPE and topic.endswith('/odom'):
        return 'odom'
    if msg_type == TF_TYPE and topic == TF_STATIC:
        return 'origin'
    return None


def _yaw(q):
    return math.atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z))


def _pose(p):
    return {'x': p.position.x, 'y': p.position.y, 'yaw': _yaw(p.orientation)}


def pose_records(kind, topic, msg):
    """[(robot, pose)] of a message on a topic of that kind: one for a pose or odometry, one
    per world -> <robot>/odom transform of /tf_static."""
    if kind == 'true':
        return [(robot_of(topic), _pose(msg.pose))]
    if kind == 'odom':
        return [(robot_of(topic), _pose(msg.pose.pose))]
    found = []
    for t in msg.transforms:
        if t.header.frame_id.strip('/') == WORLD and t.child_frame_id.endswith('/odom'):
            r, q = t.transform.translation, t.transform.rotation
            found.append((t.child_frame_id.strip('/').split('/')[0], {'x': r.x, 'y': r.y, 'yaw': _yaw(q)}))
    return found


def compose(a, b):
    """Pose b, given in the frame whose pose is a, in a's parent frame."""
    c, s = math.cos(a['yaw']), math.sin(a['yaw'])
    return {'x': a['x'] + c * b['x'] - s * b['y'], 'y': a['y'] + s * b['x'] + c * b['y'],
            'yaw': math.atan2(math.sin(a['yaw'] + b['yaw']), math.cos(a['yaw'] + b['yaw']))}


def inverse(a):
    c, s = math.cos(a['yaw']), math.sin(a['yaw'])
    return {'x': -(c * a['x'] + s * a['y']), 'y': -(-s * a['x'] + c * a['y']), 'yaw': -a['yaw']}


def anchor(true, odom):
    """Where the odometry frame sits in the world when odom and true are the same moment's
    poses of the robot: for a run recorded without /tf_static."""
    return compose(true, inverse(odom))
