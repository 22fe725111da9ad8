"""The detector on synthetic Kinect-like frames (ray-cast by vision_scene, no ROS master).

Acceptance tolerances: Angle within 2°, Depth within 5 cm, Yaw within 10° with the right
sign; one cylinder hidden or nothing in view -> no robot.
"""
import math

import numpy as np
import pytest

import vision_scene as vs
from vision_synth import detector as det

ANGLE_TOL, DEPTH_TOL, YAW_TOL = 2.0, 0.05, 10.0
HEADINGS = [-60, -30, 0, 30, 60, 150, -150]
# (angle, depth): left near, centre middle, right far; then the other corners.
PLACES = [(-20, 1.0), (0, 2.0), (20, 3.0)]
CORNERS = [(-20, 3.0), (20, 1.0), (0, 1.0), (0, 3.0)]


def angle_diff(a, b):
    return (a - b + 180.0) % 360.0 - 180.0


def detect(scene, seed=0, noise=1.5, detector=None, **render):
    rgb, xyz = scene.render(noise=noise, seed=seed, **render)
    return (detector or det.Detector()).detect(rgb, xyz)


def assert_pose(found, truth, name='faulty'):
    assert [d.name for d in found] == [name], found
    pose = found[0].pose
    assert abs(pose.angle - truth['angle']) <= ANGLE_TOL, (pose, truth)
    assert abs(pose.depth - truth['depth']) <= DEPTH_TOL, (pose, truth)
    assert abs(angle_diff(pose.yaw, truth['yaw'])) <= YAW_TOL, (pose, truth)
    if YAW_TOL < abs(truth['yaw']) < 180 - YAW_TOL:  # the sign means nothing near 0 and ±180
        assert math.copysign(1, pose.yaw) == math.copysign(1, truth['yaw']), (pose, truth)


# ---------------------------------------------------------------- poses

@pytest.mark.parametrize('heading', HEADINGS)
@pytest.mark.parametrize('angle, depth', PLACES)
def test_pose_within_tolerance(angle, depth, heading):
    scene = vs.Scene((angle, depth, heading))
    assert_pose(detect(scene, seed=heading % 97), scene.truth())


@pytest.mark.parametrize('heading', [30, -150])
@pytest.mark.parametrize('angle, depth', CORNERS)
def test_pose_within_tolerance_at_the_other_corners(angle, depth, heading):
    scene = vs.Scene((angle, depth, heading))
    assert_pose(detect(scene, seed=7), scene.truth())


@pytest.mark.parametrize('heading', [0, 60, -150])
@pytest.mark.parametrize('angle, depth', PLACES)
def test_dim_light_at_30_percent_still_detected(angle, depth, heading):
    scene = vs.Scene((angle, depth, heading), light=0.3)
    rgb, xyz = scene.render(noise=1.5, seed=3)
    assert rgb.max() < 0.3 * 255 + 6  # the scene really is dim
    assert_pose(det.Detector().detect(rgb, xyz), scene.truth())


@pytest.mark.parametrize('angle, depth, heading', [(-20, 1.0, 30), (20, 3.0, -150)])
def test_dim_overhead_light_leaves_only_ambient_and_still_detects(angle, depth, heading):
    scene = vs.Scene((angle, depth, heading), light=0.3, light_from=(0.0, -1.0, 0.0))
    rgb, xyz = scene.render(noise=1.5, seed=5)
    d = det.Detector()
    masks = d.masks(rgb)
    for colour in ('green', 'orange'):  # the scene's robot has no third cylinder
        assert 0 < rgb[masks[colour] > 0].max() <= 0.3 * vs.AMBIENT * 255 + 8  # really dark
    assert_pose(d.detect(rgb, xyz), scene.truth())


@pytest.mark.parametrize('heading', [0, 180])
def test_left_cylinder_is_left_in_the_image_only_when_the_robot_faces_away(heading):
    found = detect(vs.Scene((0, 2.0, heading)))
    assert len(found) == 1
    green, orange = found[0].left, found[0].right
    assert (green.color, orange.color) == ('green', 'orange')
    assert (green.u < orange.u) == (heading == 0)
    assert abs(angle_diff(found[0].pose.yaw, heading)) < YAW_TOL


def test_robot_name_and_sides_come_from_the_robots_table():
    """Same scene, a table that says orange is this robot's LEFT: it faces the other way."""
    scene = vs.Scene((10, 2.0, 30))
    d = det.Detector(robots={'robot_b': {'left': 'orange', 'right': 'green'}})
    found = detect(scene, detector=d)
    truth = dict(scene.truth(), yaw=angle_diff(scene.truth()['yaw'] + 180.0, 0.0))
    assert_pose(found, truth, name='robot_b')


@pytest.mark.parametrize('method', ['cloud', 'pinhole', 'thesis'])
@pytest.mark.parametrize('angle', [-25, -12, 0, 12, 25])
def test_every_angle_method_is_within_2_degrees(method, angle):
    scene = vs.Scene((angle, 2.0, 30))
    found = detect(scene, noise=0.0, detector=det.Detector(angle_method=method))
    assert len(found) == 1
    assert abs(found[0].pose.angle - angle) <= ANGLE_TOL


def test_pinhole_angle_uses_the_given_intrinsics():
    scene = vs.Scene((15, 2.0, 0))
    rgb, xyz = scene.render()
    d = det.Detector(angle_method='pinhole')
    right = d.detect(rgb, xyz, det.Intrinsics(vs.FX, vs.FY, vs.CX, vs.CY))[0].pose.angle
    shifted = d.detect(rgb, xyz, det.Intrinsics(vs.FX, vs.FY, vs.CX + 50, vs.CY))[0].pose.angle
    assert right == pytest.approx(15, abs=0.5)
    assert shifted < right - 3


# ---------------------------------------------------------------- nothing to report

@pytest.mark.parametrize('show', [('left',), ('right',)])
def test_one_cylinder_missing_reports_no_robot(show):
    assert detect(vs.Scene((0, 2.0, 0), show=show)) == []


@pytest.mark.parametrize('side', [-1, 1])
def test_one_cylinder_hidden_behind_a_post_reports_no_robot(side):
    # a grey post halfway to the camera, on the line of sight of one cylinder
    x, z = vs.robot_centre(5, 2.0)
    post = (side * vs.SEPARATION / 2 * 0.5 + x * 0.5, 1.0, 0.05)
    scene = vs.Scene((5, 2.0, 0), posts=[post])
    assert detect(vs.Scene((5, 2.0, 0))) != []
    assert detect(scene) == []


def test_edge_on_robot_hides_one_cylinder_behind_the_other():
    # heading = θ + 90: both cylinders on the same line of sight
    assert detect(vs.Scene((10, 2.0, 100))) == []


# ---------------------------------------------------------------- the third cylinder

THREE = ('left', 'right', 'back')


@pytest.mark.parametrize('heading', HEADINGS + [90, -90, 180])
@pytest.mark.parametrize('angle, depth', PLACES)
def test_three_cylinders_give_the_pose_from_any_side(angle, depth, heading):
    scene = vs.Scene((angle, depth, heading), show=THREE)
    found = detect(scene, seed=heading % 89)
    assert_pose(found, scene.truth())
    assert sum(b is not None for b in (found[0].left, found[0].right, found[0].back)) >= 2


@pytest.mark.parametrize('angle, heading', [(10, 100), (-15, 75), (0, -90), (20, -70)])
def test_edge_on_robot_with_a_third_cylinder_is_still_found(angle, heading):
    # heading = θ ± 90: left and right on one line of sight, the third one beside them
    two = vs.Scene((angle, 2.0, heading))
    three = vs.Scene((angle, 2.0, heading), show=THREE)
    if angle == 10 and heading == 100:
        assert detect(two) == []  # the thesis's self-occlusion
    found = detect(three)
    assert_pose(found, three.truth())
    assert found[0].back is not None


@pytest.mark.parametrize('hidden', ['left', 'right'])
@pytest.mark.parametrize('heading', [-30, 0, 45, 150])
def test_a_hidden_side_cylinder_is_made_up_for_by_the_third(hidden, heading):
    scene = vs.Scene((8, 2.0, heading), show=set(THREE) - {hidden})
    found = detect(scene, seed=11)
    assert_pose(found, scene.truth())
    assert getattr(found[0], hidden) is None and found[0].back is not None


@pytest.mark.parametrize('show', [('back',), ('left',), ('right',)])
def test_one_of_three_cylinders_alone_is_no_robot(show):
    assert detect(vs.Scene((0, 2.0, 0), show=show)) == []


def test_a_robot_table_without_a_back_colour_ignores_a_blue_cylinder():
    scene = vs.Scene((0, 2.0, 0), show=('left', 'back'))
    assert detect(scene) != []
    two = det.Detector(robots={'faulty': {'left': 'green', 'right': 'orange'}})
    assert detect(scene, detector=two) == []


def test_a_blue_cylinder_too_far_from_the_others_is_left_out():
    # the third cylinder of a robot 0.12 m behind, and a decoy 0.5 m to the side
    scene = vs.Scene((0, 2.0, 0), show=('left', 'right'),
                     extra_pairs=[(0.5, 2.0, 0, 0.227, {'back'})])
    found = detect(scene)
    assert_pose(found, scene.truth())
    assert found[0].back is None


@pytest.mark.parametrize('scene', [vs.Scene(None), vs.Scene((45, 2.0, 0)),
                                   vs.Scene((0, 2.0, 0), show=())])
def test_nothing_in_view_is_an_empty_list(scene):
    assert detect(scene) == []


@pytest.mark.parametrize('separation, seen', [
    (0.20, False), (0.215, False), (0.227, True), (0.245, True), (0.26, False), (0.30, False)])
def test_pairs_outside_022_025_are_rejected(separation, seen):
    found = detect(vs.Scene((0, 1.5, 20), separation=separation), noise=0.0)
    assert bool(found) == seen
    if seen:
        assert found[0].pose.separation == pytest.approx(separation, abs=0.005)


@pytest.mark.parametrize('decoy_angle', [-15, 15])
def test_of_two_candidate_pairs_the_nominal_distance_wins(decoy_angle):
    # the robot (0.227 m) and a decoy pair (0.243 m, in range) elsewhere in the view
    x, z = vs.robot_centre(decoy_angle, 2.0)
    robot_angle = -decoy_angle
    scene = vs.Scene((robot_angle, 2.0, 0), extra_pairs=[(x, z, 0.0, 0.243)])
    found = detect(scene)
    assert len(found) == 1
    assert abs(found[0].pose.angle - robot_angle) <= ANGLE_TOL
    alone = detect(vs.Scene(None, extra_pairs=[(x, z, 0.0, 0.243)]))
    assert len(alone) == 1 and abs(alone[0].pose.angle - decoy_angle) <= ANGLE_TOL


def test_blob_without_depth_is_dropped():
    rgb, xyz = vs.Scene((0, 2.0, 0)).render()
    orange = det.Detector().masks(rgb)['orange'] > 0
    xyz = xyz.copy()
    xyz[orange] = np.nan
    assert det.Detector().detect(rgb, xyz) == []


def test_all_nan_cloud_reports_nothing():
    rgb, xyz = vs.Scene((0, 2.0, 0)).render()
    assert det.Detector().detect(rgb, np.full_like(xyz, np.nan)) == []


def test_opening_removes_specks_of_colour():
    scene = vs.Scene((0, 2.0, 0))
    rgb, xyz = scene.render()
    rng = np.random.default_rng(1)
    rows, cols = rng.integers(0, 480, 300), rng.integers(0, 640, 300)
    rgb[rows, cols] = (13, 166, 38)  # isolated green pixels over the wall and floor
    d = det.Detector(min_blob_area=1, min_valid_points=1)
    green = d.blobs(d.masks(rgb)['green'], xyz, 'green')
    assert len(green) == 1
    assert_pose(d.detect(rgb, xyz), scene.truth())


def test_closing_fills_holes_in_a_cylinder():
    import cv2
    rgb, xyz = vs.Scene((0, 1.5, 0)).render()
    d = det.Detector()
    before = d.masks(rgb)['green']
    interior = cv2.erode(before, np.ones((7, 7), np.uint8)) > 0
    holed = rgb.copy()
    ys, xs = np.nonzero(interior)
    holed[ys[::9], xs[::9]] = (200, 200, 200)  # specular-like single pixels inside
    raw = d.colors['green'].mask(cv2.cvtColor(holed, cv2.COLOR_RGB2HSV))
    assert (raw[interior] == 0).sum() == len(ys[::9])  # the holes are really there
    assert np.array_equal(d.masks(holed)['green'], before)


def test_opening_and_closing_around_the_pixels_equal_the_whole_frames():
    import cv2
    rng = np.random.default_rng(3)
    for kernel in (2, 3, 5):
        d = det.Detector(kernel_size=kernel)
        for _ in range(20):
            mask = np.zeros((120, 160), np.uint8)
            for _ in range(rng.integers(1, 4)):  # a few blobs with holes and specks, some at the edge
                y, x = rng.integers(0, 120), rng.integers(0, 160)
                mask[y:y + rng.integers(1, 30), x:x + rng.integers(1, 30)] = 255
            specks = rng.random(mask.shape) < 0.01
            mask[specks] = 255 - mask[specks]
            whole = cv2.morphologyEx(mask, cv2.MORPH_OPEN, np.ones((kernel, kernel), np.uint8))
            whole = cv2.morphologyEx(whole, cv2.MORPH_CLOSE, np.ones((kernel, kernel), np.uint8))
            d._open_close(mask)
            np.testing.assert_array_equal(mask, whole)


def test_blobs_are_where_they_are_in_the_frame_and_depth_points_give_the_same_blobs():
    from vision_synth import cloud
    scene = vs.Scene((-15, 1.5, 40))
    rgb, xyz = scene.render()
    d = det.Detector()
    mask = d.masks(rgb)['orange']
    ys, xs = np.nonzero(mask)
    (blob,) = d.blobs(mask, xyz, 'orange')
    assert (blob.u, blob.v, blob.area) == (pytest.approx(xs.mean()), pytest.approx(ys.mean()), len(xs))
    lazy = cloud.DepthPoints(xyz[..., 2], vs.Intrinsics())
    (same,) = d.blobs(mask, lazy, 'orange')
    np.testing.assert_allclose(same.surface, blob.surface, atol=1e-6)
    whole = cloud.depth_to_points(xyz[..., 2], vs.Intrinsics())
    assert repr(d.detect(rgb, lazy)) == repr(d.detect(rgb, whole))
    assert d.blobs(np.zeros_like(mask), xyz) == []


def test_bgr_input():
    scene = vs.Scene((-10, 2.0, 30))
    rgb, xyz = scene.render()
    assert_pose(det.Detector().detect(np.ascontiguousarray(rgb[..., ::-1]), xyz, bgr=True),
                scene.truth())


# ---------------------------------------------------------------- bad input and parameters

@pytest.mark.parametrize('image, xyz', [
    (np.zeros((0, 0, 3), np.uint8), np.zeros((0, 0, 3), np.float32)),
    (np.zeros((480, 640, 3), np.uint8), np.zeros((240, 320, 3), np.float32)),
    (np.zeros((480, 640), np.uint8), np.zeros((480, 640, 3), np.float32)),
    (np.zeros((480, 640, 3), np.float32), np.zeros((480, 640, 3), np.float32)),
    (np.zeros((480, 640, 3), np.uint8), np.zeros((480, 640, 3), np.int16)),
    (np.zeros((480, 640, 4), np.uint8), np.zeros((480, 640, 3), np.float32)),
    (None, np.zeros((480, 640, 3), np.float32)),
])
def test_bad_frames_raise_frame_error(image, xyz):
    with pytest.raises(det.FrameError):
        det.Detector().detect(image, xyz)


def test_small_frames_work():
    rgb, xyz = vs.Scene((0, 1.0, 0)).render(
        intrinsics=vs.Intrinsics(vs.FX / 2, vs.FY / 2, 159.5, 119.5), width=320, height=240)
    assert len(det.Detector().detect(rgb, xyz)) == 1


@pytest.mark.parametrize('kwargs', [
    {'robots': {'faulty': {'left': 'green', 'right': 'purple'}}},
    {'robots': {'Faulty': {'left': 'green', 'right': 'orange'}}},
    {'robots': {'faulty': {'left': 'green', 'right': 'green'}}},
    {'robots': {'faulty': {'left': 'green'}}},
    {'robots': {'faulty': {'left': 'green', 'right': 'orange', 'back': 'green'}}},
    {'robots': {'faulty': {'left': 'green', 'right': 'orange', 'front': 'blue'}}},
    {'robots': {'faulty': {'left': 'green', 'right': 'orange', 'back': 'purple'}}},
    {'back_offset': 0},
    {'robots': {}},
    {'colors': {'green': {'h': [40, 200]}}},
    {'colors': {'green': {'h': [40]}}},
    {'colors': {'green': {'h': [40, 90], 'x': [1, 2]}}},
    {'colors': {'green': {'h': [40, 90], 's': [200, 100]}}},
    {'colors': 'green'},
    {'pair_min': 0.23},
    {'pair_max': 0.2},
    {'angle_method': 'magic'},
    {'kernel_size': 0},
    {'fov': 0},
    {'no_such_option': 1},
])
def test_bad_parameters_raise_config_error(kwargs):
    with pytest.raises(det.ConfigError):
        det.Detector(**kwargs)


def test_hue_range_wraps_through_zero_for_reds():
    red = det.ColorRange('red', (170, 10), (100, 255), (50, 255))
    hsv = np.array([[[0, 200, 200], [5, 200, 200], [175, 200, 200], [90, 200, 200],
                     [175, 50, 200]]], np.uint8)
    assert list(red.mask(hsv)[0] > 0) == [True, True, True, False, False]


def test_default_hsv_ranges_accept_the_simulator_colours_dimmed_and_reject_grey():
    import cv2
    colors = det.parse_colors(det.DEFAULT_COLORS)
    for name, rgb in (('green', vs.GREEN), ('orange', vs.ORANGE), ('blue', vs.BLUE)):
        for scale in (1.0, 0.6, 0.3, 0.3 * vs.AMBIENT, 0.25 * 0.3):  # to 25 % of 30 % ambient
            pixel = np.array([[[round(c * scale * 255) for c in rgb]]], np.uint8)
            hsv = cv2.cvtColor(pixel, cv2.COLOR_RGB2HSV)
            assert colors[name].mask(hsv)[0, 0] == 255, (name, scale, pixel, hsv)
            for other in set(colors) - {name}:
                assert colors[other].mask(hsv)[0, 0] == 0, (name, other, scale)
    # greys, and the simulator's other materials (wall, plate, base, obstacle) lit or dim
    others = [(g, g, g) for g in (0.04, 0.25, 0.5, 1.0)] + [
        (0.75, 0.75, 0.73), (0.35, 0.3, 0.25), (0.18, 0.18, 0.2), (0.4, 0.4, 0.45)]
    for rgb in others:
        for scale in (1.0, 0.3, 0.1):
            pixel = np.array([[[round(c * scale * 255) for c in rgb]]], np.uint8)
            hsv = cv2.cvtColor(pixel, cv2.COLOR_RGB2HSV)
            assert all(c.mask(hsv)[0, 0] == 0 for c in colors.values()), (rgb, scale, hsv)
