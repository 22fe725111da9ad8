"""Fleet authentication, Python's part (signing and checking are Java's rason.messaging.FleetAuth
and FleetKeys): its modes, where the key is by default, what to do without one, and the uint64
fields of the messages as Java longs; no rospy. Its ~params are in :mod:`rason_bridge.params`."""
import os

REQUIRED = 'required'
OFF = 'off'


def default_key_file(ros_home):
    """``<ros_home>/rason/fleet.key`` (``ros_home``: ``rospkg.get_ros_home()``, i.e. $ROS_HOME or ~/.ros)."""
    return os.path.join(ros_home, 'rason', 'fleet.key')


def first_run_key(settings, default_file, make_key):
    """A robot started with no fleet: with authentication required, no ``~fleet_key``, the key
    file the default one (:func:`default_key_file`) and no file there, a new key is made there
    (so one robot runs without a set-up step) and the line to log is returned; else None (another
    file that is missing stays an error: it names a fleet's key that is not there).

    :param settings: :data:`rason_bridge.params.Settings`
    :param default_file: :func:`default_key_file` of this process
    :param make_key: ``make_key(path)`` writes a new key file (:func:`rason_bridge.fleet_key.write_key`)
    """
    path = settings.fleet_key_file
    if settings.fleet_auth == OFF or settings.fleet_key is not None or path != default_file or os.path.exists(path):
        return None
    try:
        make_key(path)
    except OSError:
        return None     # the missing key's fatal line then names the file
    return ('no fleet key yet: made a new one at %s (mode 0600). This robot talks only to robots with the same '
            'key: copy this file to the same place on each of them (or point their ~fleet_key_file at it), '
            'or copy theirs here (docs: Security)' % path)


def no_key_help(settings):
    """What to do when authentication is required and no key could be loaded (for the fatal line).

    :param settings: :data:`rason_bridge.params.Settings`
    """
    if settings.fleet_key is not None:
        return 'fix ~fleet_key (one key per line, at least 32 bytes each), or use ~fleet_key_file'
    return ('make a key with `rosrun rason_bridge fleet_key %s` and put the same file on every robot of the fleet '
            '(`make setup` makes build/ros_home/rason/fleet.key), or point ~fleet_key_file at your key file; '
            'only on a trusted lab network, set ~fleet_auth to off' % settings.fleet_key_file)


def to_int64(value):
    """A uint64 field as the signed 64-bit integer with the same bits (Java's long)."""
    value = int(value) & 0xFFFFFFFFFFFFFFFF
    return value - (1 << 64) if value >= 1 << 63 else value


def to_uint64(value):
    """A Java long as the uint64 with the same bits."""
    return int(value) & 0xFFFFFFFFFFFFFFFF
