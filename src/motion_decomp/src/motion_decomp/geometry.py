"""Planar pose helpers shared by the motion cores (monitor, goto, arc), without rospy.

Poses are ``(x, y, yaw)`` tuples: metres, metres, radians (REP 103, yaw counter-clockwise).
"""
import math

#: Pose changes below both of these count as "no progress" (every motion core uses them).
PROGRESS_DISTANCE = 0.001          # metres
PROGRESS_ANGLE = math.radians(0.1)


def wrap_angle(angle):
    """The same angle in [-pi, pi).

    :param angle: radians
    """
    return (angle + math.pi) % (2.0 * math.pi) - math.pi


def yaw_from_quaternion(x, y, z, w):
    """Rotation about z of a quaternion (the robot's heading in the plane).

    :param x: quaternion x
    :param y: quaternion y
    :param z: quaternion z
    :param w: quaternion w
    :returns: radians in [-pi, pi]
    """
    return math.atan2(2.0 * (w * z + x * y), 1.0 - 2.0 * (y * y + z * z))


def is_finite_pose(pose):
    """True when ``pose`` is an ``(x, y, yaw)`` of finite numbers.

    :param pose: ``(x, y, yaw)``
    """
    return all(math.isfinite(v) for v in pose)
