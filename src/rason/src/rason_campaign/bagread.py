"""Read a run's bag into the events ``steps.extract_steps`` and ``mission.judge_mission``
take (needs rosbag, no master)."""
import math
import os

from diagnosis_reporter.report import MISSION_STATUS_NAME, STATUS_NAME

ACTION_TOPIC = '/%s/jason/action'
TRUE_POSE_TOPIC = '/%s/true_pose'
MESSAGES_TOPIC = '/rason/messages'
DIAGNOSTICS_TOPIC = '/diagnostics'
CLOCK_TOPIC = '/clock'
ROBOTS = ('faulty', 'helper')
STATUS_KINDS = {STATUS_NAME: 'diagnosis', MISSION_STATUS_NAME: 'mission'}


class BagError(IOError):
    """The bag cannot be read; the message says why."""


def planar(pose):
    """(x, y, yaw) of a geometry_msgs/Pose."""
    p, q = pose.position, pose.orientation
    return p.x, p.y, math.atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z))


def read_events(path, poses=False, robots=ROBOTS):
    """Events of the bag at ``path``, times in simulated seconds (via /clock): actions,
    messages, the ``rason/diagnosis`` ('diagnosis') and ``rason/mission`` ('mission')
    statuses and, with ``poses``, the simulator's true poses ('pose': robot, x, y, yaw), of
    ``robots`` (the pair's by default).

    :rtype: list of (t, kind, fields)
    :raises BagError: when the bag is missing or unreadable.
    """
    import rosbag  # only here: the rest of the package has no ROS
    from rason_campaign.steps import clock_mapper
    if not os.path.exists(path):
        raise BagError('no bag %s' % path)
    action_topics = {ACTION_TOPIC % r: r for r in robots}
    pose_topics = {TRUE_POSE_TOPIC % r: r for r in robots} if poses else {}
    topics = list(action_topics) + list(pose_topics) + [MESSAGES_TOPIC, DIAGNOSTICS_TOPIC,
                                                        CLOCK_TOPIC]
    clock, raw = [], []
    try:
        with rosbag.Bag(path) as bag:
            for topic, msg, t in bag.read_messages(topics=topics):
                t = t.to_sec()
                if topic == CLOCK_TOPIC:
                    clock.append((t, msg.clock.to_sec()))
                elif topic in action_topics:
                    raw.append((t, 'action', {'robot': action_topics[topic], 'agent': msg.agent,
                                              'action': msg.action,
                                              'parameters': list(msg.parameters)}))
                elif topic in pose_topics:
                    x, y, yaw = planar(msg.pose)
                    raw.append((t, 'pose', {'robot': pose_topics[topic], 'x': x, 'y': y,
                                            'yaw': yaw}))
                elif topic == MESSAGES_TOPIC:
                    raw.append((t, 'message', {'sender': msg.sender, 'receiver': msg.receiver,
                                               'performative': msg.performative,
                                               'content': msg.content}))
                else:
                    for status in msg.status:
                        kind = STATUS_KINDS.get(status.name)
                        if kind:
                            fields = {kv.key: kv.value for kv in status.values}
                            raw.append((t, kind, fields))
    except (rosbag.ROSBagException, OSError) as e:
        raise BagError('cannot read %s: %s' % (path, e))
    to_sim = clock_mapper(clock)
    return [(round(to_sim(t), 3), kind, fields) for t, kind, fields in raw]
