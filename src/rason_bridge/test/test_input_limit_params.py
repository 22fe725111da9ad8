"""rason_mas's ~max_* parameters reach Java's InputLimits, durations become Java's nanoseconds, and bad
values are refused by name."""
import jpype
import pytest

from rason_bridge.java_config import INPUT_LIMIT_SETTERS, push_input_limits
from rason_bridge.jvm import start_jvm
from rason_bridge.params import BY_NAME, ParamError, read_settings, seconds_to_nanos

start_jvm()
InputLimits = jpype.JClass('rason.core.InputLimits')
GETTERS = {'max_literal_length': 'maxLiteralLength', 'max_content_length': 'maxContentLength',
           'max_nesting': 'maxNesting', 'max_term_depth': 'maxTermDepth', 'max_literals': 'maxLiterals',
           'max_sources': 'maxSources'}


def settings(**given):
    return read_settings(lambda name, default: given.get(name, default), '/tmp')


def test_the_schema_defaults_are_the_java_defaults():
    fresh = InputLimits()
    assert set(GETTERS) == set(INPUT_LIMIT_SETTERS)
    for name, getter in GETTERS.items():
        assert BY_NAME[name].default == getattr(fresh, getter)(), name
    assert settings().max_sources == 100


def test_each_parameter_sets_its_limit():
    limits = InputLimits()
    given = {'max_literal_length': 100, 'max_content_length': 200, 'max_nesting': 3, 'max_term_depth': 40,
             'max_literals': 7, 'max_sources': 9}
    push_input_limits(limits, settings(**given))
    assert (limits.maxLiteralLength(), limits.maxContentLength(), limits.maxNesting(), limits.maxTermDepth(),
            limits.maxLiterals(), limits.maxSources()) == (100, 200, 3, 40, 7, 9)


@pytest.mark.parametrize('bad', [0, -5, 2.5, 'many', True, None])
def test_a_bad_value_is_refused_naming_the_parameter(bad):
    with pytest.raises(ParamError, match='max_nesting must be a whole number of at least 1, not '):
        settings(max_nesting=bad)


@pytest.mark.parametrize('seconds, nanos', [(60.0, 60 * 10 ** 9), (0, 0), (0.5, 5 * 10 ** 8), (-1, -10 ** 9),
                                            (1e9, 10 ** 18)])
def test_durations_become_nanoseconds(seconds, nanos):
    assert seconds_to_nanos('action_timeout', seconds) == nanos


@pytest.mark.parametrize('bad', [float('inf'), float('-inf'), float('nan'), 1e300, 2 ** 80, '60', None, True])
def test_a_duration_java_cannot_take_is_refused_naming_the_parameter(bad):
    # int(inf) raised OverflowError, which the node did not catch
    with pytest.raises(ValueError, match='perception_ttl'):
        seconds_to_nanos('perception_ttl', bad)
    with pytest.raises(ParamError, match='perception_ttl'):
        settings(perception_ttl=bad)
