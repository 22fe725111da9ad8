"""Reading action_feedback events (rason_bridge.events), without a ROS master."""
import pytest

from rason_bridge.events import ActionFeedback, BadEvent, parse_action_feedback


def test_ok_feedback_is_read():
    assert parse_action_feedback('faulty', 'action_feedback', ['OK', '17']) == \
        ActionFeedback('faulty', 17, 'OK')


def test_failure_reason_is_kept_verbatim_without_surrounding_blanks():
    fb = parse_action_feedback('faulty', 'action_feedback', [' no_progress ', '3'])
    assert fb.result == 'no_progress'
    assert fb.action_id == 3


@pytest.mark.parametrize('event_type', ['', 'fault', 'Action_Feedback'])
def test_unknown_event_types_are_refused(event_type):
    with pytest.raises(BadEvent, match='unknown event type'):
        parse_action_feedback('faulty', event_type, ['OK', '1'])


@pytest.mark.parametrize('parameters, why', [
    ([], 'needs parameters'),
    (['OK'], 'needs parameters'),
    (['OK', 'seven'], 'non-integer'),
    (['OK', '1.5'], 'non-integer'),
    (['', '1'], 'empty result'),
])
def test_malformed_feedback_is_refused_with_the_reason(parameters, why):
    with pytest.raises(BadEvent, match=why):
        parse_action_feedback('faulty', 'action_feedback', parameters)


def test_feedback_without_agent_is_refused():
    with pytest.raises(BadEvent, match='without an agent'):
        parse_action_feedback('', 'action_feedback', ['OK', '1'])
