"""jason/mind's ~params, its on/off switch and the message made of Java's snapshots (no ROS master)."""
import math

import pytest

from rason_bridge.mind import MindSwitch, to_msg
from rason_bridge.params import read_settings


def mind_settings(**given):
    return read_settings(lambda name, default: given.get(name, default), '/tmp')


def test_defaults():
    s = mind_settings()
    assert (s.mind_period, s.mind_max_items, s.mind_max_chars) == (0.5, 200, 500)


def test_zero_period_is_off_and_accepted():
    assert mind_settings(mind_period=0).mind_period == 0


@pytest.mark.parametrize('name,value', [
    ('mind_period', -1), ('mind_period', math.inf), ('mind_period', math.nan), ('mind_period', 'fast'),
    ('mind_max_items', 0), ('mind_max_items', 10001), ('mind_max_items', 2.5), ('mind_max_items', True),
    ('mind_max_chars', 15), ('mind_max_chars', 100001), ('mind_max_chars', '500'),
])
def test_bad_values_are_refused_naming_the_parameter(name, value):
    with pytest.raises(ValueError, match=name):
        mind_settings(**{name: value})


def test_switch_reads_only_while_somebody_subscribes():
    switch = MindSwitch(500_000_000)
    assert switch.update(0) is None and not switch.on   # nobody: stays off, nothing to tell Java
    assert switch.update(1) == 500_000_000 and switch.on
    assert switch.update(3) is None                      # still on
    assert switch.update(0) == 0 and not switch.on
    assert switch.update(2) == 500_000_000


def test_switch_with_zero_period_never_turns_on():
    switch = MindSwitch(0)
    assert switch.update(5) is None and not switch.on


class Record(object):
    """Stands for a Java record: every field read through an accessor method."""

    def __init__(self, **fields):
        for name, value in fields.items():
            setattr(self, name, (lambda v: lambda: v)(value))


def test_message_holds_every_field_of_every_agent():
    helper = Record(name='helper', cycle=42, stampNanos=12_500_000_000,
                    beliefs=['robot(faulty,1.5,2,3)[source(percept)]'], rules=['near(R) :- robot(R,D,_,_) & D < 2'],
                    goals=['!helpme[source(faulty)]'],
                    intentions=[Record(id=7, state='waiting', plans=['p1: +!findRobot(faulty) <- turn(10)',
                                                                      'p2: +!helpme[source(faulty)] <- !findRobot'])],
                    actions=[Record(id=3, action='turn(10)', startedNanos=12_000_000_000, held=False)],
                    events=['+!helpme[source(faulty)]'], messages=['faulty -> all: achieve helpme'], omitted=4)
    msg = to_msg('/helper/rason_mas', 13_000_000_001, [helper])
    assert msg.mas_id == '/helper/rason_mas' and msg.stamp.to_nsec() == 13_000_000_001
    (a,) = msg.agents
    assert (a.name, a.cycle, a.stamp.to_nsec(), a.omitted) == ('helper', 42, 12_500_000_000, 4)
    assert a.beliefs == ['robot(faulty,1.5,2,3)[source(percept)]'] and a.goals == ['!helpme[source(faulty)]']
    assert a.rules == ['near(R) :- robot(R,D,_,_) & D < 2']
    assert (a.intentions[0].id, a.intentions[0].state) == (7, 'waiting')
    assert a.intentions[0].plans[0].startswith('p1: +!findRobot')
    assert (a.actions[0].id, a.actions[0].action, a.actions[0].started.to_nsec(), a.actions[0].held) == \
        (3, 'turn(10)', 12_000_000_000, False)
    assert a.events == ['+!helpme[source(faulty)]'] and a.messages == ['faulty -> all: achieve helpme']


def test_no_agents_is_an_empty_list():
    assert to_msg('/x', 0, []).agents == []


def test_the_inspector_url_when_one_runs():
    assert to_msg('/x', 0, []).inspector_url == ''
    assert to_msg('/x', 0, [], 'http://127.0.0.1:40123').inspector_url == 'http://127.0.0.1:40123'
