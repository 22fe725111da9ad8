"""ROS messages as the dashboard's plain records (dicts of str, numbers and lists). No rospy:
it reads the fields of rason_msgs/MindState, rason_msgs/AgentMessage and
diagnostic_msgs/DiagnosticArray, whoever delivered them (a subscriber or a bag)."""

#: The /diagnostics statuses the dashboard shows (diagnosis_reporter's).
STATUS_PREFIX = 'rason/'
_LEVELS = {0: 'OK', 1: 'WARN', 2: 'ERROR', 3: 'STALE'}


def _secs(stamp):
    return stamp.secs + stamp.nsecs * 1e-9


def mind_record(msg):
    """A MindState as {'mas_id', 'stamp', 'agents': [...]} (times in seconds)."""
    return {
        'mas_id': msg.mas_id,
        'stamp': _secs(msg.stamp),
        'inspector_url': getattr(msg, 'inspector_url', ''),  # bags recorded before it existed lack it
        'agents': [{
            'name': a.name, 'cycle': a.cycle, 'stamp': _secs(a.stamp),
            'beliefs': list(a.beliefs), 'rules': list(getattr(a, 'rules', [])),  # older bags lack rules
            'goals': list(a.goals),
            'intentions': [{'id': i.id, 'state': i.state, 'plans': list(i.plans)} for i in a.intentions],
            'actions': [{'id': p.id, 'action': p.action, 'started': _secs(p.started), 'held': p.held}
                        for p in a.actions],
            'events': list(a.events), 'messages': list(a.messages), 'omitted': a.omitted,
        } for a in msg.agents],
    }


def message_record(msg):
    """An AgentMessage between robots, with the line rason_dialogue prints for it."""
    receiver = msg.receiver or 'all'
    return {'sender': msg.sender, 'receiver': receiver, 'performative': msg.performative,
            'content': msg.content, 'sender_mas': msg.sender_mas,
            'line': '%s -> %s: %s %s' % (msg.sender, receiver, msg.performative, msg.content)}


def status_records(msg):
    """The rason/* statuses of a DiagnosticArray (the diagnosis, the mission)."""
    return [{'name': s.name, 'level': _LEVELS.get(int(ord(s.level) if isinstance(s.level, bytes) else s.level),
                                                   str(s.level)),
             'message': s.message, 'values': {kv.key: kv.value for kv in s.values}}
            for s in msg.status if s.name.startswith(STATUS_PREFIX)]
