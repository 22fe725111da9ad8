"""Angle, depth and yaw of a robot seen through its two cylinders (thesis §6.2). No ROS.

Frames and signs
----------------
Points are in the camera's optical frame (``x`` right, ``y`` down, ``z`` forward, metres),
as in a Kinect's ``depth_registered/points``. The camera looks horizontally, so the
*ground plane* of the camera is ``(x, z)``. Every angle is in DEGREES and CLOCKWISE-positive
seen from above, i.e. positive to the RIGHT, like the thesis's Angle:

- **Angle** θ: bearing of the robot's centre, 0 on the optical axis, negative = left,
  ``θ = atan2(x, z)`` of the midpoint of the two cylinder axes.
- **Depth**: the mean of the two cylinders' depths ``z`` (thesis: ``(c1 + c2) / 2``), which is
  the optical-axis depth of the robot's centre (the cylinders sit symmetrically about it).
- **heading** ψ: where the observed robot faces, in the camera frame: 0 = the same way as the
  camera (away from it), +90 = towards the camera's right, ±180 = towards the camera.
  With ``r = right − left`` (the robot's right-hand direction; the thesis's robot carries
  green on its left and orange on its right), the heading is ``r`` turned 90° counter-clockwise
  seen from above: ``f = (−r_z, r_x)`` in ``(x, z)``, and ``ψ = atan2(f_x, f_z)``.
- **Yaw** = ψ + θ, normalised to (−180, 180].

Why Yaw = ψ + θ: Faulty's plans (thesis Appendix A.1) diagnose a ``bad_move`` with
``Yaw1 − (Yaw + (Deg1 − Deg))``. With Yaw = ψ + θ that is ``(ψ1 + θ1) − (ψ0 + θ0) − (θ1 − θ0)
= ψ1 − ψ0``: exactly how far the robot turned (clockwise-positive), whatever its path
across the helper's view. A right-actuator fault turns it clockwise (thesis Eq. 6.2), so
the value is positive and the plan says "right actuator"; left gives a negative value.
(A yaw relative to the line of sight, ψ − θ, would leave the rule off by 2·(θ1 − θ0).)
The identity holds modulo 360: a robot whose Yaw crosses ±180 between the two sightings
makes the raw difference jump by 360.
"""
import math

import numpy as np

#: Median depth offset of a cylinder's visible surface from its axis, in radii. Seen from
#: afar, the visible half of a cylinder of radius r covers image columns uniformly in
#: ``s = r·sin(φ)``; the surface lies ``r·cos(φ)`` in front of the axis, so the median point
#: (|s| = r/2) is ``r·cos(30°) = 0.866 r`` in front of it.
SURFACE_TO_AXIS = math.sqrt(3.0) / 2.0


def normalize_deg(angle):
    """``angle`` in degrees mapped into (−180, 180].

    :param angle: degrees
    :rtype: float
    """
    a = math.fmod(angle, 360.0)
    if a <= -180.0:
        a += 360.0
    elif a > 180.0:
        a -= 360.0
    return a


def axis_point(surface_point, radius):
    """The point on a vertical cylinder's axis behind a point of its visible surface.

    Moves ``surface_point`` away from the camera, horizontally along the line of sight, by
    ``SURFACE_TO_AXIS × radius`` (the median offset of the visible surface, see above).

    :param surface_point: (x, y, z) optical frame, metres (e.g. the median of a blob's points)
    :param radius: cylinder radius, metres (0 leaves the point unchanged)
    :rtype: numpy array (3,)
    """
    p = np.asarray(surface_point, dtype=float)
    ground = math.hypot(p[0], p[2])
    if radius <= 0.0 or ground == 0.0:
        return p.copy()
    k = SURFACE_TO_AXIS * radius / ground
    return np.array([p[0] * (1.0 + k), p[1], p[2] * (1.0 + k)])


def bearing_deg(point):
    """Angle θ of a point: degrees, 0 on the optical axis, positive to the right.

    This is what the node reports by default (``angle_method: cloud``): it is exact for the
    robot's centre at any place in the image and needs no intrinsics (the cloud already
    has them). The thesis's pixel-linear formula (:func:`thesis_angle_deg`) is off by up to
    ~1° in mid-image with a 57° lens; :func:`pinhole_angle_deg` is exact for the pixel it
    is given, but the midpoint of two blobs' pixels is not quite the projection of the
    robot's centre when the robot is turned (perspective).

    :param point: (x, y, z) optical frame
    :rtype: float
    """
    return math.degrees(math.atan2(point[0], point[2]))


def pinhole_angle_deg(u, fx, cx):
    """Angle of image column ``u`` with a pinhole camera: ``atan((u − cx) / fx)``, degrees.

    :param u: column (pixels, 0 = left edge's pixel centre)
    :param fx: focal length, pixels
    :param cx: principal point column, pixels
    :rtype: float
    """
    return math.degrees(math.atan2(u - cx, fx))


def thesis_angle_deg(u, width, fov_deg=57.0):
    """The thesis's angle (§6.2): ``(u − W/2) / (W/2) × fov/2``, linear in pixels, degrees.

    :param u: column, pixels
    :param width: image width, pixels
    :param fov_deg: horizontal field of view, degrees
    :rtype: float
    """
    half = width / 2.0
    return (u - half) / half * (fov_deg / 2.0)


def focal_from_fov(width, fov_deg):
    """Pinhole focal length (pixels) of a ``width``-pixel image with horizontal ``fov_deg``.

    :rtype: float
    """
    return (width / 2.0) / math.tan(math.radians(fov_deg) / 2.0)


def heading_deg(left_point, right_point):
    """Heading ψ of a robot in the camera frame from its left and right cylinder axes.

    ``r = right − left`` in the ground plane (x, z) is the robot's right-hand direction;
    the robot faces ``f = (−r_z, r_x)``; ``ψ = atan2(f_x, f_z) = atan2(−r_z, r_x)``.
    Examples: facing away (ψ = 0) puts its left cylinder on the left of the image
    (``r = (+, 0)``); facing the camera (ψ = 180) puts it on the right (``r = (−, 0)``).

    :param left_point: (x, y, z) of the robot's left cylinder
    :param right_point: (x, y, z) of its right cylinder
    :rtype: float, degrees in (−180, 180]
    """
    rx = right_point[0] - left_point[0]
    rz = right_point[2] - left_point[2]
    return normalize_deg(math.degrees(math.atan2(-rz, rx)))


def yaw_deg(heading, angle):
    """The reported Yaw: ``ψ + θ`` normalised to (−180, 180] (see the module docstring).

    :param heading: ψ, degrees
    :param angle: θ, degrees
    :rtype: float
    """
    return normalize_deg(heading + angle)


class Pose(object):
    """Angle, depth and yaw of an observed robot, plus the intermediate values.

    :ivar angle: θ, degrees, positive right
    :ivar depth: metres along the optical axis
    :ivar yaw: ψ + θ, degrees in (−180, 180]
    :ivar heading: ψ, degrees in (−180, 180]
    :ivar separation: 3-D distance between the two cylinder axes, metres
    """
    __slots__ = ('angle', 'depth', 'yaw', 'heading', 'separation')

    def __init__(self, angle, depth, yaw, heading, separation):
        self.angle = angle
        self.depth = depth
        self.yaw = yaw
        self.heading = heading
        self.separation = separation

    def __repr__(self):
        return 'Pose(angle=%.2f, depth=%.3f, yaw=%.2f, heading=%.2f, separation=%.3f)' % (
            self.angle, self.depth, self.yaw, self.heading, self.separation)


def observe(left_point, right_point, angle=None):
    """Pose of a robot from its two cylinder axis points.

    :param left_point: (x, y, z) of its left cylinder's axis, optical frame
    :param right_point: (x, y, z) of its right cylinder's axis
    :param angle: θ to use instead of the bearing of the midpoint (e.g. a pixel-based one)
    :rtype: :class:`Pose`
    """
    left = np.asarray(left_point, dtype=float)
    right = np.asarray(right_point, dtype=float)
    middle = (left + right) / 2.0
    theta = bearing_deg(middle) if angle is None else float(angle)
    psi = heading_deg(left, right)
    depth = (left[2] + right[2]) / 2.0
    return Pose(theta, depth, yaw_deg(psi, theta), psi, float(np.linalg.norm(right - left)))


def fit_pose(points, layout, angle=None, separation=float('nan')):
    """Pose of a robot from two or more of its cylinders: the rigid motion (turn, then
    shift) that best puts where the cylinders sit on the robot onto where their axes are
    seen, in the least-squares sense (2-D Kabsch: the centroids matched, the turn from the
    summed cross and dot products about them). With only the left and right cylinders it
    gives what :func:`observe` gives: the centre is their midpoint.

    :param points: (x, y, z) axis points, optical frame, two or more
    :param layout: (forward, left) metres of each of those cylinders from the robot's
        centre, in the same order
    :param angle: θ to use instead of the bearing of the fitted centre
    :param separation: what :attr:`Pose.separation` holds (NaN: left and right not both seen)
    :rtype: :class:`Pose`; depth is the optical-axis depth of the fitted centre
    """
    seen = np.array([[p[2], -p[0]] for p in points], dtype=float)  # from above: forward, left
    model = np.asarray(layout, dtype=float)
    if len(seen) < 2 or seen.shape != model.shape:
        raise ValueError('fit_pose needs two or more points, one (forward, left) each')
    seen_c, model_c = seen.mean(axis=0), model.mean(axis=0)
    s, m = seen - seen_c, model - model_c
    turn = math.atan2(float(np.sum(m[:, 0] * s[:, 1] - m[:, 1] * s[:, 0])),
                      float(np.sum(m[:, 0] * s[:, 0] + m[:, 1] * s[:, 1])))
    c, n = math.cos(turn), math.sin(turn)
    forward, left = seen_c - np.array([c * model_c[0] - n * model_c[1],
                                       n * model_c[0] + c * model_c[1]])
    x, z = -left, forward
    theta = math.degrees(math.atan2(x, z)) if angle is None else float(angle)
    psi = normalize_deg(-math.degrees(turn))  # turn is counter-clockwise, ψ clockwise
    return Pose(theta, float(z), yaw_deg(psi, theta), psi, float(separation))

