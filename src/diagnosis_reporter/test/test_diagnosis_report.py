import pytest

from diagnosis_reporter import report


@pytest.mark.parametrize('component,level', [
    ('none', 0), ('left_actuator', 1), ('right_actuator', 1), ('both_actuators', 1),
    ('odometry', 1), ('undiagnosed', 2)])
def test_each_component_has_its_level(component, level):
    d = report.parse('faulty', [component, 'because'])
    assert (d.component, d.level) == (component, level)


def test_message_names_agent_component_and_evidence():
    d = report.parse('faulty', ['both_actuators', 'same place before and after'])
    assert d.message == 'faulty: fault in both actuators (same place before and after)'
    assert d.values() == [('agent', 'faulty'), ('component', 'both_actuators'),
                          ('evidence', 'same place before and after')]


def test_evidence_is_optional():
    d = report.parse('faulty', ['odometry'])
    assert d.evidence == '' and d.message.endswith('encoders)')


@pytest.mark.parametrize('parameters,why', [
    ([], 'got 0'), (['a', 'b', 'c'], 'got 3'), (['wheels'], "unknown component 'wheels'")])
def test_bad_parameters_say_why(parameters, why):
    with pytest.raises(report.BadDiagnosis, match=why):
        report.parse('faulty', parameters)


def test_a_completed_mission_names_who_and_how():
    m = report.parse_mission('faulty', ['true', '[helper]', 'delegate', 'both_actuators'])
    assert m.level == 0
    assert m.values() == [('agent', 'faulty'), ('completed', 'true'), ('by', 'helper'),
                          ('recovery', 'delegate'), ('diagnosis', 'both_actuators')]
    assert m.message == 'faulty: mission completed by helper (diagnosis both_actuators, recovery delegate)'


def test_a_mission_not_completed_is_an_error_with_nobody():
    m = report.parse_mission('faulty', ['false', '[]', 'none', 'undiagnosed'])
    assert m.level == 2 and ('by', '') in m.values() and 'not completed' in m.message


def test_several_agents_can_complete_a_mission():
    m = report.parse_mission('faulty', ['true', '[faulty, helper]', 'guided', 'odometry'])
    assert ('by', 'faulty,helper') in m.values()


@pytest.mark.parametrize('parameters,why', [
    (['true', '[helper]', 'delegate'], 'got 3'),
    (['yes', '[helper]', 'delegate', 'none'], 'Completed must be true or false'),
    (['true', 'helper', 'delegate', 'none'], 'list of agent names'),
    (['true', '[Helper]', 'delegate', 'none'], "'Helper'"),
    (['true', '[]', 'delegate', 'none'], 'By is empty'),
    (['true', '[helper]', 'pray', 'none'], "unknown recovery 'pray'"),
    (['true', '[helper]', 'delegate', 'wheels'], "unknown diagnosis 'wheels'")])
def test_bad_mission_reports_say_why(parameters, why):
    with pytest.raises(report.BadDiagnosis, match=why):
        report.parse_mission('faulty', parameters)
