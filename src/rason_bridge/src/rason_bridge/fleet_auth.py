"""The ~params of fleet authentication (Java's rason.messaging.FleetAuth and FleetKeys); no rospy.

``~fleet_auth``: ``required`` (default) or ``off``; ``~fleet_key_file``: the key file
(default ``$ROS_HOME/rason/fleet.key``); ``~fleet_key``: the key itself, instead of a file;
``~auth_window``: seconds a stamp may be from this robot's clock (0: no clock checks).
"""
import collections
import numbers
import os

from rason_bridge.limits import seconds_to_nanos

REQUIRED = 'required'
OFF = 'off'
DEFAULT_WINDOW = 60.0

#: What :func:`auth_settings` read: ``key_text`` is None unless ~fleet_key is set.
AuthSettings = collections.namedtuple('AuthSettings', 'mode key_file key_text window')


def default_key_file(ros_home):
    """``<ros_home>/rason/fleet.key`` (``ros_home``: ``rospkg.get_ros_home()``, i.e. $ROS_HOME or ~/.ros)."""
    return os.path.join(ros_home, 'rason', 'fleet.key')


def auth_settings(get_param, ros_home):
    """Read and check the parameters.

    :param get_param: ``get_param(name, default)``, e.g. ``lambda n, d: rospy.get_param('~' + n, d)``
    :param ros_home: where the default key file is (see :func:`default_key_file`)
    :rtype: AuthSettings
    :raises ValueError: a value that cannot be used, naming the parameter
    """
    mode = get_param('fleet_auth', REQUIRED)
    # YAML (rosrun's _fleet_auth:=off, rosparam) reads an unquoted off as false and on as true
    if mode is False:
        mode = OFF
    elif mode is True:
        mode = REQUIRED
    if mode not in (REQUIRED, OFF):
        raise ValueError("fleet_auth must be '%s' or '%s', not %r" % (REQUIRED, OFF, mode))
    window = get_param('auth_window', DEFAULT_WINDOW)
    if isinstance(window, bool) or not isinstance(window, numbers.Real) or not window >= 0:
        raise ValueError('auth_window must be a number of seconds, 0 or more (0: no clock checks), not %r' % (window,))
    seconds_to_nanos('auth_window', window)  # infinite or beyond a Java long: refused here, not at start
    key_text = get_param('fleet_key', None)
    if key_text is not None and not isinstance(key_text, str):
        raise ValueError('fleet_key must be a string (quote it), not %s' % type(key_text).__name__)
    key_text = key_text or None
    key_file = get_param('fleet_key_file', None)
    if key_file is not None and not isinstance(key_file, str):
        raise ValueError('fleet_key_file must be a path, not %r' % (key_file,))
    if key_text and key_file:
        raise ValueError('set fleet_key or fleet_key_file, not both')
    key_file = os.path.expanduser(key_file) if key_file else default_key_file(ros_home)
    return AuthSettings(mode, key_file, key_text, float(window))


def no_key_help(settings):
    """What to do when authentication is required and no key could be loaded (for the fatal line)."""
    if settings.key_text is not None:
        return 'fix ~fleet_key (one key per line, at least 32 bytes each), or use ~fleet_key_file'
    return ('make a key with `rosrun rason_bridge fleet_key %s` and put the same file on every robot of the fleet '
            '(`make setup` makes build/ros_home/rason/fleet.key), or point ~fleet_key_file at your key file; '
            'only on a trusted lab network, set ~fleet_auth to off' % settings.key_file)


def to_int64(value):
    """A uint64 field as the signed 64-bit integer with the same bits (Java's long)."""
    value = int(value) & 0xFFFFFFFFFFFFFFFF
    return value - (1 << 64) if value >= 1 << 63 else value


def to_uint64(value):
    """A Java long as the uint64 with the same bits."""
    return int(value) & 0xFFFFFFFFFFFFFFFF
