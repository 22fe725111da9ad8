"""Reading rason_msgs/Event messages (thesis §5.1): plain functions, no ROS."""
from collections import namedtuple

ACTION_FEEDBACK = 'action_feedback'
#: The feedback result that makes an action succeed; any other value is a failure reason.
OK = 'OK'

ActionFeedback = namedtuple('ActionFeedback', 'agent action_id result')


class BadEvent(ValueError):
    """An event that cannot be delivered; the message says why."""


def parse_action_feedback(agent, event_type, parameters):
    """Turn the fields of an Event into an :class:`ActionFeedback`.

    :param agent: the receiving agent's name
    :param event_type: must be ``action_feedback``
    :param parameters: ``[result, action_id]``
    :rtype: ActionFeedback
    :raises BadEvent: unknown event type, missing or malformed parameters
    """
    if event_type != ACTION_FEEDBACK:
        raise BadEvent('unknown event type %r' % (event_type,))
    if not agent:
        raise BadEvent('action_feedback without an agent')
    if len(parameters) < 2:
        raise BadEvent('action_feedback needs parameters [result, action_id], got %r'
                       % (list(parameters),))
    result = parameters[0].strip()
    if not result:
        raise BadEvent('action_feedback with an empty result')
    try:
        action_id = int(parameters[1])
    except ValueError:
        raise BadEvent('action_feedback with a non-integer action id %r' % (parameters[1],))
    return ActionFeedback(agent, action_id, result)
