"""Perception managers as plug-ins (jason_lib), through JPype without a ROS master: accumulate,
per-source rate limit, selective perception, and building them from .mas2j options."""
import jpype
import pytest

from rason_bridge.jvm import start_jvm

start_jvm()
Perceptions = jpype.JClass('rason.perception.Perceptions')
PerSourcePerception = jpype.JClass('rason.perception.PerSourcePerception')
AccumulatePerception = jpype.JClass('rason.perception.AccumulatePerception')
RateLimitedPerception = jpype.JClass('rason.perception.RateLimitedPerception')
SelectivePerception = jpype.JClass('rason.perception.SelectivePerception')
PerceptionManagers = jpype.JClass('rason.perception.PerceptionManagers')
ArrayList = jpype.JClass('java.util.ArrayList')
HashSet = jpype.JClass('java.util.HashSet')

S = 1000000000
MS = 1000000


def lits(*texts):
    out = ArrayList()
    for t in texts:
        out.add(Perceptions.parse(t))
    return out


def texts(collection):
    return sorted(str(x) for x in collection) if collection is not None else None


def selection(*entries):
    out = HashSet()
    for e in entries:
        out.add(e)
    return out


# ---- accumulate ---------------------------------------------------------------------

def test_accumulate_adds_every_message_and_replaces_nothing():
    m = AccumulatePerception()
    assert m.update('a', lits('p(1)'), 0)
    assert m.update('a', lits('p(2)'), 1)
    assert m.update('b', lits('q(1)'), 2)
    assert texts(m.perceive()) == ['p(1)', 'p(2)', 'q(1)']


def test_accumulate_counts_every_message_as_a_change():
    m = AccumulatePerception()
    m.update('a', lits('p(1)'), 0)
    m.perceive()
    assert m.update('a', lits('p(1)'), 1)      # same content: Jason still runs its belief update
    assert texts(m.perceive()) == ['p(1)']
    assert not m.update('a', ArrayList(), 2)   # an empty list clears nothing
    assert m.perceive() is None


def test_accumulate_forgets_literals_not_heard_within_the_ttl():
    m = AccumulatePerception()
    m.update('a', lits('p(1)'), 0)
    m.update('a', lits('p(2)'), S)
    assert m.expire(int(2.5 * S), 2 * S)
    assert texts(m.current()) == ['p(2)']


# ---- rate limit ---------------------------------------------------------------------

def test_rate_limit_passes_the_first_update_and_holds_the_burst():
    m = RateLimitedPerception(PerSourcePerception(), 5.0)   # one per 200 ms
    assert m.update('cam', lits('n(1)'), 0)
    for k in range(2, 10):
        assert not m.update('cam', lits('n(%d)' % k), k * 10 * MS)
    assert texts(m.perceive()) == ['n(1)']
    assert not m.expire(150 * MS, 0)           # window not over
    assert m.expire(200 * MS, 0)               # the newest held update, not the first held
    assert texts(m.perceive()) == ['n(9)']


def test_rate_limit_is_per_source():
    m = RateLimitedPerception(PerSourcePerception(), 5.0)
    assert m.update('a', lits('p(1)'), 0)
    assert m.update('b', lits('q(1)'), MS)
    assert not m.update('a', lits('p(2)'), 2 * MS)
    assert texts(m.current()) == ['p(1)', 'q(1)']


def test_rate_limit_lets_updates_through_at_the_declared_rate():
    m = RateLimitedPerception(PerSourcePerception(), 5.0)
    applied = 0
    for k in range(100):                       # 100 Hz for one second, ticks every 50 ms
        now = k * 10 * MS
        applied += m.update('cam', lits('n(%d)' % k), now)
        if k % 5 == 0:
            applied += m.expire(now, 0)
    m.expire(S + 200 * MS, 0)
    assert 4 <= applied <= 6
    assert texts(m.current()) == ['n(99)']     # nothing stale sticks


def test_rate_limited_clear_is_applied_too():
    m = RateLimitedPerception(PerSourcePerception(), 5.0)
    m.update('a', lits('p(1)'), 0)
    assert not m.update('a', ArrayList(), 10 * MS)
    assert m.expire(200 * MS, 0)
    assert texts(m.current()) == []


@pytest.mark.parametrize('rate', [0.0, -1.0, float('inf'), float('nan')])
def test_rate_limit_refuses_a_rate_that_is_not_positive(rate):
    with pytest.raises(jpype.JException) as info:
        RateLimitedPerception(PerSourcePerception(), rate)
    assert 'positive' in str(info.value.getMessage())


# ---- selective --------------------------------------------------------------------

def test_selective_keeps_only_the_declared_functors():
    m = SelectivePerception(PerSourcePerception(), selection('robot/4', 'battery/1'))
    m.update('cam', lits('robot(a,1,2,3)', 'robot(b)', 'battery(50)', 'temp(3)', '~battery(0,1)'), 0)
    assert texts(m.perceive()) == ['battery(50)', 'robot(a,1,2,3)']


def test_selective_ignores_changes_of_unwanted_literals():
    m = SelectivePerception(PerSourcePerception(), selection('robot/4'))
    m.update('cam', lits('robot(a,1,2,3)', 'temp(1)'), 0)
    m.perceive()
    assert not m.update('cam', lits('robot(a,1,2,3)', 'temp(2)'), 1)
    assert m.perceive() is None


def test_selective_change_of_selection_applies_at_once():
    m = SelectivePerception(PerSourcePerception(), selection('robot/4'))
    m.update('cam', lits('robot(a,1,2,3)', 'battery(50)'), 0)
    m.perceive()
    m.select(selection('battery/1'))
    assert texts(m.perceive()) == ['battery(50)']
    m.select(None)
    assert texts(m.perceive()) == ['battery(50)', 'robot(a,1,2,3)']


def test_selective_without_selection_passes_everything():
    m = SelectivePerception(AccumulatePerception(), None)
    m.update('cam', lits('robot(a,1,2,3)', 'temp(1)'), 0)
    assert texts(m.perceive()) == ['robot(a,1,2,3)', 'temp(1)']
    assert m.wants(Perceptions.parse('anything(1)'))


def test_selective_wants_is_what_the_bridge_filters_its_own_percepts_with():
    m = SelectivePerception(PerSourcePerception(), selection('present/1'))
    assert m.wants(Perceptions.parse('present(bob)'))
    assert not m.wants(Perceptions.parse('robot(a,1,2,3)'))


@pytest.mark.parametrize('spec, expected', [
    ('robot/4, battery/1', ['battery/1', 'robot/4']),
    ('(robot/4)', ['robot/4']),
    ('"robot/4"', ['robot/4']),
    ('~door/1', ['door/1']),
    (' , ', []),
])
def test_selection_parsing(spec, expected):
    assert sorted(str(s) for s in SelectivePerception.parseSelection(spec)) == expected


@pytest.mark.parametrize('spec', ['robot', 'robot/', '/4', 'Robot/4', 'robot/x', 'robot/4/5'])
def test_selection_parsing_refuses_what_is_not_functor_arity(spec):
    with pytest.raises(jpype.JException) as info:
        SelectivePerception.parseSelection(spec)
    assert 'functor/arity' in str(info.value.getMessage())


# ---- choosing per agent -------------------------------------------------------------

@pytest.mark.parametrize('manager, rate, perceive, expected', [
    (None, None, None, 'per_source'),
    ('accumulate', None, None, 'accumulate'),
    ('per_source', '5', None, 'rate_limit(5.0/s) over per_source'),
    (None, None, 'robot/4', 'selective[robot/4] over per_source'),
    ('rason.perception.AccumulatePerception', '2.5', 'a/1', 'selective[a/1] over rate_limit(2.5/s) over accumulate'),
])
def test_chain_from_options(manager, rate, perceive, expected):
    assert str(PerceptionManagers.forAgent(manager, rate, perceive, 'per_source')) == expected


def test_default_strategy_applies_when_the_agent_names_none():
    assert str(PerceptionManagers.forAgent(None, None, None, 'accumulate')) == 'accumulate'


@pytest.mark.parametrize('manager, rate, perceive, why', [
    ('fancy', None, None, 'perception_manager: perception manager \'fancy\' is neither'),
    ('java.lang.String', None, None, 'does not implement rason.perception.PerceptionManager'),
    ('rason.perception.RateLimitedPerception', None, None, 'public constructor without arguments'),
    (None, 'fast', None, 'perception_rate: \'fast\' is not a number'),
    (None, '0', None, 'perception_rate: a perception rate must be a positive'),
    (None, None, 'robot', 'perceive: \'robot\' is not functor/arity'),
])
def test_bad_options_are_refused_with_the_option_named(manager, rate, perceive, why):
    with pytest.raises(jpype.JException) as info:
        PerceptionManagers.forAgent(manager, rate, perceive, 'per_source')
    assert why in str(info.value.getMessage())
