"""The diagnosis of each robot as an rviz text marker above where the robot truly is.

Pure part: :func:`diagnosis_of` (the rason/diagnosis statuses of a DiagnosticArray, by
agent) and :func:`marker` (one text marker); :func:`main` is the thin node
``rosrun rason diagnosis_marker`` that rviz.launch runs: it follows ``/<agent>/true_pose``
(the simulator's ground truth, in frame ``world``) and publishes ``diagnosis_markers``.
"""
from geometry_msgs.msg import Point, Pose, Quaternion, Vector3
from std_msgs.msg import ColorRGBA
from visualization_msgs.msg import Marker, MarkerArray

STATUS_NAME = 'rason/diagnosis'
HEIGHT = 0.6  # m above the robot's base
#: Text colour by /diagnostics level: OK green, WARN amber, ERROR red.
COLOURS = {0: (0.2, 0.8, 0.2), 1: (1.0, 0.7, 0.0), 2: (0.9, 0.1, 0.1)}


def _level(status):
    return ord(status.level) if isinstance(status.level, bytes) else int(status.level)


def diagnosis_of(array):
    """{agent: (level, text)} of the rason/diagnosis statuses in a DiagnosticArray."""
    found = {}
    for s in array.status:
        if s.name != STATUS_NAME:
            continue
        values = {kv.key: kv.value for kv in s.values}
        agent = values.get('agent')
        if agent:
            found[agent] = (_level(s), values.get('component', s.message))
    return found


def marker(index, agent, level, text, pose, frame='world', stamp=None):
    """A text marker 'agent: text' HEIGHT above pose (a geometry_msgs/Pose)."""
    m = Marker(type=Marker.TEXT_VIEW_FACING, action=Marker.ADD, ns='rason_diagnosis', id=index,
               text='%s: %s' % (agent, text))
    m.header.frame_id = frame
    if stamp is not None:
        m.header.stamp = stamp
    m.pose = Pose(position=Point(pose.position.x, pose.position.y, pose.position.z + HEIGHT),
                  orientation=Quaternion(0, 0, 0, 1))
    m.scale = Vector3(0, 0, 0.2)  # a text marker's height is scale.z
    r, g, b = COLOURS.get(level, (0.6, 0.6, 0.6))
    m.color = ColorRGBA(r, g, b, 1.0)
    return m


def main():
    import rason_rospy
    import rospy
    from diagnostic_msgs.msg import DiagnosticArray
    from geometry_msgs.msg import PoseStamped

    rason_rospy.init_node('diagnosis_marker')
    pub = rospy.Publisher('diagnosis_markers', MarkerArray, queue_size=1, latch=True)
    diagnoses, poses, subs = {}, {}, {}

    def publish():
        shown = sorted(a for a in diagnoses if a in poses)
        pub.publish(MarkerArray(markers=[
            marker(i, a, diagnoses[a][0], diagnoses[a][1], poses[a].pose, poses[a].header.frame_id)
            for i, a in enumerate(shown)]))

    def on_pose(agent, msg):
        poses[agent] = msg
        publish()

    def on_diagnostics(msg):
        for agent, found in diagnosis_of(msg).items():
            diagnoses[agent] = found
            if agent not in subs:  # follow that robot's true pose from now on
                subs[agent] = rospy.Subscriber('/%s/true_pose' % agent, PoseStamped,
                                               lambda m, a=agent: on_pose(a, m), queue_size=1)
        publish()

    rospy.Subscriber('/diagnostics', DiagnosticArray, on_diagnostics, queue_size=10)
    rospy.spin()
