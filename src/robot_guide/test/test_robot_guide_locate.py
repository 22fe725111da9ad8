"""Poses of seen robots in the odometry frame, against hand-computed cases."""
import math

import pytest

from robot_guide.locate import BadSighting, Located, bearing, locate, normalize_rad, rotate

# The simulator's camera: 0.08 m ahead of the base, 0.30 m up, optical frame (z forward,
# x right, y down) turned from the base by this quaternion (x, y, z, w).
OPTICAL = (-0.5, 0.5, -0.5, 0.5)
FORWARD, HEIGHT = 0.08, 0.30


def multiply(a, b):
    ax, ay, az, aw = a
    bx, by, bz, bw = b
    return (aw * bx + ax * bw + ay * bz - az * by, aw * by - ax * bz + ay * bw + az * bx,
            aw * bz + ax * by - ay * bx + az * bw, aw * bw - ax * bx - ay * by - az * bz)


def camera(x, y, yaw):
    """(translation, rotation) of the optical frame of a robot at (x, y, yaw rad) in odom."""
    base = (0.0, 0.0, math.sin(yaw / 2), math.cos(yaw / 2))
    return ((x + FORWARD * math.cos(yaw), y + FORWARD * math.sin(yaw), HEIGHT),
            multiply(base, OPTICAL))


def close(found, x, y, yaw, tol=1e-9):
    assert abs(found.x - x) < tol and abs(found.y - y) < tol, found
    assert abs(normalize_rad(found.yaw - yaw)) < tol, found


def test_the_optical_frame_looks_along_the_base():
    _, q = camera(0, 0, 0)
    forward, right, down = rotate(q, (0, 0, 1)), rotate(q, (1, 0, 0)), rotate(q, (0, 1, 0))
    for got, want in ((forward, (1, 0, 0)), (right, (0, -1, 0)), (down, (0, 0, -1))):
        assert all(abs(g - w) < 1e-12 for g, w in zip(got, want))


def test_straight_ahead_facing_away():
    # 2 m ahead of the camera, which is 0.08 m ahead of the base at the origin
    found = locate('faulty', 0.0, 2.0, 0.0, *camera(0, 0, 0))
    assert isinstance(found, Located) and found.name == 'faulty'
    close(found, 2.08, 0.0, 0.0)


def test_to_the_right_is_minus_y():
    # 30 deg right at depth 2: 2 m forward, 2·tan 30 = 1.1547 m right (-y); facing away
    # (psi 0) makes Yaw = psi + angle = 30, the heading still 0 in odom
    found = locate('faulty', 30.0, 2.0, 30.0, *camera(0, 0, 0))
    close(found, 2.08, -2.0 * math.tan(math.radians(30)), 0.0)


def test_to_the_left_is_plus_y():
    found = locate('faulty', -20.0, 1.5, -20.0, *camera(0, 0, 0))
    close(found, 1.58, 1.5 * math.tan(math.radians(20)), 0.0)


@pytest.mark.parametrize('psi, heading', [
    (-90.0, math.pi / 2),    # facing the camera's left: +y, counter-clockwise +90
    (90.0, -math.pi / 2),    # facing the camera's right: -y
    (180.0, math.pi),        # facing the camera
    (45.0, -math.pi / 4),
])
def test_facing_left_right_and_towards_the_camera(psi, heading):
    found = locate('faulty', 0.0, 1.5, psi, *camera(0, 0, 0))
    close(found, 1.58, 0.0, heading)


def test_facing_the_camera_from_the_right():
    # 10 deg right, facing the camera (psi 180): Yaw = 190 -> -170 as vision_synth reports it
    found = locate('faulty', 10.0, 2.0, -170.0, *camera(0, 0, 0))
    close(found, 2.08, -2.0 * math.tan(math.radians(10)), math.pi)


def test_camera_yawed_in_odom():
    # base at (1, 2) facing +y: the camera at (1, 2.08); right of the camera is +x
    found = locate('faulty', 0.0, 1.5, 0.0, *camera(1, 2, math.pi / 2))
    close(found, 1.0, 3.58, math.pi / 2)
    # 20 deg right at depth 1, facing the camera's right (psi 90, Yaw 110): +x, heading 0
    found = locate('faulty', 20.0, 1.0, 110.0, *camera(1, 2, math.pi / 2))
    close(found, 1.0 + math.tan(math.radians(20)), 3.08, 0.0)
    # base facing -x (yaw 180): ahead is -x, right is +y; psi -90 faces the camera's left (-y)
    found = locate('faulty', 15.0, 2.0, -75.0, *camera(0, 0, math.pi))
    close(found, -2.08, 2.0 * math.tan(math.radians(15)), -math.pi / 2)


def truth_sighting(helper, seen):
    """(angle, depth, yaw) a level camera on ``helper`` reports of ``seen`` (world poses),
    vision_synth's definitions written independently of locate()."""
    hx, hy, hyaw = helper
    cx, cy = hx + FORWARD * math.cos(hyaw), hy + FORWARD * math.sin(hyaw)
    dx, dy = seen[0] - cx, seen[1] - cy
    forward = dx * math.cos(hyaw) + dy * math.sin(hyaw)
    right = dx * math.sin(hyaw) - dy * math.cos(hyaw)
    angle = math.degrees(math.atan2(right, forward))
    psi = -math.degrees(seen[2] - hyaw)
    return angle, forward, math.degrees(normalize_rad(math.radians(psi + angle)))


@pytest.mark.parametrize('helper', [(0, 0, 0), (-1, 0.75, 0.4), (2, -3, -2.5), (0.5, 0.5, math.pi)])
@pytest.mark.parametrize('offset', [(1.0, 0.0), (2.0, 0.6), (3.0, -1.2), (1.2, 0.5)])
@pytest.mark.parametrize('heading', [-2.8, -1.0, 0.0, 0.7, 3.0])
def test_round_trip_through_what_the_camera_reports(helper, offset, heading):
    hx, hy, hyaw = helper
    seen = (hx + offset[0] * math.cos(hyaw) - offset[1] * math.sin(hyaw),
            hy + offset[0] * math.sin(hyaw) + offset[1] * math.cos(hyaw), hyaw + heading)
    found = locate('r', *truth_sighting(helper, seen), *camera(*helper))
    close(found, seen[0], seen[1], seen[2], tol=1e-9)


def test_the_camera_rotation_need_not_be_normalised():
    t, q = camera(0, 0, 0.3)
    found = locate('r', 5.0, 2.0, 12.0, t, tuple(2.0 * c for c in q))
    close(found, *locate('r', 5.0, 2.0, 12.0, t, q)[1:])


@pytest.mark.parametrize('angle, depth, yaw, why', [
    (0.0, 0.0, 0.0, 'in front'), (0.0, -1.0, 0.0, 'in front'), (90.0, 1.0, 0.0, 'view'),
    (-89.5, 1.0, 0.0, 'view'), (float('nan'), 1.0, 0.0, 'finite'),
    (0.0, float('inf'), 0.0, 'finite'), (0.0, 1.0, float('nan'), 'finite'),
])
def test_impossible_sightings_are_refused(angle, depth, yaw, why):
    with pytest.raises(BadSighting, match=why):
        locate('r', angle, depth, yaw, *camera(0, 0, 0))


def test_a_rotation_that_is_not_one_is_refused():
    with pytest.raises(BadSighting, match='not a rotation'):
        locate('r', 0.0, 1.0, 0.0, (0, 0, 0), (0, 0, 0, 0))
    with pytest.raises(BadSighting, match='finite'):
        locate('r', 0.0, 1.0, 0.0, (float('nan'), 0, 0), OPTICAL)


def test_a_camera_looking_straight_down_is_refused():
    # optical z along odom -z: the facing direction has no horizontal part
    down = (1.0, 0.0, 0.0, 0.0)    # 180 deg about x: z -> -z
    with pytest.raises(BadSighting, match='straight up or down'):
        locate('r', 0.0, 1.0, 0.0, (0, 0, 1), down)


@pytest.mark.parametrize('angle, want', [(0.0, 0.0), (math.pi, math.pi), (-math.pi, math.pi),
                                         (3 * math.pi / 2, -math.pi / 2), (-7.0, -7.0 + 2 * math.pi)])
def test_normalize_rad(angle, want):
    assert abs(normalize_rad(angle) - want) < 1e-12


@pytest.mark.parametrize('helper', [(0, 0, 0), (-1, 0.75, 0.4), (2, -3, -2.5)])
@pytest.mark.parametrize('angle', [-25.0, -3.0, 0.0, 12.5, 28.0])
def test_bearing_is_the_angle_at_which_the_camera_sees_a_located_point(helper, angle):
    found = locate('r', angle, 1.7, 30.0, *camera(*helper))
    assert bearing(found.x, found.y, *camera(*helper)) == pytest.approx(angle, abs=1e-9)


def test_bearing_follows_the_cameras_own_turn():
    # a point straight ahead of a base at the origin; the base turned 10 deg counter-clockwise
    # sees it to its right (clockwise-positive): a little more than 10 deg, as the camera,
    # 8 cm ahead of the base's centre, moved left: at (0.0788, 0.0139), the point 1.9684 m
    # ahead and 0.3612 m right of it, atan2(0.3612, 1.9684) = 10.398 deg
    assert bearing(2.08, 0.0, *camera(0, 0, math.radians(10))) == pytest.approx(10.398, abs=1e-3)
    assert bearing(2.08, 0.0, *camera(0, 0, math.radians(-10))) == pytest.approx(-10.398, abs=1e-3)
    # behind: beyond 90 deg, so the turn toward it saturates the right way
    assert bearing(-2.0, -0.1, *camera(0, 0, 0)) == pytest.approx(180 - math.degrees(
        math.atan2(0.1, 2.08)), abs=1e-9)
