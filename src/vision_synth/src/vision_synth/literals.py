"""Jason literals for the perceptions this synthesizer publishes. No ROS.

``robot(Name, Angle, Depth, Yaw)``: Name an atom, Angle and Yaw degrees with 2 decimals,
Depth metres with 3 decimals, e.g. ``robot(faulty,-3.52,1.503,12.4)``. Trailing zeros are
dropped (``1.5``, ``0``), there is never ``-0`` and never an exponent, NaN or infinity;
a Yaw that rounds to -180 is written 180.

``cameraFrame(N, T)``: N counts the clouds the node processed (1, 2, ...), T is when the
cloud was taken (its stamp, ms of ROS time), one literal in every message, so an agent can
tell a new frame from the same one read twice (the values of a still robot repeat exactly)
and a frame taken after its robot stopped from one the pipeline still held (a busy CPU
can hold the camera for seconds).
"""
import math
import re

_ATOM = re.compile(r'[a-z][A-Za-z0-9_]*\Z')

ANGLE_DECIMALS = 2
DEPTH_DECIMALS = 3


def is_atom(name):
    """True if ``name`` is a Jason atom that needs no quotes (``faulty``, ``robot_2``).

    :param name: str
    :rtype: bool
    """
    return isinstance(name, str) and _ATOM.match(name) is not None


def format_number(value, decimals):
    """A finite number in Jason syntax, rounded to ``decimals`` decimals.

    :param value: number
    :param decimals: digits after the point (>= 0)
    :rtype: str
    :raises ValueError: NaN or infinite value
    """
    value = float(value)
    if not math.isfinite(value):
        raise ValueError('not a finite number: %r' % value)
    text = '%.*f' % (decimals, value)
    if '.' in text:
        text = text.rstrip('0').rstrip('.')
    if text in ('-0', ''):
        text = '0'
    return text


def robot_literal(name, angle, depth, yaw):
    """The perception ``robot(Name, Angle, Depth, Yaw)``.

    :param name: the robot's agent name, a Jason atom
    :param angle: degrees, negative = left
    :param depth: metres
    :param yaw: degrees
    :rtype: str
    :raises ValueError: name not an atom, or a value not finite
    """
    if not is_atom(name):
        raise ValueError('robot name %r is not a Jason atom (lower-case letter, then letters, '
                         'digits, _)' % (name,))
    yaw_text = format_number(yaw, ANGLE_DECIMALS)
    if yaw_text == '-180':  # keep the rounded Yaw in (-180, 180]
        yaw_text = '180'
    return 'robot(%s,%s,%s,%s)' % (name, format_number(angle, ANGLE_DECIMALS),
                                   format_number(depth, DEPTH_DECIMALS), yaw_text)


def frame_literal(count, stamp_ms):
    """The perception ``cameraFrame(N, T)``: the ``count``-th cloud processed, taken at
    ``stamp_ms`` (its header's stamp, whole milliseconds of ROS time).

    :param count: int >= 1
    :param stamp_ms: int >= 0
    :rtype: str
    :raises ValueError: count not a positive int, or stamp_ms not an int >= 0
    """
    if not isinstance(count, int) or isinstance(count, bool) or count < 1:
        raise ValueError('frame count must be a positive int, got %r' % (count,))
    if not isinstance(stamp_ms, int) or isinstance(stamp_ms, bool) or stamp_ms < 0:
        raise ValueError('frame stamp must be an int >= 0 (ms), got %r' % (stamp_ms,))
    return 'cameraFrame(%d,%d)' % (count, stamp_ms)
