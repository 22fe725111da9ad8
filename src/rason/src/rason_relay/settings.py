"""The topic relay's parameters, checked, and the broker topic of each relayed ROS topic."""
import collections

from rason_bridge.mqtt_url import parse_mqtt_url

Settings = collections.namedtuple('Settings', 'robot host port tls prefix username password_file ca_file '
                                              'send receive max_bytes max_age max_rate')

DEFAULT_URL = 'tcp://127.0.0.1:1883'
DEFAULT_PREFIX = 'rason/'


class SettingsError(ValueError):
    """A parameter the relay cannot run with; the message names it and what is valid."""


def broker_topic(prefix, ros_name):
    """``rason/topics/helper/located/faulty`` for ``/helper/located/faulty``."""
    return prefix + 'topics' + ros_name


def _topics(param, value, resolve):
    if value is None:
        return ()
    if isinstance(value, str):
        value = value.split()
    if not isinstance(value, (list, tuple)) or not all(isinstance(v, str) and v for v in value):
        raise SettingsError('~%s must be a list of ROS topic names, not %r' % (param, value))
    names = tuple(dict.fromkeys(resolve(v) for v in value))
    for name in names:
        if any(c in name for c in '+#\0') or '//' in name:
            raise SettingsError('~%s: %r cannot name a broker topic (no +, # or empty levels)' % (param, name))
    return names


def parse_settings(params, resolve, default_robot):
    """:class:`Settings` from the node's private parameters (a dict).

    :param resolve: turns a relative topic name into the global one (rospy.resolve_name)
    :param default_robot: the sender name when ``~robot`` is not given (the node's namespace)
    :raises SettingsError: with the parameter and what it may be
    """
    try:
        broker = parse_mqtt_url(params.get('mqtt_url', DEFAULT_URL))
    except ValueError as e:
        raise SettingsError('~mqtt_url ' + str(e))
    prefix = params.get('mqtt_prefix', DEFAULT_PREFIX)
    if not isinstance(prefix, str) or any(c in prefix for c in '+#\0'):
        raise SettingsError('~mqtt_prefix %r: a topic prefix without +, # or NUL' % (prefix,))
    if prefix and not prefix.endswith('/'):
        prefix += '/'
    send = _topics('send', params.get('send'), resolve)
    receive = _topics('receive', params.get('receive'), resolve)
    both = sorted(set(send) & set(receive))
    if both:
        raise SettingsError('%s both in ~send and ~receive: the relay would echo its own messages'
                            % ', '.join(both))
    numbers = {}
    for name, default, least in (('max_bytes', 65536, 1), ('max_age', 5.0, 1e-9), ('max_rate', 0.0, 0.0)):
        value = params.get(name, default)
        if isinstance(value, bool) or not isinstance(value, (int, float)) or not value >= least:
            raise SettingsError('~%s must be a number of at least %g, not %r' % (name, least, value))
        numbers[name] = value
    robot = params.get('robot', default_robot)
    if not isinstance(robot, str) or not robot:
        raise SettingsError('~robot must be a non-empty name, not %r' % (robot,))
    return Settings(robot=robot, host=broker.host, port=broker.port, tls=broker.tls, prefix=prefix,
                    username=str(params.get('mqtt_username', '')),
                    password_file=str(params.get('mqtt_password_file', '')),
                    ca_file=str(params.get('mqtt_ca_file', '')), send=send, receive=receive,
                    max_bytes=int(numbers['max_bytes']), max_age=float(numbers['max_age']),
                    max_rate=float(numbers['max_rate']))
