"""Step boundaries from synthetic message lists, outcomes, the clock mapping."""
import pytest

from rason_campaign.steps import Steps, classify, clock_mapper, extract_steps, judge


def action(t, name, robot='faulty'):
    return (t, 'action', {'robot': robot, 'agent': robot, 'action': name, 'parameters': []})


def message(t, sender, receiver, performative, content):
    return (t, 'message', {'sender': sender, 'receiver': receiver,
                           'performative': performative, 'content': content})


def diagnosis(t, component, evidence='seen'):
    return (t, 'diagnosis', {'agent': 'faulty', 'component': component, 'evidence': evidence})


def cooperative_run():
    """Like thesis Table 7.1 run 1: 4.3 + 14.7 + 4.4 = 23.4 s, from t = 10."""
    return [
        action(9.0, 'turn', robot='helper'),           # the helper's motion is not a start
        message(9.5, 'faulty', '', 'achieve', 'helpme'),  # before any move: ignored
        action(10.0, 'move'),
        action(12.0, 'move'),
        message(14.3, 'faulty', '', 'achieve', 'helpme'),
        message(20.0, 'helper', 'other', 'tell', 'found(other)'),  # not to the asker
        message(29.0, 'helper', 'faulty', 'tell', 'found(faulty)'),
        message(29.1, 'faulty', 'helper', 'achieve', 'trackMe'),
        diagnosis(33.4, 'both_actuators'),
        diagnosis(34.4, 'both_actuators'),             # repeats of the status
    ]


def test_cooperative_run_boundaries_and_steps():
    s = extract_steps(cooperative_run())
    assert (s.start, s.help, s.found, s.diagnosed) == (10.0, 14.3, 29.0, 33.4)
    assert s.component == 'both_actuators'
    assert s.durations() == pytest.approx({'fault_detection': 4.3, 'robot_location': 14.7,
                                           'diagnosis': 4.4, 'total': 23.4})


def test_order_of_the_list_does_not_matter():
    events = cooperative_run()
    assert extract_steps(reversed(events)).to_dict() == extract_steps(events).to_dict()


def test_no_fault_has_only_a_total():
    s = extract_steps([action(5.0, 'move'), action(9.0, 'move'), diagnosis(12.5, 'none')])
    d = s.durations()
    assert d['total'] == pytest.approx(7.5)
    assert d['fault_detection'] is d['robot_location'] is d['diagnosis'] is None


def test_found_before_help_does_not_count():
    s = extract_steps([action(1.0, 'move'), message(2.0, 'helper', 'faulty', 'tell', 'found(faulty)'),
                       message(3.0, 'faulty', '', 'achieve', 'helpme')])
    assert s.help == 3.0 and s.found is None and s.diagnosed is None
    assert s.durations()['total'] is None


def test_nothing_recorded():
    assert extract_steps([]).to_dict() == Steps().to_dict()


@pytest.mark.parametrize('fault,component,outcome', [
    ('none', 'none', 'correct'),
    ('left_actuator', 'left_actuator', 'correct'),
    ('left_actuator', 'right_actuator', 'wrong'),
    ('none', 'odometry', 'wrong'),
    ('odometry', 'none', 'wrong'),
    ('odometry', 'undiagnosed', 'undiagnosed'),
    ('both_actuators', None, 'undiagnosed'),
])
def test_classify(fault, component, outcome):
    assert classify(fault, component) == outcome


def test_judge_reasons():
    nothing = Steps()
    assert judge('odometry', nothing, 'timed out after 240 s') == (
        'undiagnosed', 'timed out after 240 s')
    assert judge('odometry', nothing) == ('undiagnosed', 'no diagnosis recorded')
    told = Steps(component='undiagnosed', evidence='the helper could not find me')
    assert judge('odometry', told) == ('undiagnosed', 'the helper could not find me')
    wrong = Steps(component='none', evidence='destination reached')
    assert judge('odometry', wrong) == ('wrong', 'none: destination reached')


def test_clock_mapper_keeps_sim_record_times():
    to_sim = clock_mapper([(1.0, 1.0), (1.01, 1.02), (2.0, 2.0)])
    assert to_sim(1.5) == 1.5


def test_clock_mapper_maps_wall_record_times():
    # Recorded on wall time 1000 s ahead of the simulated clock.
    to_sim = clock_mapper([(1001.0, 1.0), (1002.0, 2.0), (1003.0, 3.0)])
    assert to_sim(1002.5) == pytest.approx(2.5)
    assert to_sim(999.0) == pytest.approx(-1.0)  # before the first /clock


def test_clock_mapper_without_clock_is_identity():
    assert clock_mapper([])(42.0) == 42.0
