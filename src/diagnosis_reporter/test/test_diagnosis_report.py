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
