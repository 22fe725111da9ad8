"""Which pose the motions use (``pose_source(Name)``, issue 15), without rospy.

``odom`` (the default) is the robot's own odometry. ``guided`` is a pose of the robot seen by
someone else (e.g. another robot's camera and odometry, while this robot's encoders are
faulty), which comes late and seldom (~0.2 s, ~10 Hz): it is usable only while fresh, so that
the robot is never driven on a position it had a while ago.
"""
import math
from collections import namedtuple

from motion_decomp.geometry import is_finite_pose

ODOM = 'odom'
GUIDED = 'guided'
#: The names ``pose_source`` accepts.
POSE_SOURCES = (ODOM, GUIDED)

#: A guided pose ``(x, y, yaw)`` and the time (s) it describes.
StampedPose = namedtuple('StampedPose', 'pose stamp')


def stamped_pose(pose, stamp, received):
    """The :class:`StampedPose` of a guided pose message, or ``None`` when it holds no pose.

    :param pose: ``(x, y, yaw)``; a value that is not finite means "no pose"
    :param stamp: the header's stamp (s); 0 (not set) counts as the time it was received
    :param received: when it arrived (s)
    """
    if not is_finite_pose(pose) or not math.isfinite(stamp):
        return None
    return StampedPose(tuple(float(v) for v in pose), float(stamp) if stamp != 0 else float(received))


def fresh_pose(stamped, now, max_age):
    """The pose of ``stamped`` when it is usable at ``now``, else ``None``.

    :param stamped: a :class:`StampedPose` or ``None``
    :param now: seconds, the same clock as the stamps (ROS time)
    :param max_age: seconds; a pose older than this is stale, and so is one stamped more than
        this ahead of ``now`` (its clock is not ours)
    """
    if stamped is None or abs(now - stamped.stamp) > max_age:
        return None
    return stamped.pose


def select_pose(source, odom, guided, now, max_age):
    """The pose the motions use now.

    :param source: :data:`ODOM` or :data:`GUIDED`
    :param odom: the latest odometry pose or ``None``
    :param guided: the latest guided :class:`StampedPose` or ``None``
    :param now: seconds
    :param max_age: seconds, see :func:`fresh_pose`
    """
    return odom if source == ODOM else fresh_pose(guided, now, max_age)
