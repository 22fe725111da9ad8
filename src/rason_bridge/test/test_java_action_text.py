"""The Java side of the bridge (jason_lib), driven through JPype without a ROS master:
action parameters and failure reasons."""
import jpype
import pytest

from rason_bridge.jvm import start_jvm

start_jvm()
RosAgArch = jpype.JClass('rason.RosAgArch')
ASSyntax = jpype.JClass('jason.asSyntax.ASSyntax')


@pytest.mark.parametrize('action, params', [
    ('move(1)', ['1']),
    ('move(-0.3)', ['-0.3']),
    ('turn(5)', ['5']),
    ('say("hello there", bob)', ['hello there', 'bob']),
    ('go(pos(1,2),[a,b])', ['pos(1,2)', '[a,b]']),
    ('stop', []),
])
def test_action_parameters_are_sent_as_text(action, params):
    term = ASSyntax.parseStructure(action)
    assert [str(p) for p in RosAgArch.parametersOf(term)] == params


@pytest.mark.parametrize('result, literal', [
    ('no_progress', 'no_progress'),
    ('bad_move', 'bad_move'),
    ('blocked(left)', 'blocked(left)'),
    ('Motor stalled!', 'failure_reason("Motor stalled!")'),
    ('X', 'failure_reason("X")'),
])
def test_failure_reasons_become_annotations(result, literal):
    assert str(RosAgArch.reasonLiteral(result)) == literal
