"""What changed in an agent's mind from one jason/mind snapshot to the next: the beliefs,
rules and goals added and removed, the intentions that began, changed (state or stack) or
ended. No rospy: the timeline marks each view with it, live and in replay alike."""


def _added_removed(before, after):
    old, new = set(before), set(after)
    return [x for x in after if x not in old], [x for x in before if x not in new]


def agent_changes(before, after):
    """The changes from agent record before (None: the agent is new) to after, as lists."""
    if before is None:
        return {'new_agent': True, 'beliefs_added': [], 'beliefs_removed': [], 'rules_added': [],
                'rules_removed': [], 'goals_added': [], 'goals_removed': [], 'intentions_changed': [],
                'intentions_ended': []}
    changes = {'new_agent': False}
    for field in ('beliefs', 'rules', 'goals'):
        changes[field + '_added'], changes[field + '_removed'] = _added_removed(
            before.get(field, []), after.get(field, []))
    old = {i['id']: i for i in before['intentions']}
    new_ids = {i['id'] for i in after['intentions']}
    changes['intentions_changed'] = [i['id'] for i in after['intentions']
                                     if i['id'] not in old or (old[i['id']]['state'], old[i['id']]['plans'])
                                     != (i['state'], i['plans'])]
    changes['intentions_ended'] = [i for i in before['intentions'] if i['id'] not in new_ids]
    return changes


def robot_changes(before, after):
    """after (a robot's mind record) with each agent's changes since before (None: none earlier)
    and the time of before as since."""
    earlier = {} if before is None else {a['name']: a for a in before['agents']}
    agents = [dict(a, changes=agent_changes(earlier.get(a['name']), a)) for a in after['agents']]
    return dict(after, agents=agents, since=None if before is None else before['stamp'])
