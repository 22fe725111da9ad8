"""Recorded bags as a Timeline: jason/mind, the messages between robots, the rason/*
statuses of /diagnostics and the robots' poses (true_pose, odom, /tf_static), each at the time
it was recorded. Reads the bags only: nothing is
published, so replaying never reaches live agents.

Several bags are one run when each robot recorded on its own master (robots on hosts of their
own): their times agree as they all run on the world's /clock (or on synchronised wall clocks).
What two bags both hold (one master recorded twice, a message seen by both robots) is shown
once."""
import rosbag

from rason_dashboard.poses import pose_records, pose_topic_kind
from rason_dashboard.records import message_record, mind_record, status_records
from rason_dashboard.timeline import Timeline

MIND_TYPE = 'rason_msgs/MindState'
MESSAGE_TYPE = 'rason_msgs/AgentMessage'
DIAGNOSTICS_TYPE = 'diagnostic_msgs/DiagnosticArray'
#: How far apart (s) two bags may have recorded the same message or status.
SAME_RECORD_WINDOW = 1.0


def read_bag(path):
    """The dashboard's records of one bag, in recorded order: a list of (kind, time, record),
    kind 'mind', 'message', 'status' or 'pose' (a record (pose kind, robot, pose)).
    IOError/ROSBagException if it cannot be read."""
    records = []
    with rosbag.Bag(path) as bag:
        topics = bag.get_type_and_topic_info().topics
        poses = {t: pose_topic_kind(t, info.msg_type) for t, info in topics.items()}
        wanted = [t for t, info in topics.items()
                  if info.msg_type in (MIND_TYPE, MESSAGE_TYPE, DIAGNOSTICS_TYPE) or poses[t]]
        for topic, msg, stamp in bag.read_messages(topics=wanted):
            t = stamp.to_sec()
            kind = topics[topic].msg_type
            if poses[topic]:
                records.extend(('pose', t, (poses[topic], robot, pose))
                               for robot, pose in pose_records(poses[topic], topic, msg))
            elif kind == MIND_TYPE:
                records.append(('mind', t, mind_record(msg)))
            elif kind == MESSAGE_TYPE:
                records.append(('message', t, message_record(msg)))
            else:
                records.extend(('status', t, s) for s in status_records(msg))
    return records


def _key(kind, record):
    if kind == 'pose':
        pose_kind, robot, pose = record
        return kind, pose_kind, robot, pose['x'], pose['y'], pose['yaw']
    if kind == 'mind':
        return kind, record['mas_id'], record['stamp']
    if kind == 'message':
        return kind, record['sender_mas'], record['sender'], record['receiver'], record['performative'], \
            record['content']
    return kind, record['name'], record['level'], record['message'], tuple(sorted(record['values'].items()))


def merge_runs(runs):
    """The records of several bags as one run: a record of a later bag that an earlier bag holds
    too (the same mind state; the same message or status recorded within SAME_RECORD_WINDOW s,
    each matched once) is left out. Returns [(kind, time, record)] in time order."""
    merged = []
    seen = {}  # key -> times recorded by the bags merged so far, each usable once per later bag
    for records in runs:
        unmatched = {k: list(ts) for k, ts in seen.items()}
        for kind, t, record in records:
            key = _key(kind, record)
            times = unmatched.get(key)
            twin = None if not times else min(times, key=lambda s: abs(s - t))
            if twin is not None and (kind == 'mind' or abs(twin - t) <= SAME_RECORD_WINDOW):
                times.remove(twin)
                continue
            merged.append((kind, t, record))
            seen.setdefault(key, []).append(t)
    merged.sort(key=lambda r: r[1])
    return merged


def load_bags(paths):
    """The Timeline of one or more bags of a run; IOError/ROSBagException if one cannot be read.
    Returns (timeline, counts)."""
    timeline = Timeline(mode='replay')
    counts = {'minds': 0, 'messages': 0, 'statuses': 0, 'poses': 0}
    adders = {'mind': (timeline.add_mind, 'minds'), 'message': (timeline.add_message, 'messages'),
              'status': (timeline.add_status, 'statuses'),
              'pose': (lambda t, r: timeline.add_pose(t, *r), 'poses')}
    for kind, t, record in merge_runs([read_bag(p) for p in paths]):
        add, count = adders[kind]
        add(t, record)
        counts[count] += 1
    return timeline, counts


def load_bag(path):
    """The Timeline of a bag. Returns (timeline, counts)."""
    return load_bags([path])
