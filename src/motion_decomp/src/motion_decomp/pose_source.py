"""Which pose the motions use (``pose_source(Name)``, issue 15), without rospy.

``odom`` (the default) is the robot's own odometry. ``guided`` is a pose of the robot seen by
someone else (e.g. another robot's camera and odometry, while this robot's encoders are
faulty), which comes late and seldom (~0.2 s, ~10 Hz): it is usable only while fresh, so that
the robot is never driven on a position it had a while ago. While fresh, it is carried forward
from its stamp to now by the robot's own commands (:func:`carried_forward`), so that its lateness
(a camera frame's, and the network's between two robots) does not become a lag in control.
"""
import bisect
import math
from collections import namedtuple

from motion_decomp.geometry import is_finite_pose, wrap_angle

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


class CommandedTrail(object):
    """The poses the robot's own commands integrated to (its commanded odometry) over the last
    ``span`` seconds: how it moved between two recent moments.

    :param span: seconds kept, at least as long as a guided pose stays fresh
    """

    def __init__(self, span):
        self.span = float(span)
        self._times = []
        self._poses = []

    def record(self, now, pose):
        """The commanded pose at ``now``; time going back (a restarted simulation) starts anew."""
        if self._times and now < self._times[-1]:
            del self._times[:], self._poses[:]
        self._times.append(float(now))
        self._poses.append(pose)
        old = bisect.bisect_left(self._times, now - self.span)
        if old > len(self._times) // 2:       # drop in batches, not a list shift per sample
            del self._times[:old], self._poses[:old]

    def at(self, t):
        """The newest recorded pose at or before ``t``, or ``None`` when none is that old."""
        i = bisect.bisect_right(self._times, t)
        return self._poses[i - 1] if i else None


def _moved(start, end):
    """``end`` seen from ``start``: ``(forward, left, turn)``."""
    dx, dy = end[0] - start[0], end[1] - start[1]
    c, s = math.cos(start[2]), math.sin(start[2])
    return (c * dx + s * dy, -s * dx + c * dy, wrap_angle(end[2] - start[2]))


def carried_forward(guided, trail, now):
    """``guided`` moved on by what the robot commanded itself between its stamp and ``now``
    (stamp unchanged, so its freshness is still judged by when it was seen).

    :param guided: a :class:`StampedPose` or ``None``
    :param trail: the :class:`CommandedTrail`
    :returns: a :class:`StampedPose`, ``guided`` itself when the trail does not reach back to
        its stamp, or ``None``
    """
    if guided is None:
        return None
    then, current = trail.at(guided.stamp), trail.at(now)
    if then is None or current is None:
        return guided
    forward, left, turn = _moved(then, current)
    x, y, yaw = guided.pose
    c, s = math.cos(yaw), math.sin(yaw)
    return StampedPose((x + c * forward - s * left, y + s * forward + c * left, wrap_angle(yaw + turn)),
                       guided.stamp)
