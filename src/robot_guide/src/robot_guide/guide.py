"""The ``guide(Name, Seconds)`` action: its arguments, and one run's state. No ROS.

A run keeps ``Name`` centred for ``Seconds`` of ROS time and ends ``OK``; it fails ``lost``
when ``Name`` has not been seen for ``lost_after`` seconds (counted from the run's start
too, so a robot never seen fails as soon as one that went out of view).

Where to aim: the camera's frames come at 10 Hz and reach the node 0.1–0.3 s after their
stamp (rendering, the cloud, detection; more on a loaded machine). Turning on each frame's
Angle alone would answer the base's own turn that late, and the loop overshoots and swings
(seen on the simulator under load: ±11 deg). So each frame's sighting is kept as the POINT
of the odometry frame where the robot was (:mod:`robot_guide.locate`), moved on by the
robot's own velocity to where it is now (:class:`robot_guide.track.Track`), and the node
turns, at its own faster rate, by the angle at which the camera sees that point NOW, from the
newest odometry (:func:`robot_guide.locate.bearing`): the base's own turn is then answered
at the odometry's delay, and the seen robot's motion from its track. Between frames, and in
frames that miss the robot (a robot crossing the view side-on hides one cylinder behind the
other), the run keeps aiming at the track. A frame whose point could not be worked out (no
transform) leaves its Angle as the aim until the next frame.
"""
import math

from rason_msgs.msg import Event
from rason_wiring import terms

from robot_guide.centring import Centring
from robot_guide.track import Track

ACTION = 'guide'


class BadGuide(ValueError):
    """Arguments that are not ``guide(Name, Seconds)`` (the message says why)."""


def parse_arguments(parameters):
    """``(name, seconds)`` of a guide action's parameters (text, as the bridge sends them).

    :param parameters: e.g. ``['faulty', '5']``
    :raises BadGuide: not two arguments, a name that is not a Jason atom, seconds that are not
        a positive finite number
    """
    if len(parameters) != 2:
        raise BadGuide('guide(Name, Seconds) takes 2 arguments, got %d' % len(parameters))
    name, seconds = parameters[0].strip(), terms.number(parameters[1])
    if not terms.is_atom(name):
        raise BadGuide('Name %r is not a Jason atom (a robot\'s agent name)' % parameters[0])
    if seconds is None or not (math.isfinite(seconds) and seconds > 0):
        raise BadGuide('Seconds %r is not a positive finite number' % parameters[1])
    return name, float(seconds)


class GuideRun(object):
    """One guide: whom, until when, when last seen, where to aim.

    :param name: the robot to keep centred
    :param seconds: how long, seconds of the node's clock
    :param start: the clock when it starts
    :param lost_after: seconds without seeing ``name`` before the run fails ``lost``
    :param deadband, gain, max_speed: the centring's (see :class:`Centring`)
    """

    def __init__(self, name, seconds, start, lost_after, deadband, gain, max_speed):
        self.name = name
        self.end = start + seconds
        self.lost_after = lost_after
        self.last_seen = start
        self.track = Track()     # where it was located in the odometry frame, and its velocity
        self.angle = None        # the last frame's Angle, when that frame could not locate it
        self._centring = Centring(deadband, gain, max_speed)

    def frame(self, now, angle, point, stamp):
        """One camera frame, stamped ``stamp``, handled at ``now``.

        :param angle: ``name``'s Angle in it (degrees, clockwise), None when not in it
        :param point: ``(x, y)`` where it is in the odometry frame, None when not worked out
        """
        if angle is None:
            self.angle = None    # a bare Angle goes stale as the base turns; a point does not
            return
        self.last_seen = max(self.last_seen, now)
        if point is not None:
            self.track.add(stamp, *point)
            self.angle = None
        else:
            self.angle = angle

    def command(self, now, bearing_of):
        """The turn (``angular.z``, rad/s, REP 103) at ``now``.

        :param bearing_of: ``bearing_of(x, y)`` -> the Angle at which the camera sees that
            point of the odometry frame now, or None when the camera's pose is unknown
        :returns: the centring turn toward the aim; 0.0 with nothing to aim at
        """
        aim = self.angle
        if aim is None:
            point = self.track.at(now)
            aim = None if point is None else bearing_of(*point)
        return self._centring.speed(aim)

    def outcome(self, now):
        """``Event.OK`` once the time is over, ``Event.LOST`` once ``name`` has not been seen
        for ``lost_after`` seconds (the time being over wins), else None (it goes on)."""
        if now >= self.end:
            return Event.OK
        if now - self.last_seen >= self.lost_after:
            return Event.LOST
        return None
