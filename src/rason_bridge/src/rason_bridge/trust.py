"""The ``~trust`` parameter: which agents of other robots may send what to the agents
hosted here (Java's ``rason.messaging.TrustPolicy`` checks it); no rospy.

``~trust`` maps an agent name (or ``'*'`` for every agent of the process) to a map
from a performative group (``tell``, ``achieve``, ``ask``, ``askHow``, ``tellHow``,
``other``) to who may: ``all``, ``none`` or agent names (a list or a string)::

    rason_mas:
      trust:
        '*':    {tellHow: none}
        helper: {tellHow: [faulty], achieve: [faulty]}
"""


def trust_rules(value):
    """The rules of a ``~trust`` value as ``(agent, group, who)`` triples, ``who`` as text.

    :raises ValueError: saying which part of the value is wrong
    """
    if value is None or value == '' or value == {}:
        return []
    if not isinstance(value, dict):
        raise ValueError('trust must map agent names (or \'*\') to rules, not %r' % (value,))
    rules = []
    for agent, groups in value.items():
        if not isinstance(agent, str) or not isinstance(groups, dict):
            raise ValueError('trust: %r must map performative groups to who may send them, not %r'
                             % (agent, groups))
        for group, who in groups.items():
            if isinstance(who, (list, tuple)) and all(isinstance(n, str) for n in who):
                text = ', '.join(who) if who else 'none'
            elif isinstance(who, str):
                text = who
            else:
                raise ValueError('trust: %s/%s must be all, none or agent names, not %r' % (agent, group, who))
            rules.append((agent, str(group), text))
    return rules

