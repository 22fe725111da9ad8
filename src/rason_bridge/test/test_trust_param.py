"""rason_mas's ~trust parameter reaches Java's TrustPolicy, and bad values are refused saying where."""
import jpype
import pytest

from rason_bridge.jvm import start_jvm
from rason_bridge.java_config import push_trust
from rason_bridge.trust import trust_rules

start_jvm()
Bridge = jpype.JClass('rason.bridge.Bridge')
Group = jpype.JClass('rason.messaging.TrustPolicy$Group')


def test_rules_are_flattened_with_lists_as_names():
    rules = trust_rules({'*': {'tellHow': 'all'}, 'helper': {'achieve': ['faulty', 'scout'], 'askHow': []}})
    assert sorted(rules) == [('*', 'tellHow', 'all'), ('helper', 'achieve', 'faulty, scout'),
                             ('helper', 'askHow', 'none')]


def test_no_parameter_is_no_rule():
    assert trust_rules(None) == [] and trust_rules({}) == [] and trust_rules('') == []


@pytest.mark.parametrize('bad', ['all', ['helper'], {'helper': 'all'}, {'helper': {'tell': 3}},
                                 {'helper': {'tell': ['a', 1]}}])
def test_malformed_values_are_refused(bad):
    with pytest.raises(ValueError, match='trust'):
        trust_rules(bad)


def test_rules_decide_what_the_agent_takes_from_other_robots():
    bridge = Bridge()
    push_trust(bridge, trust_rules({'param_agent': {'tellHow': ['faulty']}, 'someone_else': {'achieve': 'none'}}))
    trust = bridge.fleet().trust()
    assert trust.allows('param_agent', 'faulty', 'tellHow')
    assert trust.allows('param_agent', 'faulty', 'untellHow')
    assert not trust.allows('param_agent', 'mallory', 'tellHow')
    assert not trust.allows('someone_else', 'faulty', 'achieve')
    assert trust.allows('someone_else', 'faulty', 'tell')
    assert str(trust.rule('someone_else', Group.ASK_HOW)) == 'none'


@pytest.mark.parametrize('value, where', [({'helper': {'tellhow': 'all'}}, 'helper/tellhow'),
                                          ({'helper': {'tell': 'Bad Name'}}, 'helper/tell'),
                                          ({'Helper': {'tell': 'all'}}, 'Helper/tell')])
def test_java_refusals_name_the_rule(value, where):
    with pytest.raises(ValueError, match=where):
        push_trust(Bridge(), trust_rules(value))
