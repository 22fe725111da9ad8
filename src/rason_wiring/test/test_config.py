"""Unit tests of rason_wiring.config: ~actions checked into mappings, messages built from
arguments, outcomes and feedback read from replies (no ROS master: real message classes)."""
import copy

import pytest
from move_base_msgs.msg import MoveBaseFeedback, MoveBaseGoal
from std_msgs.msg import String
from std_srvs.srv import SetBoolRequest, SetBoolResponse, TriggerResponse

from rason_wiring import config, fields
from rason_wiring.config import ConfigError
from rason_wiring.ros_types import Resolver

GOTO = {
    'kind': 'actionlib', 'name': 'move_base', 'type': 'move_base_msgs/MoveBase',
    'fields': {'target_pose.header.frame_id': 'odom', 'target_pose.pose.position.x': 'X',
               'target_pose.pose.position.y': {'arg': 1}, 'target_pose.pose.orientation.w': 1.0},
    'feedback': {'at': ['base_position.pose.position.x', 'base_position.pose.position.y']},
}
LIGHT = {'kind': 'service', 'name': 'light', 'type': 'std_srvs/SetBool', 'fields': {'data': 'State'},
         'ok_when': 'success', 'reason': 'message'}
SAY = {'kind': 'topic', 'name': 'speech', 'type': 'std_msgs/String', 'fields': {'data': 'Text'}}


def parse(actions, **kw):
    return config.parse(copy.deepcopy(actions), Resolver(), **kw)


def one(signature, spec):
    return parse({signature: spec})[0]


def refused(signature, spec):
    with pytest.raises(ConfigError) as e:
        parse({signature: spec})
    text = str(e.value)
    assert text.startswith(signature + ': '), 'the error names the entry: ' + text
    return text


# ---------------------------------------------------------------- good configurations

def test_each_kind_gets_its_classes_and_arity():
    goto, light, say = parse({'goto(X, Y)': GOTO, 'light(State)': LIGHT, 'say(Text)': SAY})
    assert (goto.functor, goto.kind, goto.name, goto.arities) == ('goto', 'actionlib', 'move_base', {2})
    assert goto.ros_class.__name__ == 'MoveBaseAction'
    assert light.ros_class.__name__ == 'SetBool' and say.ros_class is String


def test_an_action_type_may_be_named_with_its_action_suffix():
    spec = dict(GOTO, type='move_base_msgs/MoveBaseAction')
    assert one('goto(X, Y)', spec).ros_class.__name__ == 'MoveBaseAction'


def test_build_fills_arguments_by_name_and_position_and_constants():
    goal = one('goto(X, Y)', GOTO).build(['1.5', '-2'])
    assert isinstance(goal, MoveBaseGoal)
    assert goal.target_pose.header.frame_id == 'odom'
    assert (goal.target_pose.pose.position.x, goal.target_pose.pose.position.y) == (1.5, -2.0)
    assert goal.target_pose.pose.orientation.w == 1.0


def test_a_string_field_takes_the_argument_text_as_the_bridge_sent_it():
    say = one('say(Text)', SAY)
    assert say.build(['Hello, "world"']).data == 'Hello, "world"'
    assert say.build(['3']).data == '3'


def test_constants_may_be_given_as_value_and_text_that_looks_like_a_variable_so():
    spec = dict(SAY, fields={'data': {'value': 'Hello'}})
    assert one('hello', spec).build([]).data == 'Hello'


def test_trailing_defaults_make_shorter_arities_valid():
    spec = dict(GOTO, fields=dict(GOTO['fields'], **{'target_pose.pose.orientation.z': 'Z'}),
                defaults={'Z': 0.5})
    goto = one('goto(X, Y, Z)', spec)
    assert goto.arities == {2, 3}
    assert goto.build(['1', '2']).target_pose.pose.orientation.z == 0.5
    assert goto.build(['1', '2', '0.25']).target_pose.pose.orientation.z == 0.25


def test_the_same_functor_may_map_different_arities():
    mappings = parse({'say(Text)': SAY, 'say': dict(SAY, fields={'data': {'value': 'hi'}})})
    assert [m.arities for m in mappings] == [{1}, {0}]


def test_a_value_that_does_not_fit_fails_at_run_time_naming_the_field():
    goto = one('goto(X, Y)', GOTO)
    with pytest.raises(fields.BadValue) as e:
        goto.build(['far', '1'])
    assert e.value.path == 'target_pose.pose.position.x'


def test_service_outcome_ok_or_the_reason_from_the_response():
    light = one('light(State)', LIGHT)
    assert isinstance(light.build(['true']), SetBoolRequest) and light.build(['true']).data is True
    assert light.outcome(SetBoolResponse(True, 'whatever')) == 'OK'
    assert light.outcome(SetBoolResponse(False, 'bulb_broken')) == 'bulb_broken'
    assert light.outcome(SetBoolResponse(False, '  ')) == config.FAILED


def test_a_service_without_ok_when_is_ok_once_it_answers():
    spec = {'kind': 'service', 'name': 'reset', 'type': 'std_srvs/Trigger'}
    assert one('reset', spec).outcome(TriggerResponse(False, 'no')) == 'OK'


def test_ok_when_may_compare_a_field_with_a_value():
    spec = dict(LIGHT, ok_when={'field': 'message', 'equals': 'done'})
    light = one('light(State)', spec)
    assert light.outcome(SetBoolResponse(False, 'done')) == 'OK'
    assert light.outcome(SetBoolResponse(True, 'jammed')) == 'jammed'


def test_goal_outcomes_for_each_terminal_state():
    goto = one('goto(X, Y)', GOTO)
    assert goto.goal_outcome('SUCCEEDED', None) == 'OK'
    assert goto.goal_outcome('ABORTED', None) == config.ABORTED
    assert goto.goal_outcome('REJECTED', None) == config.REJECTED
    assert goto.goal_outcome('PREEMPTED', None) == config.PREEMPTED
    assert goto.goal_outcome('RECALLED', None) == config.PREEMPTED
    assert goto.goal_outcome('LOST', None) == config.SERVER_LOST


def test_a_goal_result_field_gives_the_reason_and_ok_when_of_a_succeeded_goal():
    spec = {'kind': 'actionlib', 'name': 'test_request', 'type': 'actionlib/TestRequest',
            'fields': {'the_result': 'N'}, 'ok_when': {'field': 'the_result', 'equals': 0},
            'reason': 'the_result'}
    m = one('request(N)', spec)
    result = m.ros_class().action_result.result.__class__
    assert m.goal_outcome('SUCCEEDED', result(the_result=0)) == 'OK'
    assert m.goal_outcome('SUCCEEDED', result(the_result=7)) == '7'
    assert m.goal_outcome('ABORTED', result(the_result=3)) == '3'
    assert m.goal_outcome('SUCCEEDED', None) == config.FAILED


def test_feedback_becomes_literals_with_a_source():
    goto = one('goto(X, Y)', GOTO)
    assert goto.has_feedback and goto.feedback_source == 'goto'
    feedback = MoveBaseFeedback()
    feedback.base_position.pose.position.x, feedback.base_position.pose.position.y = 0.5, -1.0
    assert goto.feedback_literals(feedback) == ['at(0.5,-1.0)']
    named = parse({'goto(X, Y)': GOTO}, default_source=lambda f: 'wiring_' + f)[0]
    assert named.feedback_source == 'wiring_goto'
    assert one('goto(X, Y)', dict(GOTO, feedback_source='nav')).feedback_source == 'nav'


# ---------------------------------------------------------------- malformed configurations

@pytest.mark.parametrize('actions', [None, {}, [], 'goto'])
def test_actions_must_be_a_non_empty_dict(actions):
    with pytest.raises(ConfigError, match='~actions'):
        config.parse(actions, Resolver())


@pytest.mark.parametrize('signature, message', [
    ('Goto(X)', "functor 'Goto' is not a Jason atom"),
    ('go-to(X)', "functor 'go-to' is not a Jason atom"),
    ('goto(x)', "argument 'x' is not a Jason variable name"),
    ('goto(X, X)', 'argument X is named twice'),
    ('goto(X', 'not an action signature such as goto(X, Y)'),
])
def test_bad_signatures_are_named(signature, message):
    assert message in refused(signature, dict(SAY, fields={'data': 'X'}))


@pytest.mark.parametrize('change, message', [
    ({'kind': 'pigeon'}, "unknown kind 'pigeon' (one of: topic, service, actionlib)"),
    ({'kind': None}, 'unknown kind None'),
    ({'ok_when': 'data'}, 'unknown key ok_when for kind topic'),
    ({'name': ''}, 'name is missing'),
    ({'type': None}, 'type is missing'),
    ({'type': 'std_msgs/Strin'}, "unknown message type 'std_msgs/Strin'"),
    ({'type': 'String'}, "unknown message type 'String'"),
    ({'fields': {'dat': 'Text'}}, "bad field path dat: std_msgs/String has no field 'dat'"),
    ({'fields': {'data': 'Txt'}}, 'field data: missing argument Txt (arguments: Text'),
    ({'fields': {'data': {'arg': 'Txt'}}}, 'field data: missing argument Txt'),
    ({'fields': {'data': {'arg': 1}}}, 'field data: missing argument: position 1'),
    ({'fields': {'data': {'argh': 'Text'}}}, '{arg: Name or position} or {value: constant} is needed'),
    ({'fields': {}}, 'argument Text is used by no field'),
    ({'fields': ['data']}, 'fields: a dict'),
    ({'defaults': {'Voice': 1}}, 'default for Voice, which is not an argument'),
])
def test_bad_topic_entries_are_named(change, message):
    assert message in refused('say(Text)', dict(SAY, **change))


def test_a_constant_that_does_not_fit_is_refused():
    spec = dict(GOTO, fields=dict(GOTO['fields'], **{'target_pose.pose.orientation.w': 'one'}))
    assert 'constant for target_pose.pose.orientation.w does not fit' in refused('goto(X, Y)', spec)


def test_only_trailing_arguments_may_have_defaults_and_they_must_fit():
    assert 'only the last arguments can have defaults' in refused(
        'goto(X, Y)', dict(GOTO, defaults={'X': 1.0}))
    assert 'default for Y does not fit' in refused('goto(X, Y)', dict(GOTO, defaults={'Y': 'far'}))


def test_overlapping_arities_of_one_functor_are_refused():
    with pytest.raises(ConfigError, match=r'say\(Text, V\): say/1 is also mapped by say\(Text\)'):
        parse({'say(Text)': SAY, 'say(Text, V)': dict(SAY, type='diagnostic_msgs/KeyValue',
                                                      fields={'key': 'Text', 'value': 'V'},
                                                      defaults={'V': 'x'})})


def test_an_argument_yaml_read_as_a_bool_gets_a_hint():
    assert "YAML reads an unquoted On as a bool" in refused('light(On)', dict(LIGHT, fields={'data': True}))


@pytest.mark.parametrize('change, message', [
    ({'type': 'std_srvs/SetBoo'}, "unknown service type 'std_srvs/SetBoo'"),
    ({'ok_when': 'sucess'}, 'bad field path sucess in ok_when'),
    ({'ok_when': 'message'}, 'ok_when message is a string: give {field: message, equals: value}'),
    ({'ok_when': {'field': 'success', 'above': 1}}, 'ok_when: a bool field'),
    ({'ok_when': {'field': 'success', 'equals': 'yes'}}, 'ok_when equals: success: true or false is needed'),
    ({'reason': 'msg'}, 'bad field path msg in reason'),
    ({'ok_when': None}, 'reason needs ok_when'),
    ({'feedback': {'x': 'message'}}, 'unknown key feedback for kind service'),
])
def test_bad_service_entries_are_named(change, message):
    spec = {k: v for k, v in dict(LIGHT, **change).items() if v is not None}
    assert message in refused('light(State)', spec)


@pytest.mark.parametrize('change, message', [
    ({'type': 'move_base_msgs/MoveBas'}, "unknown action type 'move_base_msgs/MoveBas'"),
    ({'type': 'std_msgs/String'}, "unknown action type 'std_msgs/String'"),
    ({'feedback': {'At': 'base_position.pose.position.x'}}, "feedback functor 'At' is not a Jason atom"),
    ({'feedback': {'at': 'base_position.pose'}}, 'bad field path base_position.pose in feedback at'),
    ({'feedback': {'at': [1]}}, 'feedback at: a field path or a list of them is needed'),
    ({'feedback': ['at']}, 'feedback: a dict'),
    ({'feedback_source': 'Nav'}, "feedback_source 'Nav' is not a Jason atom"),
    ({'fields': dict(GOTO['fields'], **{'target_pose.header.stamp': 0})}, 'time and duration fields are not supported'),
])
def test_bad_actionlib_entries_are_named(change, message):
    assert message in refused('goto(X, Y)', dict(GOTO, **change))
