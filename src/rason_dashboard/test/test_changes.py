"""What changed between two snapshots of an agent, and the timeline's views marked with it
(no ROS)."""
from rason_dashboard.changes import agent_changes
from rason_dashboard.timeline import Timeline


def agent(beliefs=(), goals=(), intentions=(), rules=()):
    return {'name': 'a', 'cycle': 1, 'stamp': 0.0, 'beliefs': list(beliefs), 'rules': list(rules),
            'goals': list(goals), 'intentions': list(intentions), 'actions': [], 'events': [], 'messages': [],
            'omitted': 0}


def intention(iid, state, *plans):
    return {'id': iid, 'state': state, 'plans': list(plans)}


def test_beliefs_goals_and_rules_added_and_removed_in_order():
    c = agent_changes(agent(['a', 'b', 'c'], ['!g1'], rules=['r :- a']),
                      agent(['b', 'd', 'e'], ['!g2'], rules=['r :- a']))
    assert (c['beliefs_added'], c['beliefs_removed']) == (['d', 'e'], ['a', 'c'])
    assert (c['goals_added'], c['goals_removed']) == (['!g2'], ['!g1'])
    assert (c['rules_added'], c['rules_removed']) == ([], [])
    assert not c['new_agent']


def test_intentions_new_changed_and_ended():
    before = agent(intentions=[intention(1, 'running', '+!a <- x'), intention(2, 'waiting', '+!b <- y'),
                               intention(3, 'waiting', '+!c <- z')])
    after = agent(intentions=[intention(1, 'running', '+!a <- x'), intention(2, 'running', '+!b <- y'),
                              intention(4, 'running', '+!d <- w')])
    c = agent_changes(before, after)
    assert c['intentions_changed'] == [2, 4]
    assert [i['id'] for i in c['intentions_ended']] == [3]


def test_a_new_agent_has_nothing_marked():
    c = agent_changes(None, agent(['a'], intentions=[intention(1, 'running', 'p')]))
    assert c['new_agent'] and c['beliefs_added'] == [] and c['intentions_changed'] == []


def test_each_view_is_marked_against_the_robots_snapshot_before_it():
    t = Timeline('replay')
    for stamp, beliefs in ((10.0, ['a']), (20.0, ['a', 'b']), (30.0, ['b'])):
        t.add_mind(stamp, {'mas_id': '/r', 'stamp': stamp, 'agents': [agent(beliefs)]})
    first, second, third = (t.view(x)['robots'][0] for x in (15.0, 25.0, None))
    assert first['since'] is None and first['agents'][0]['changes']['new_agent']
    assert second['since'] == 10.0 and second['agents'][0]['changes']['beliefs_added'] == ['b']
    assert third['since'] == 20.0 and third['agents'][0]['changes']['beliefs_removed'] == ['a']
