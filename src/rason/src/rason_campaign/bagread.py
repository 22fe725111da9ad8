"""Read a run's bag into the events ``steps.extract_steps`` takes (needs rosbag, no master)."""
import os

from diagnosis_reporter.report import STATUS_NAME

ACTION_TOPIC = '/%s/jason/action'
MESSAGES_TOPIC = '/rason/messages'
DIAGNOSTICS_TOPIC = '/diagnostics'
CLOCK_TOPIC = '/clock'
ROBOTS = ('faulty', 'helper')


class BagError(IOError):
    """The bag cannot be read; the message says why."""


def read_events(path):
    """Events of the bag at ``path``, times in simulated seconds (via /clock).

    :rtype: list of (t, kind, fields)
    :raises BagError: when the bag is missing or unreadable.
    """
    import rosbag  # only here: the rest of the package has no ROS
    from rason_campaign.steps import clock_mapper
    if not os.path.exists(path):
        raise BagError('no bag %s' % path)
    action_topics = {ACTION_TOPIC % r: r for r in ROBOTS}
    topics = list(action_topics) + [MESSAGES_TOPIC, DIAGNOSTICS_TOPIC, CLOCK_TOPIC]
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
                elif topic == MESSAGES_TOPIC:
                    raw.append((t, 'message', {'sender': msg.sender, 'receiver': msg.receiver,
                                               'performative': msg.performative,
                                               'content': msg.content}))
                else:
                    for status in msg.status:
                        if status.name == STATUS_NAME:
                            fields = {kv.key: kv.value for kv in status.values}
                            raw.append((t, 'diagnosis', fields))
    except (rosbag.ROSBagException, OSError) as e:
        raise BagError('cannot read %s: %s' % (path, e))
    to_sim = clock_mapper(clock)
    return [(round(to_sim(t), 3), kind, fields) for t, kind, fields in raw]
