"""The Java side of the bridge (jason_lib), driven through JPype without a ROS master:
parsing perceptions, per-source replacement, expiry."""
import jpype
import pytest

from rason_bridge.jvm import start_jvm

start_jvm()
Perceptions = jpype.JClass('rason.perception.Perceptions')
PerSourcePerception = jpype.JClass('rason.perception.PerSourcePerception')
ASSyntax = jpype.JClass('jason.asSyntax.ASSyntax')
ArrayList = jpype.JClass('java.util.ArrayList')

SECOND = 1000000000


def lits(*texts):
    out = ArrayList()
    for t in texts:
        out.add(Perceptions.parse(t))
    return out


def texts(collection):
    return sorted(str(x) for x in collection) if collection is not None else None


@pytest.mark.parametrize('text, expected', [
    ('robot(faulty,-3.5,1.5,12)', 'robot(faulty,(-3.5),1.5,12)'),  # Jason's own spelling
    ('  hot ', 'hot'),
    ('~door(open)', '~door(open)'),
    ('pos(a)[quality(high)]', 'pos(a)[quality(high)]'),
    ('name("green cylinder")', 'name("green cylinder")'),
])
def test_valid_perceptions_parse(text, expected):
    assert str(Perceptions.parse(text)) == expected


@pytest.mark.parametrize('text, why', [
    ('robot(', 'not a Jason literal'),
    ('robot(a) extra', 'not a Jason literal'),
    ('', 'empty'),
    ('   ', 'empty'),
    ('robot(X, 1)', 'ground'),
    ('a :- b', 'not a Jason literal'),
    ('.print(x)', 'internal action'),
    ('123', 'not a Jason literal'),
    ('robot(@#)', 'not a Jason literal'),
])
def test_malformed_perceptions_are_refused_with_a_reason(text, why):
    with pytest.raises(jpype.JException) as info:
        Perceptions.parse(text)
    assert why in str(info.value.getMessage())


def test_first_list_of_a_source_is_perceived_once():
    table = PerSourcePerception()
    assert table.update('cam_robots', lits('robot(a,1,2,3)'), 0)
    assert texts(table.perceive()) == ['robot(a,1,2,3)']
    assert table.perceive() is None  # unchanged: Jason skips belief update


def test_new_list_replaces_the_old_one_of_the_same_source_only():
    table = PerSourcePerception()
    table.update('cam_robots', lits('robot(a,1,2,3)', 'robot(b,1,2,3)'), 0)
    table.update('laser_walls', lits('wall(left)'), 0)
    table.perceive()
    assert table.update('cam_robots', lits('robot(a,5,2,3)'), 1)
    assert texts(table.perceive()) == ['robot(a,5,2,3)', 'wall(left)']


def test_same_list_again_is_not_a_change_but_keeps_the_source_alive():
    table = PerSourcePerception()
    table.update('s', lits('p(1)'), 0)
    table.perceive()
    assert not table.update('s', lits('p(1)'), int(1.5 * SECOND))
    assert table.perceive() is None
    assert not table.expire(int(3 * SECOND), 2 * SECOND)  # heard at 1.5 s
    assert texts(table.current()) == ['p(1)']


def test_empty_list_clears_the_source():
    table = PerSourcePerception()
    table.update('s', lits('p(1)'), 0)
    table.update('t', lits('q(1)'), 0)
    table.perceive()
    assert table.update('s', ArrayList(), 1)
    assert texts(table.perceive()) == ['q(1)']
    assert not table.update('s', ArrayList(), 2)  # already empty


def test_silent_source_expires_after_the_ttl():
    table = PerSourcePerception()
    table.update('s', lits('p(1)'), 0)
    table.update('t', lits('q(1)'), int(1.5 * SECOND))
    table.perceive()
    assert not table.expire(2 * SECOND, 2 * SECOND)
    assert table.expire(int(2.1 * SECOND), 2 * SECOND)
    assert texts(table.perceive()) == ['q(1)']
    assert list(table.sourceNames()) == ['t']


def test_ttl_zero_never_expires():
    table = PerSourcePerception()
    table.update('s', lits('p(1)'), 0)
    assert not table.expire(1000 * SECOND, 0)
    assert texts(table.current()) == ['p(1)']
