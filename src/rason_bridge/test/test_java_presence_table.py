"""Presence between rason_mas processes (jason_lib PresenceTable), through JPype without a
ROS master: joins, links, timeouts, leaving, restarts, messages before announcements, clashes."""
import jpype

from rason_bridge.jvm import start_jvm

start_jvm()
PresenceTable = jpype.JClass('rason.messaging.PresenceTable')

S = 1000000000
TIMEOUT = 2 * S


def names(table):
    return sorted(str(n) for n in table.reachable())


def changed(changes):
    return sorted(str(a) for a in changes.joined), sorted(str(a) for a in changes.left)


def joined(table, mas, agents, now=0, incarnation=1):
    table.announced(mas, incarnation, agents, False, now)
    return table.tick([mas], now, TIMEOUT)


def test_announced_agent_is_reachable_only_once_linked():
    t = PresenceTable()
    c = t.announced('/r2/rason_mas', 1, ['bob'], False, 0)
    assert changed(c) == ([], [])
    assert t.masOf('bob') is None            # heard is not connected
    assert str(t.sendableMasOf('bob')) == '/r2/rason_mas'  # a message may wait for the link
    c = t.tick(['/r2/rason_mas'], 1, TIMEOUT)
    assert changed(c) == (['bob'], [])
    assert str(t.masOf('bob')) == '/r2/rason_mas'
    assert names(t) == ['bob']


def test_silent_peer_leaves_after_the_timeout_and_its_agents_are_lost():
    t = PresenceTable()
    joined(t, '/r2/rason_mas', ['bob', 'bea'])
    c = t.tick(['/r2/rason_mas'], TIMEOUT, TIMEOUT)
    assert changed(c) == ([], [])              # exactly the timeout: still there
    c = t.tick(['/r2/rason_mas'], TIMEOUT + 1, TIMEOUT)
    assert changed(c) == ([], ['bea', 'bob'])
    assert sorted(str(a) for a in c.lost) == ['bea', 'bob']
    assert t.masOf('bob') is None
    assert 'has left' in str(t.whyUnreachable('bob'))
    assert 'not heard for 2.0 s' in str(t.whyUnreachable('bob'))


def test_announcements_keep_a_peer_present():
    t = PresenceTable()
    joined(t, '/r2/rason_mas', ['bob'])
    for k in range(1, 10):
        t.announced('/r2/rason_mas', 1, ['bob'], False, k * S)
        assert changed(t.tick(['/r2/rason_mas'], k * S + S // 2, TIMEOUT)) == ([], [])
    assert names(t) == ['bob']


def test_leaving_announcement_removes_at_once():
    t = PresenceTable()
    joined(t, '/r2/rason_mas', ['bob'])
    c = t.announced('/r2/rason_mas', 1, ['bob'], True, S)
    assert changed(c) == ([], ['bob'])
    assert 'announced it is leaving' in str(t.whyUnreachable('bob'))


def test_lost_link_makes_agents_unreachable_until_it_is_back():
    t = PresenceTable()
    joined(t, '/r2/rason_mas', ['bob'])
    assert changed(t.tick([], S // 2, TIMEOUT)) == ([], ['bob'])
    assert t.sendableMasOf('bob') is None    # a send would be lost: it fails instead
    assert 'connection to its process is down' in str(t.whyUnreachable('bob'))
    assert changed(t.tick(['/r2/rason_mas'], S, TIMEOUT)) == (['bob'], [])
    assert str(t.sendableMasOf('bob')) == '/r2/rason_mas'


def test_restart_within_the_timeout_loses_pending_answers_but_stays_present():
    t = PresenceTable()
    joined(t, '/r2/rason_mas', ['bob'], incarnation=100)
    c = t.announced('/r2/rason_mas', 200, ['bob'], False, S)
    assert sorted(str(a) for a in c.lost) == ['bob']
    assert any('restarted' in str(e) for e in c.events)
    assert names(t) == ['bob']


def test_restart_after_departure_is_a_new_join():
    t = PresenceTable()
    joined(t, '/r2/rason_mas', ['bob'], incarnation=100)
    t.tick([], 3 * S, TIMEOUT)
    assert names(t) == []
    c = joined(t, '/r2/rason_mas', ['bob'], now=4 * S, incarnation=200)
    assert changed(c) == (['bob'], [])


def test_stale_announcement_of_an_earlier_run_is_ignored():
    t = PresenceTable()
    joined(t, '/r2/rason_mas', ['bob'], incarnation=200)
    c = t.announced('/r2/rason_mas', 100, ['bob'], True, S)
    assert c.isEmpty()
    assert names(t) == ['bob']


def test_message_before_announcement_counts_as_presence():
    t = PresenceTable()
    t.messageFrom('/r2/rason_mas', 'bob', 0)
    t.tick(['/r2/rason_mas'], 1, TIMEOUT)
    assert names(t) == ['bob']
    # its announcement then brings the full list, and is not taken for a restart
    c = t.announced('/r2/rason_mas', 7, ['bob', 'bea'], False, 2)
    assert len(c.lost) == 0
    t.tick(['/r2/rason_mas'], 3, TIMEOUT)
    assert names(t) == ['bea', 'bob']


def test_agent_list_follows_the_announcements():
    t = PresenceTable()
    joined(t, '/r2/rason_mas', ['bob', 'bea'])
    t.announced('/r2/rason_mas', 1, ['bob'], False, 1)
    assert changed(t.tick(['/r2/rason_mas'], 2, TIMEOUT)) == ([], [])
    assert names(t) == ['bob']


def test_clash_with_a_local_agent_is_reported_once_and_the_name_stays_local():
    t = PresenceTable()
    t.setLocal(['alice'])
    c = t.announced('/r2/rason_mas', 1, ['alice', 'bob'], False, 0)
    assert len(c.clashes) == 1
    assert 'hosted here and also announced by /r2/rason_mas' in str(c.clashes[0])
    assert 'agent_prefix' in str(c.clashes[0])
    t.tick(['/r2/rason_mas'], 1, TIMEOUT)
    assert t.masOf('alice') is None
    assert names(t) == ['bob']
    c = t.announced('/r2/rason_mas', 1, ['alice', 'bob'], False, 2)
    assert len(c.clashes) == 0                 # once


def test_clash_between_two_peers_keeps_the_first_claimer():
    t = PresenceTable()
    joined(t, '/r2/rason_mas', ['bob'])
    c = t.announced('/r3/rason_mas', 1, ['bob', 'carl'], False, 1)
    assert len(c.clashes) == 1
    assert 'both /r2/rason_mas and /r3/rason_mas' in str(c.clashes[0])
    t.tick(['/r2/rason_mas', '/r3/rason_mas'], 2, TIMEOUT)
    assert str(t.masOf('bob')) == '/r2/rason_mas'
    # when the first claimer leaves, the other one gets the name
    t.announced('/r2/rason_mas', 1, [], True, 3)
    assert str(t.masOf('bob')) == '/r3/rason_mas'


def test_unknown_agent_has_a_reason():
    t = PresenceTable()
    assert 'no agent' in str(t.whyUnreachable('nobody'))
