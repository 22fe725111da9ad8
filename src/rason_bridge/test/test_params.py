"""rason_mas's parameter schema: the committed reference is what the schema renders, the node reads
exactly the schema's parameters, each default is allowed, and a bad value is refused in one line
naming the parameter, the value and what is allowed."""
import math
import os
import re

import pytest

from rason_bridge import params
from rason_bridge.params import PARAMS, ParamError, Settings, read_settings, render_markdown

PACKAGE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
MODULES = os.path.join(PACKAGE, 'src', 'rason_bridge')


def recorded(**given):
    asked = []

    def get_param(name, default):
        asked.append((name, default))
        return given.get(name, default)
    return read_settings(get_param, '/home/robot/.ros'), asked


def test_the_committed_reference_is_what_the_schema_renders():
    with open(os.path.join(PACKAGE, 'PARAMETERS.md')) as f:
        committed = f.read()
    assert committed == render_markdown(), \
        'run: PYTHONPATH=src/rason_bridge/src python3 -m rason_bridge.params > src/rason_bridge/PARAMETERS.md'


def test_the_reference_has_one_row_a_parameter_with_its_default():
    rows = [l for l in render_markdown().splitlines() if l.startswith('| `')]
    assert [re.match(r'\| `(\w+)`', r).group(1) for r in rows] == [p.name for p in PARAMS]
    assert '| `action_timeout` | float | `60.0` | s (ROS time) |' in render_markdown()


def test_reading_asks_for_every_schema_parameter_once_with_its_default():
    settings, asked = recorded()
    assert [name for name, _ in asked] == [p.name for p in PARAMS]
    assert len(set(name for name, _ in asked)) == len(asked)
    assert dict(asked) == {p.name: p.default for p in PARAMS}
    assert set(Settings._fields) == set(dict(asked))
    assert settings.fleet_key_file == '/home/robot/.ros/rason/fleet.key'


def _private_param_reads(path):
    with open(path) as f:
        text = f.read()
    return re.findall(r"get_param\(\s*['\"]([^'\"]+)['\"]\s*[,)]", text), 'read_settings(' in text


def test_the_node_reads_its_private_parameters_only_through_the_schema():
    # every ~param read by name outside the schema would bypass its check and its reference row
    read_by_name = {}
    through_schema = []
    for module in sorted(os.listdir(MODULES)):
        if module.endswith('.py') and module != 'params.py':
            names, calls_schema = _private_param_reads(os.path.join(MODULES, module))
            if names:
                read_by_name[module] = names
            if calls_schema:
                through_schema.append(module)
    assert read_by_name == {'inbound.py': ['/use_sim_time']}  # a global parameter, not the node's
    assert through_schema == ['cds_build.py', 'mas_node.py']
    with open(os.path.join(MODULES, 'mas_node.py')) as f:
        assert "read_settings(lambda name, default: rospy.get_param('~' + name, default)" in f.read()
    with open(os.path.join(MODULES, 'cds_build.py')) as f:  # the build's warm-up: the defaults, no parameter
        assert 'read_settings(lambda name, default: default,' in f.read()


def test_every_default_is_allowed_and_typed():
    settings, _ = recorded()
    for p in PARAMS:
        value = getattr(settings, p.name)
        if p.type_name == 'float':
            assert isinstance(value, float), p.name
        elif p.type_name == 'int':
            assert isinstance(value, int) and not isinstance(value, bool), p.name
    assert settings.trust == [] and settings.fleet_key is None and settings.presence_beliefs is True


def test_whole_numbers_of_seconds_become_floats():
    settings, _ = recorded(action_timeout=5, connect_wait=0, auth_window=10)
    assert (settings.action_timeout, settings.connect_wait, settings.auth_window) == (5.0, 0.0, 10.0)
    assert all(isinstance(v, float) for v in (settings.action_timeout, settings.connect_wait))


@pytest.mark.parametrize('name, value, text', [
    ('connect_wait', -1, 'connect_wait must be 0 s or more, not -1'),
    ('shutdown_grace', -0.5, 'shutdown_grace must be 0 s or more, not -0.5'),
    ('decomposer_grace', -1.0, 'decomposer_grace must be 0 s or more, not -1.0'),
    ('action_timeout', math.inf, 'action_timeout must be a finite number of seconds up to 1e+09, not inf'),
    ('ask_timeout', 'long', "ask_timeout must be a number of seconds, not 'long'"),
    ('presence_beliefs', 'yes', "presence_beliefs must be true or false, not 'yes'"),
    ('messages_topic', 3, 'messages_topic must be a topic name, not 3'),
    ('mind_max_chars', 15, 'mind_max_chars must be a whole number from 16 to 100000, not 15'),
    ('fleet_auth', 'yes', "fleet_auth must be 'required' or 'off', not 'yes'"),
    ('fleet_key_file', 7, 'fleet_key_file must be a path, not 7'),
    ('trust', 'all', "trust must map agent names (or '*') to rules, not 'all'"),
    ('fleet_channel', 'zmq', "fleet_channel must be `ros` or `mqtt`, not 'zmq'"),
    ('mqtt_url', 'localhost:1883', "mqtt_url must be `tcp://HOST:PORT` or `ssl://HOST:PORT` (TLS), not 'localhost:1883'"),
    ('mqtt_prefix', 'rason/+/', "mqtt_prefix must be a topic prefix without `+` or `#`, not 'rason/+/'"),
    ('message_ttl', 0.5, 'message_ttl must be a whole number of seconds, 1 or more, not 0.5'),
    ('message_ttl', 1.5, 'message_ttl must be a whole number of seconds, 1 or more, not 1.5'),
])
def test_a_bad_value_is_one_line_naming_parameter_value_and_what_is_allowed(name, value, text):
    with pytest.raises(ParamError) as e:
        recorded(**{name: value})
    assert str(e.value) == text
    assert '\n' not in str(e.value)


@pytest.mark.parametrize('period, timeout', [(0.5, 0.5), (0, 2.0), (-1, 2.0), (3.0, 2.0)])
def test_presence_timeout_must_exceed_a_positive_period(period, timeout):
    with pytest.raises(ParamError, match=re.escape('presence_timeout (%s s) must be longer than presence_period '
                                                   '(%s s) > 0' % (float(timeout), float(period)))):
        recorded(presence_period=period, presence_timeout=timeout)


def test_yaml_booleans_are_fleet_auth_modes():
    assert recorded(fleet_auth=False)[0].fleet_auth == 'off'
    assert recorded(fleet_auth=True)[0].fleet_auth == 'required'


def test_the_schema_alone_writes_the_defaults():
    # the node and its helpers take the settings; no module but the schema names a default of its own
    for module in ('mas_node.py', 'java_config.py', 'fleet_auth.py', 'mind.py', 'trust.py'):
        with open(os.path.join(MODULES, module)) as f:
            text = f.read()
        assert not re.search(r"get_param\('~\w", text), module
        assert 'DEFAULT' not in text, module
    assert params.MAX_SECONDS == 1e9
