"""Angle/depth/yaw definitions, and the proof that Yaw = ψ + θ makes thesis Appendix A's
left/right-actuator rules right (pure geometry, no images, no ROS master)."""
import math
import re

import numpy as np
import pytest

from vision_synth import geometry as g
from vision_synth import literals

HALF = 0.227 / 2.0


def cylinders(x, z, heading):
    """Axis points (left, right) of a robot at (x, z) in the camera's ground plane, facing
    ``heading`` degrees clockwise from the camera's forward direction (the test's own
    model: forward = (sin h, cos h), right-hand side = forward turned 90° clockwise)."""
    h = math.radians(heading)
    right = np.array([math.cos(h), 0.0, -math.sin(h)])
    centre = np.array([x, 0.1, z])
    return centre - HALF * right, centre + HALF * right


# ---------------------------------------------------------------- basic definitions

@pytest.mark.parametrize('angle, expected', [
    (0, 0), (180, 180), (-180, 180), (190, -170), (-190, 170), (540, 180), (359.5, -0.5),
    (-720.25, -0.25)])
def test_normalize_deg_maps_into_half_open_interval(angle, expected):
    assert g.normalize_deg(angle) == pytest.approx(expected)


def test_bearing_is_negative_on_the_left_and_exact():
    assert g.bearing_deg((-1.0, 0.0, 1.0)) == pytest.approx(-45.0)
    assert g.bearing_deg((0.5, 3.0, 2.0)) == pytest.approx(math.degrees(math.atan(0.25)))
    assert g.bearing_deg((0.0, -1.0, 2.0)) == 0.0


def test_robot_facing_away_has_its_left_cylinder_on_the_left_of_the_image():
    left, right = cylinders(0.0, 2.0, 0.0)
    assert left[0] < right[0]                       # green appears left in the image
    assert g.heading_deg(left, right) == pytest.approx(0.0)


def test_robot_facing_the_camera_has_its_left_cylinder_on_the_right_of_the_image():
    left, right = cylinders(0.0, 2.0, 180.0)
    assert left[0] > right[0]
    assert g.heading_deg(left, right) == pytest.approx(180.0)


def test_heading_to_the_right_puts_the_right_cylinder_nearer():
    left, right = cylinders(0.0, 2.0, 90.0)
    assert right[2] < left[2]
    assert g.heading_deg(left, right) == pytest.approx(90.0)
    left, right = cylinders(0.0, 2.0, -90.0)
    assert g.heading_deg(left, right) == pytest.approx(-90.0)


@pytest.mark.parametrize('heading', [-179, -150, -90, -60, -30, 0, 30, 60, 90, 150, 180])
@pytest.mark.parametrize('x, z', [(-0.8, 1.5), (0.0, 1.0), (1.2, 3.0)])
def test_observe_recovers_the_model_pose(x, z, heading):
    pose = g.observe(*cylinders(x, z, heading))
    theta = math.degrees(math.atan2(x, z))
    assert pose.angle == pytest.approx(theta)
    assert pose.depth == pytest.approx(z)
    assert g.normalize_deg(pose.heading - heading) == pytest.approx(0.0, abs=1e-9)
    assert g.normalize_deg(pose.yaw - (heading + theta)) == pytest.approx(0.0, abs=1e-9)
    assert -180.0 < pose.yaw <= 180.0
    assert pose.separation == pytest.approx(0.227)


def test_observe_uses_a_given_angle_for_the_yaw():
    left, right = cylinders(0.5, 2.0, 30.0)
    pose = g.observe(left, right, angle=10.0)
    assert pose.angle == 10.0
    assert pose.yaw == pytest.approx(40.0)


@pytest.mark.parametrize('surface', [(0.0, 0.1, 2.0), (-1.0, 0.0, 1.0), (0.7, -0.2, 2.5)])
def test_axis_point_moves_away_along_the_horizontal_line_of_sight(surface):
    axis = g.axis_point(surface, 0.02)
    step = axis - np.asarray(surface)
    assert np.hypot(step[0], step[2]) == pytest.approx(0.02 * math.sqrt(3) / 2)
    assert step[1] == 0.0
    assert g.bearing_deg(axis) == pytest.approx(g.bearing_deg(surface))
    assert np.array_equal(g.axis_point(surface, 0.0), np.asarray(surface))


def test_median_visible_point_of_a_cylinder_is_where_axis_point_assumes():
    """Sample the visible half of a cylinder uniformly in image columns (far view)."""
    r, zc = 0.02, 2.0
    s = np.linspace(-r, r, 2001)[1:-1]
    z_surface = zc - np.sqrt(r * r - s * s)
    median = np.array([0.0, 0.0, np.median(z_surface)])
    assert g.axis_point(median, r)[2] == pytest.approx(zc, abs=2e-4)


def test_angle_formulas_agree_within_the_2_degree_tolerance_across_the_image():
    fx = g.focal_from_fov(640, 57.0)
    assert fx == pytest.approx(589.37, abs=0.01)
    assert g.pinhole_angle_deg(639.0, fx, 319.5) == pytest.approx(28.45, abs=0.05)
    assert g.thesis_angle_deg(0, 640) == -28.5
    worst = max(abs(g.thesis_angle_deg(u, 640) - g.pinhole_angle_deg(u, fx, 320.0))
                for u in range(641))
    assert 0.5 < worst < 2.0  # the thesis's linear formula errs, but by less than 2°


# ---------------------------------------------------------------- Yaw proof (Appendix A)

def drive(x, z, heading, distance, fault, step=0.001):
    """The faulty robot commanded forward (0.2 m/s) for ``distance`` metres of travel.

    Thesis Eq. 6.2/6.3 (as the fault injector applies them): left_actuator gives
    angular.z = +v, right_actuator angular.z = −v, and the linear speed is halved.
    ROS angular.z is counter-clockwise-positive, our heading clockwise-positive.
    """
    v, wz = 0.2, 0.0
    if fault == 'left_actuator':
        v, wz = v / 2.0, v
    elif fault == 'right_actuator':
        v, wz = v / 2.0, -v
    h = math.radians(heading)
    travelled = 0.0
    while travelled < distance - 1e-12:
        ds = min(step, distance - travelled)
        dt = ds / v
        mid = h - 0.5 * wz * dt
        x += ds * math.sin(mid)
        z += ds * math.cos(mid)
        h -= wz * dt
        travelled += ds
    return x, z, math.degrees(h)


def perceive(x, z, heading):
    """What the helper's synthesizer reports, as the agent reads it: (Deg, Depth, Yaw)
    parsed back from the published literal."""
    pose = g.observe(*cylinders(x, z, heading))
    text = literals.robot_literal('faulty', pose.angle, pose.depth, pose.yaw)
    m = re.match(r'robot\(faulty,(-?[\d.]+),(-?[\d.]+),(-?[\d.]+)\)\Z', text)
    return tuple(float(v) for v in m.groups())


def faulty_rule(init, curr):
    """Thesis Appendix A.1, lines 73–95: ``Yaw1 − (Yaw + (Deg1 − Deg))`` and its verdict."""
    (deg, _, yaw), (deg1, _, yaw1) = init, curr
    value = yaw1 - (yaw + (deg1 - deg))
    if abs(value) < 8:
        return value, 'false_positive'
    if value > 8:
        return value, 'right_actuator'
    return value, 'left_actuator'


# Start poses (x, z, heading): the thesis's set-up (Faulty moving across the helper's view
# at 1.5 m, from the centre), and moves from the left, the right, diagonally and away.
STARTS = [(0.0, 1.5, 90.0), (0.0, 1.5, -90.0), (-0.6, 1.5, 90.0), (0.6, 2.0, -90.0),
          (-0.5, 1.0, 45.0), (0.4, 2.5, -45.0), (0.0, 1.2, 0.0), (0.3, 1.0, 100.0),
          (-0.3, 2.0, -120.0)]


@pytest.mark.parametrize('start', STARTS)
@pytest.mark.parametrize('fault, verdict', [
    ('right_actuator', 'right_actuator'), ('left_actuator', 'left_actuator'),
    (None, 'false_positive')])
def test_appendix_a_rule_measures_the_true_turn_and_names_the_faulty_side(start, fault, verdict):
    end = drive(*start, distance=0.3, fault=fault)
    turned = g.normalize_deg(end[2] - start[2])      # clockwise-positive truth
    value, said = faulty_rule(perceive(*start), perceive(*end))
    assert value == pytest.approx(turned, abs=0.02)  # literal rounding only
    assert said == verdict
    if fault == 'right_actuator':
        assert turned > 8  # Eq. 6.2: the robot really turns clockwise (to the right)


def test_across_the_view_the_line_of_sight_yaw_would_misdiagnose_a_healthy_move():
    """The thesis's set-up: 0.3 m across the view at 1.5 m. ψ − θ (what a depth-difference
    pose measures) leaves the rule off by 2·Δθ ≈ 22°: a false actuator fault."""
    start = (0.0, 1.5, 90.0)
    end = drive(*start, distance=0.3, fault=None)
    p0, p1 = g.observe(*cylinders(*start)), g.observe(*cylinders(*end))
    d_theta = p1.angle - p0.angle
    assert d_theta == pytest.approx(math.degrees(math.atan(0.3 / 1.5)), abs=0.01)
    chosen = p1.yaw - (p0.yaw + d_theta)
    line_of_sight = (p1.heading - p1.angle) - ((p0.heading - p0.angle) + d_theta)
    assert abs(chosen) < 1e-6
    assert line_of_sight == pytest.approx(-2 * d_theta)
    assert abs(line_of_sight) > 8


def test_the_rule_is_exact_only_modulo_360_when_yaw_crosses_180():
    """A robot turned towards the camera: its Yaw (≈ 137° here) can wrap past 180°."""
    start = (0.3, 1.0, 120.0)
    end = drive(*start, distance=0.3, fault='right_actuator')
    value, _ = faulty_rule(perceive(*start), perceive(*end))
    turned = g.normalize_deg(end[2] - start[2])
    assert abs(value - turned) == pytest.approx(360.0, abs=0.05)
    assert g.normalize_deg(value) == pytest.approx(turned, abs=0.05)


# ---------------------------------------------------------------- fit_pose

def _on_robot(angle, depth, heading, layout):
    """Optical-frame points of cylinders at ``layout`` ((forward, left) m) on a robot at
    bearing ``angle``, depth ``depth``, heading ``heading`` (deg, clockwise, 0 = away)."""
    x0, z0 = depth * math.tan(math.radians(angle)), depth
    h = math.radians(heading)
    fwd = (math.sin(h), math.cos(h))           # (x, z) of the robot's forward
    left = (-math.cos(h), math.sin(h))         # its left: forward turned counter-clockwise
    return [(x0 + f * fwd[0] + l * left[0], -0.1, z0 + f * fwd[1] + l * left[1])
            for f, l in layout]


LAYOUT = {'left': (0.0, 0.1135), 'right': (0.0, -0.1135), 'back': (-0.12, 0.0)}


@pytest.mark.parametrize('roles', [('left', 'right'), ('left', 'back'), ('back', 'right'),
                                   ('left', 'right', 'back')])
@pytest.mark.parametrize('angle, depth, heading', [(0, 2.0, 0), (-20, 1.0, 30),
                                                   (15, 3.0, -120), (5, 2.0, 95),
                                                   (-10, 1.5, 180)])
def test_fit_pose_recovers_the_pose_from_any_two_cylinders(roles, angle, depth, heading):
    layout = [LAYOUT[r] for r in roles]
    pose = g.fit_pose(_on_robot(angle, depth, heading, layout), layout)
    assert pose.angle == pytest.approx(angle, abs=1e-9)
    assert pose.depth == pytest.approx(depth, abs=1e-9)
    assert g.normalize_deg(pose.heading - heading) == pytest.approx(0, abs=1e-9)
    assert pose.yaw == pytest.approx(g.normalize_deg(heading + angle), abs=1e-9)


def test_fit_pose_of_left_and_right_is_what_observe_gives():
    left, right = (-0.13, -0.1, 2.04), (0.09, -0.1, 1.97)  # not quite 0.227 apart
    fit = g.fit_pose([left, right], [LAYOUT['left'], LAYOUT['right']])
    seen = g.observe(left, right)
    for key in ('angle', 'depth', 'yaw', 'heading'):
        assert getattr(fit, key) == pytest.approx(getattr(seen, key), abs=1e-9)


def test_fit_pose_needs_two_points_with_a_place_each():
    with pytest.raises(ValueError):
        g.fit_pose([(0, 0, 2)], [(0, 0.1)])
    with pytest.raises(ValueError):
        g.fit_pose([(0, 0, 2), (0.2, 0, 2)], [(0, 0.1)])
