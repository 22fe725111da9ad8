"""Every ``~param`` of the rason_mas node: its type, default, unit, what is allowed and what it
does, written once here; reading and checking them; no rospy.

:func:`read_settings` asks ``get_param(name, default)`` for each parameter of :data:`PARAMS`
and returns a :data:`Settings` of checked, typed values (or raises :class:`ParamError`, whose
text names the parameter, the value and what is allowed). ``PARAMETERS.md`` is
:func:`render_markdown` of this table.
"""
import collections
import math
import os
import re

from rason_bridge.fleet_auth import OFF, REQUIRED, default_key_file
from rason_bridge.mqtt_url import parse_mqtt_url
from rason_bridge.trust import trust_rules

#: An agent name: a Jason atom.
_ATOM = re.compile(r'^[a-z][A-Za-z0-9_]*$')

#: The longest duration a ~param may give (s): about 31 years, far inside Java's long nanoseconds.
MAX_SECONDS = 1e9

class ParamError(ValueError):
    """A ~param value that cannot be used; the text names the parameter, the value and what is allowed."""


def seconds_to_nanos(name, seconds):
    """A duration in seconds as whole nanoseconds for Java.

    :raises ParamError: not a number, not finite or beyond :data:`MAX_SECONDS` either way,
        naming the parameter (``int(inf)`` would raise OverflowError, and a Java long
        cannot hold more than 292 years)
    """
    if isinstance(seconds, bool) or not isinstance(seconds, (int, float)):
        raise ParamError('%s must be a number of seconds, not %r' % (name, seconds))
    if not math.isfinite(seconds) or abs(seconds) > MAX_SECONDS:
        raise ParamError('%s must be a finite number of seconds up to %g, not %r' % (name, MAX_SECONDS, seconds))
    return int(round(seconds * 1e9))


class Param(object):
    """One ~param: ``check(name, value)`` returns the typed value or raises ParamError.

    :param allowed: what may be given, as the reference and the error message say it
    :param shown_default: the default as the reference shows it, when not the value itself
    """

    def __init__(self, name, type_name, default, unit, allowed, doc, check, shown_default=None):
        self.name, self.type_name, self.default, self.unit = name, type_name, default, unit
        self.allowed, self.doc, self._check = allowed, doc, check
        self.shown_default = shown_default

    def check(self, value):
        return self._check(self, value)

    def refuse(self, value):
        raise ParamError('%s must be %s, not %r' % (self.name, self.allowed, value))


def _seconds(low=None):
    def check(param, value):
        seconds_to_nanos(param.name, value)
        if low is not None and not value >= low:
            param.refuse(value)
        return float(value)
    return check


def _whole(low, high=None):
    def check(param, value):
        if isinstance(value, bool) or not isinstance(value, int) or value < low \
                or (high is not None and value > high):
            param.refuse(value)
        return value
    return check


def _flag(param, value):
    if not isinstance(value, bool):
        param.refuse(value)
    return value


def _text(param, value):
    if not isinstance(value, str):
        param.refuse(value)
    return value


def _fleet_auth(param, value):
    # YAML (rosrun's _fleet_auth:=off, rosparam) reads an unquoted off as false and on as true
    value = {False: OFF, True: REQUIRED}.get(value, value) if isinstance(value, bool) else value
    if value not in (REQUIRED, OFF):
        param.refuse(value)
    return value


def _fleet_key(param, value):
    if value is not None and not isinstance(value, str):
        raise ParamError('fleet_key must be a string (quote it), not %s' % type(value).__name__)
    return value or None


def _key_file(param, value):
    if value is not None and not isinstance(value, str):
        param.refuse(value)
    return os.path.expanduser(value) if value else None  # None: the default under ROS_HOME


def _names(param, value):
    if not isinstance(value, list) or not all(isinstance(n, str) and _ATOM.match(n) for n in value):
        param.refuse(value)
    return list(value)


#: ``fleet_channel`` values: the ROS topics of one master, or an MQTT broker.
ROS, MQTT = 'ros', 'mqtt'


def _choice(*allowed):
    def check(param, value):
        if value not in allowed:
            param.refuse(value)
        return value
    return check


def _optional_path(param, value):
    if value is None or value == '':
        return ''
    if not isinstance(value, str):
        param.refuse(value)
    return os.path.expanduser(value)


def _paths(param, value):
    # a list, or one string as a Java class path is written (os.pathsep between entries)
    if isinstance(value, str):
        value = value.split(os.pathsep)
    if not isinstance(value, list) or not all(isinstance(p, str) for p in value):
        param.refuse(value)
    return [p.strip() for p in value if p.strip()]


def _mqtt_url(param, value):
    try:
        parse_mqtt_url(value)
    except ValueError:
        param.refuse(value)
    return value


def _mqtt_prefix(param, value):
    if not isinstance(value, str) or '+' in value or '#' in value or '\0' in value:
        param.refuse(value)
    return value


def _trust(param, value):
    try:
        return trust_rules(value)
    except ValueError as e:
        raise ParamError(str(e))


def _limit(name, default, what):
    return Param(name, 'int', default, '', 'a whole number of at least 1', what, _whole(1))


_OFF_IF_ZERO = 'a finite number of seconds up to 1e9 (0: off)'

#: Every ~param rason_mas reads, in the reference's order.
PARAMS = (
    Param('action_timeout', 'float', 60.0, 's (ROS time)', _OFF_IF_ZERO,
          'time without feedback before an action fails `timeout`', _seconds()),
    Param('perception_ttl', 'float', 2.0, 's (ROS time)', _OFF_IF_ZERO,
          'time after which a source that stopped publishing is forgotten', _seconds()),
    Param('connect_wait', 'float', 2.0, 's (wall clock)', '0 s or more',
          'how long an action waits for decomposers that are registered but not yet connected, '
          'and a message for a robot just heard of for the link to it', _seconds(0)),
    Param('shutdown_grace', 'float', 0.5, 's (wall clock)', '0 s or more',
          'time the agents get to run their `-!` plans for actions failed by `shutdown` '
          '(the cancels of pending actions go out meanwhile)', _seconds(0)),
    Param('decomposer_grace', 'float', 0.5, 's (wall clock)', '0 s or more',
          'time the node that took an action may have no `jason/event` link before the action fails '
          '`decomposer_lost`', _seconds(0)),
    Param('perception_manager', 'str', 'per_source', '', '`per_source`, `accumulate` or a Java class name',
          'perception strategy of agents whose `.mas2j` names none', _text),
    Param('classpath', 'list', [], '', 'a list of paths, or one string of paths separated by `%s`' % os.pathsep,
          'the project\'s own Java classes (internal actions, belief bases, agent classes, environment): '
          'folders and jars (`lib/*.jar` patterns too), relative to the `.mas2j`\'s folder; '
          'not given: `build/classes/java/main`, `build/resources/main`, `bin/classes` and `lib/*.jar` '
          'there, those that exist (see docs/guides/agents.md)', _paths, shown_default='[]'),
    Param('agent_prefix', 'str', '', '', 'a Jason atom start (lower-case letter, then letters, digits, `_`)',
          'prepended to every agent name of the project', _text),
    Param('messages_topic', 'str', '/rason/messages', '', 'a topic name',
          'topic shared by all robots for agent messages', _text),
    Param('presence_topic', 'str', '/rason/presence', '', 'a topic name',
          'topic shared by all robots for presence', _text),
    Param('pulse_topic', 'str', '/rason/pulse', '', 'a topic name',
          'topic shared by all robots for pulses (signs of life on a connection apart from presence\'s)', _text),
    Param('presence_period', 'float', 0.5, 's (wall clock)', 'more than 0 s',
          'time between presence announcements', _seconds()),
    Param('presence_timeout', 'float', 2.0, 's (wall clock)', 'more than presence_period',
          'silence after which another process has left', _seconds()),
    Param('presence_beliefs', 'bool', True, '', 'true or false',
          'agents perceive `present(Name)`', _flag),
    Param('ask_timeout', 'float', 60.0, 's (ROS time)', _OFF_IF_ZERO,
          'how long a synchronous ask to a remote agent may wait without Jason\'s own timeout', _seconds()),
    Param('trust', 'map', {}, '', 'agent (or `*`) -> performative group -> `all`, `none` or agent names',
          'which agents of other robots may send what to the agents hosted here', _trust, shown_default='{}'),
    Param('await_agents', 'list', [], '', 'a list of agent names (Jason atoms)',
          'the agents (of any robot) that must be present before this node starts its agents',
          _names, shown_default='[]'),
    Param('await_robots', 'int', 0, '', 'a whole number, 0 or more',
          'how many other rason_mas processes must be reachable before this node starts its agents',
          _whole(0)),
    Param('await_timeout', 'float', 30.0, 's (wall clock)', 'more than 0 s',
          'how long the node holds its agents for `await_agents`/`await_robots`; then they start anyway '
          '(with a warning naming what is missing)', _seconds(1e-9)),
    Param('expected_sources', 'list', [], '', 'a list of perception sources (Jason atoms)',
          'the perception sources the agents need: each not heard within `expect_within` of the agents\' start '
          'is named once in a warning', _names, shown_default='[]'),
    Param('expect_within', 'float', 10.0, 's (wall clock)', 'more than 0 s',
          'how long `expected_sources` may stay silent after the agents start', _seconds(1e-9)),
    Param('warning_period', 'float', 10.0, 's (wall clock)', 'more than 0 s',
          'the period of the rate-limited warnings about dropped input, refused messages and ignored events: '
          'at most 10 lines of a kind per period, then one line saying how many more there were',
          _seconds(1e-9)),
    _limit('max_literal_length', 4096, 'characters of one literal'),
    _limit('max_content_length', 65536, 'characters of one message\'s content'),
    _limit('max_nesting', 32, 'brackets open at once'),
    _limit('max_term_depth', 512, 'levels of one term'),
    _limit('max_literals', 1000, 'literals in one `jason/perception` message'),
    _limit('max_sources', 100, 'perception sources remembered at once'),
    Param('fleet_auth', 'str', REQUIRED, '', "'required' or 'off'",
          '`required`: sign everything, drop what is not authentic; `off`: neither', _fleet_auth),
    Param('fleet_key_file', 'str', None, '', 'a path',
          'the fleet key file', _key_file, shown_default='$ROS_HOME/rason/fleet.key'),
    Param('fleet_key', 'str', None, '', 'a string',
          'the key itself (one key per line) instead of a file; readable by anyone who reaches the master',
          _fleet_key, shown_default='none'),
    Param('auth_window', 'float', 60.0, 's', 'a number of seconds, 0 or more (0: no clock checks)',
          'how far a stamp may be from this robot\'s clock', _seconds(0)),
    Param('fleet_channel', 'str', ROS, '', '`ros` or `mqtt`',
          'how this process reaches the others: `ros`: the messages and presence topics of this master; '
          '`mqtt`: an MQTT 5 broker (`mqtt_*`), from Java (see docs/guides/fleet-channel.md)', _choice(ROS, MQTT)),
    Param('mqtt_url', 'str', 'tcp://127.0.0.1:1883', '', '`tcp://HOST:PORT` or `ssl://HOST:PORT` (TLS)',
          'the broker, with `fleet_channel: mqtt`', _mqtt_url),
    Param('mqtt_prefix', 'str', 'rason/', '', 'a topic prefix without `+` or `#`',
          'what every fleet topic on the broker starts with (a fleet per prefix)', _mqtt_prefix),
    Param('message_ttl', 'float', 60.0, 's (wall clock)', 'a whole number of seconds, 1 or more',
          'how long a message to an agent of another process may take: the sending intention waits for the '
          'receiver\'s receipt this long, then fails with `error(undelivered)`; over MQTT also how long the broker '
          'keeps the message (and our session) for a process that is away',
          _seconds(1)),
    Param('mqtt_username', 'str', '', '', 'a string', 'the broker user; empty: none', _text, shown_default="''"),
    Param('mqtt_password_file', 'str', '', '', 'a path',
          'a file whose first line is the broker user\'s password; empty: none', _optional_path,
          shown_default="''"),
    Param('mqtt_ca_file', 'str', '', '', 'a path',
          'PEM certificates that sign the broker\'s TLS certificate (`ssl://`); empty: the JVM\'s trust store',
          _optional_path, shown_default="''"),
    Param('mind_period', 'float', 0.5, 's (wall clock)', '0 (off) or more seconds',
          'time between two readings of a running agent\'s state for `jason/mind`; 0: no `jason/mind`',
          _seconds(0)),
    Param('mind_max_items', 'int', 200, '', 'a whole number from 1 to 10000',
          'entries of one list of a `jason/mind` snapshot', _whole(1, 10000)),
    Param('mind_max_chars', 'int', 500, '', 'a whole number from 16 to 100000',
          'characters of one entry of a `jason/mind` snapshot', _whole(16, 100000)),
)

BY_NAME = collections.OrderedDict((p.name, p) for p in PARAMS)

#: The checked values, one field a parameter; ``trust`` as ``(agent, group, who)`` rules,
#: ``fleet_key`` None when not given, ``fleet_key_file`` the file to read.
Settings = collections.namedtuple('Settings', list(BY_NAME))


def read_settings(get_param, ros_home):
    """Read and check every parameter.

    :param get_param: ``get_param(name, default)``, e.g. ``lambda n, d: rospy.get_param('~' + n, d)``
    :param ros_home: where the default fleet key file is (see :func:`default_key_file`)
    :rtype: Settings
    :raises ParamError: the first value that cannot be used
    """
    values = {p.name: p.check(get_param(p.name, p.default)) for p in PARAMS}
    if not values['presence_period'] > 0 or not values['presence_timeout'] > values['presence_period']:
        raise ParamError('presence_timeout (%s s) must be longer than presence_period (%s s) > 0'
                         % (values['presence_timeout'], values['presence_period']))
    if values['fleet_key'] and values['fleet_key_file']:
        raise ParamError('set fleet_key or fleet_key_file, not both')
    if values['message_ttl'] != int(values['message_ttl']):
        raise ParamError('message_ttl must be a whole number of seconds, 1 or more, not %r' % values['message_ttl'])
    if values['fleet_key_file'] is None:
        values['fleet_key_file'] = default_key_file(ros_home)
    return Settings(**values)


def _shown(value):
    if isinstance(value, bool):
        return str(value).lower()  # as YAML writes it
    return repr(value) if value == '' else value


def _cell(text):
    return str(text).replace('|', '\\|')


def render_markdown():
    """The parameter reference (``src/rason_bridge/PARAMETERS.md``) as Markdown."""
    lines = ['# rason_mas parameters', '',
             'Private parameters (`~name`) of the `rason_mas` node, generated from',
             '`src/rason_bridge/src/rason_bridge/params.py`; do not edit by hand, run',
             '`PYTHONPATH=src/rason_bridge/src python3 -m rason_bridge.params > src/rason_bridge/PARAMETERS.md`.',
             'A value that is not allowed stops the node with exit status 1 and one line',
             '`bad parameter: NAME must be ALLOWED, not VALUE`.', '',
             '| name | type | default | unit | allowed | meaning |',
             '|---|---|---|---|---|---|']
    for p in PARAMS:
        default = p.shown_default if p.shown_default is not None else _shown(p.default)
        lines.append('| `%s` | %s | `%s` | %s | %s | %s |' % (
            p.name, p.type_name, _cell(default), p.unit, _cell(p.allowed), _cell(p.doc)))
    return '\n'.join(lines) + '\n'


if __name__ == '__main__':
    print(render_markdown(), end='')
