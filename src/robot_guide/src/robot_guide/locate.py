"""Where a seen robot is in the seeing robot's odometry frame. No ROS.

A sighting (``rason_msgs/RobotSighting``, vision_synth's ``robot(Name, Angle, Depth, Yaw)``)
is relative to the camera, in vision_synth's conventions (its ``geometry.py``):

- the camera's optical frame has ``x`` right, ``y`` down, ``z`` forward, and looks
  horizontally, so its ground plane is ``(x, z)``;
- **Angle** θ (degrees, CLOCKWISE-positive: positive = right): bearing of the robot's centre,
  ``θ = atan2(x, z)``; **Depth** D (metres): its ``z``. So the centre is at
  ``x = D·tan θ, z = D``;
- **Yaw** (degrees, clockwise-positive) = ψ + θ, ψ the robot's heading relative to the
  camera's: 0 = facing the way the camera looks, +90 = facing the camera's right. So the
  robot faces ``(x, z) = (sin ψ, cos ψ)`` with ``ψ = Yaw − θ``.

Given the camera's pose in the odometry frame at the sighting's stamp (tf2's transform
``odom <- optical frame``: a translation and a unit quaternion), the seen robot's position is
the point on the floor under the midpoint of its markers — its centre, mapped into odom, with
``z`` dropped (the camera is level, as vision_synth assumes, so the marker's height does not
move it) — and its heading is the facing direction mapped into odom, measured
COUNTER-CLOCKWISE from odom's ``x`` (REP 103), in radians in (−π, π].

:func:`bearing` goes the other way: the Angle at which the camera, wherever it is now, would
see a point of the odometry frame.
"""
import math
from collections import namedtuple

#: A seen robot in the odometry frame: ``name``, ``x`` and ``y`` (metres), ``yaw`` (radians,
#: counter-clockwise, in (−π, π]).
Located = namedtuple('Located', 'name x y yaw')

#: Bearings at or beyond this many degrees cannot come from a camera (tan θ explodes).
MAX_BEARING = 89.0


class BadSighting(ValueError):
    """A sighting or camera pose that cannot be turned into a pose (says why)."""


def normalize_rad(angle):
    """``angle`` (radians) mapped into (−π, π]."""
    a = math.fmod(angle, 2.0 * math.pi)
    if a <= -math.pi:
        a += 2.0 * math.pi
    elif a > math.pi:
        a -= 2.0 * math.pi
    return a


def rotate(quaternion, vector):
    """``vector`` (x, y, z) rotated by the unit ``quaternion`` (x, y, z, w).

    :raises BadSighting: a quaternion of (nearly) zero length or not finite
    """
    qx, qy, qz, qw = (float(c) for c in quaternion)
    norm = math.sqrt(qx * qx + qy * qy + qz * qz + qw * qw)
    if not math.isfinite(norm) or norm < 1e-9:
        raise BadSighting('camera rotation %r is not a rotation' % (tuple(quaternion),))
    qx, qy, qz, qw = qx / norm, qy / norm, qz / norm, qw / norm
    vx, vy, vz = vector
    # v' = v + 2w (u × v) + 2 u × (u × v), u = (qx, qy, qz)
    cx, cy, cz = qy * vz - qz * vy, qz * vx - qx * vz, qx * vy - qy * vx
    ccx, ccy, ccz = qy * cz - qz * cy, qz * cx - qx * cz, qx * cy - qy * cx
    return (vx + 2.0 * (qw * cx + ccx), vy + 2.0 * (qw * cy + ccy), vz + 2.0 * (qw * cz + ccz))


def locate(name, angle, depth, yaw, translation, rotation):
    """The seen robot's pose in the odometry frame.

    :param name: the seen robot's name (kept as it is)
    :param angle: θ, degrees, clockwise-positive (the sighting's ``angle``)
    :param depth: metres along the optical axis (the sighting's ``depth``)
    :param yaw: ψ + θ, degrees, clockwise-positive (the sighting's ``yaw``)
    :param translation: (x, y, z) of the optical frame's origin in the odometry frame
    :param rotation: (x, y, z, w) quaternion of the optical frame in the odometry frame
    :rtype: :class:`Located`
    :raises BadSighting: a value that is not finite, a depth that is not positive, a bearing
        no camera can have, or a rotation that is not one
    """
    values = (angle, depth, yaw) + tuple(translation)
    if not all(math.isfinite(float(v)) for v in values):
        raise BadSighting('%s: not finite: angle %r, depth %r, yaw %r, camera at %r'
                          % (name, angle, depth, yaw, tuple(translation)))
    if depth <= 0.0:
        raise BadSighting('%s: depth %r is not in front of the camera' % (name, depth))
    if abs(angle) >= MAX_BEARING:
        raise BadSighting('%s: angle %r is outside any camera\'s view' % (name, angle))
    theta = math.radians(angle)
    psi = math.radians(yaw) - theta
    centre = rotate(rotation, (depth * math.tan(theta), 0.0, depth))
    facing = rotate(rotation, (math.sin(psi), 0.0, math.cos(psi)))
    if math.hypot(facing[0], facing[1]) < 1e-6:
        raise BadSighting('%s: the camera looks straight up or down' % name)
    return Located(name, centre[0] + translation[0], centre[1] + translation[1],
                   normalize_rad(math.atan2(facing[1], facing[0])))


def bearing(x, y, translation, rotation):
    """The angle (degrees, clockwise-positive, as a sighting's) at which a level camera with
    this pose in the odometry frame sees the point ``(x, y)`` of that frame; beyond ±90 when
    the point is behind it.

    :param translation: (x, y, z) of the optical frame's origin in the odometry frame
    :param rotation: (x, y, z, w) quaternion of the optical frame in the odometry frame
    :raises BadSighting: a rotation that is not one
    """
    qx, qy, qz, qw = rotation
    # into the optical frame: rotate by the inverse (the conjugate); at the camera's height,
    # so that a camera that is not quite level still measures a horizontal angle
    seen = rotate((-qx, -qy, -qz, qw), (x - translation[0], y - translation[1], 0.0))
    return math.degrees(math.atan2(seen[0], seen[2]))
