"""robot_guide_node's private parameters, checked, and its frame names. No ROS.

Frames follow the simulator's (and a tf_prefix's) naming: a robot's frames are
``<robot>/odom``, ``<robot>/base_footprint``, ``<robot>/camera_rgb_optical_frame``. A
relative ``~odom_frame`` (default ``odom``) is put under the node's namespace
(``/helper/`` -> ``helper/odom``); one with a leading ``/`` is taken as it is (without the
slash, which tf2 frames never have). ``~camera_frame`` empty (default) means the frame of
each sightings message (vision_synth copies the cloud's, e.g. ``helper/camera_rgb_optical_frame``).
"""
import math

from rason_wiring import terms

#: The parameters (``~name``) and their defaults.
DEFAULTS = {
    'odom_frame': 'odom',
    'camera_frame': '',
    'tf_timeout': 0.2,        # s (ROS time) to wait for the camera's pose at a cloud's stamp
    'max_rate': 5.0,          # Hz at most of the located(...) perception; 0: every frame
    'rate': 20.0,             # Hz (ROS time) of guide's turn commands and checks
    'centre_deadband': 3.0,   # degrees: a robot this near the centre needs no turn
    'centre_gain': 3.0,       # rad/s per rad of angle
    'angular_speed': 0.4,     # rad/s at most
    'lost_after': 2.0,        # s (ROS time) without seeing the guided robot: fails lost
    'source': '',             # perception source; empty: <node name>_located
}

_POSITIVE = ('tf_timeout', 'rate', 'centre_gain', 'angular_speed', 'lost_after')
_NOT_NEGATIVE = ('max_rate', 'centre_deadband')


class BadSetting(ValueError):
    """A parameter the node cannot run with (says which and why)."""


def resolve_frame(frame, namespace):
    """A tf2 frame name: ``frame`` under ``namespace`` unless it starts with ``/``.

    :param frame: e.g. ``odom`` or ``/world``; empty stays empty
    :param namespace: the node's namespace, e.g. ``/helper/`` (``/`` at the root)
    """
    frame = frame.strip()
    if not frame or frame.startswith('/'):
        return frame.lstrip('/')
    prefix = namespace.strip('/')
    return '%s/%s' % (prefix, frame) if prefix else frame


def default_source(node_name):
    """``<node name>_located`` (``/helper/robot_guide`` -> ``robot_guide_located``)."""
    return node_name.rstrip('/').rsplit('/', 1)[-1] + '_located'


def check(values, namespace, node_name):
    """The settings, checked and completed.

    :param values: parameter name -> value (those of :data:`DEFAULTS`, as ROS gave them)
    :param namespace: the node's namespace (for the frames)
    :param node_name: the node's resolved name (for the default source)
    :rtype: dict with the keys of :data:`DEFAULTS`
    :raises BadSetting: a number that is not finite or out of range, a frame or source that
        is not text, no odometry frame, a source that is not a Jason atom
    """
    out = dict(DEFAULTS)
    out.update(values)
    for key in _POSITIVE + _NOT_NEGATIVE:
        value = out[key]
        if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
            raise BadSetting('~%s: a finite number is needed, not %r' % (key, value))
        if key in _POSITIVE and value <= 0 or value < 0:
            raise BadSetting('~%s: must be %s, not %r'
                             % (key, 'positive' if key in _POSITIVE else '>= 0', value))
        out[key] = float(value)
    for key in ('odom_frame', 'camera_frame', 'source'):
        if not isinstance(out[key], str):
            raise BadSetting('~%s: a name is needed, not %r' % (key, out[key]))
    if not out['odom_frame'].strip('/ '):
        raise BadSetting('~odom_frame: a frame name is needed')
    out['odom_frame'] = resolve_frame(out['odom_frame'], namespace)
    out['camera_frame'] = resolve_frame(out['camera_frame'], namespace)
    out['source'] = out['source'].strip() or default_source(node_name)
    if not terms.is_atom(out['source']):
        raise BadSetting('~source: %r is not a Jason atom' % out['source'])
    return out
