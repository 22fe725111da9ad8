"""Fleet authentication, Python's part (signing and checking are Java's rason.messaging.FleetAuth
and FleetKeys): its modes, where the key is by default, what to do without one, and the uint64
fields of the messages as Java longs; no rospy. Its ~params are in :mod:`rason_bridge.params`."""
import os

REQUIRED = 'required'
OFF = 'off'


def default_key_file(ros_home):
    """``<ros_home>/rason/fleet.key`` (``ros_home``: ``rospkg.get_ros_home()``, i.e. $ROS_HOME or ~/.ros)."""
    return os.path.join(ros_home, 'rason', 'fleet.key')


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
