"""The detector on recorded frames in fixtures/ (simulator renders and synthetic ones).

Every complete fixture (``<name>_rgb.png``, ``<name>_depth.png``, ``<name>.json``) is a
test case: ``expected`` null -> nothing reported; else that robot, Angle within 2°, Depth
within 5 cm, Yaw within 10° with the right sign. See vision_fixtures for the format.
"""
import math

import numpy as np
import pytest

import vision_fixtures
import vision_scene as vs
from vision_synth import detector as det

ANGLE_TOL, DEPTH_TOL, YAW_TOL = 2.0, 0.05, 10.0


def angle_diff(a, b):
    return (a - b + 180.0) % 360.0 - 180.0


def test_there_are_fixtures_with_and_without_a_robot():
    metas = [vision_fixtures.load(n)[2] for n in vision_fixtures.names()]
    assert any(m['expected'] is None for m in metas)
    assert any(m['expected'] is not None for m in metas)


@pytest.mark.parametrize('name', vision_fixtures.names())
def test_fixture(name):
    rgb, xyz, meta = vision_fixtures.load(name)
    intrinsics = det.Intrinsics(meta['fx'], meta['fy'], meta['cx'], meta['cy'])
    found = det.Detector().detect(rgb, xyz, intrinsics)
    expected = meta['expected']
    if expected is None:
        assert found == []
        return
    assert [d.name for d in found] == [expected['name']], found
    pose = found[0].pose
    assert abs(pose.angle - expected['angle']) <= ANGLE_TOL, pose
    assert abs(pose.depth - expected['depth']) <= DEPTH_TOL, pose
    assert abs(angle_diff(pose.yaw, expected['yaw'])) <= YAW_TOL, pose
    if YAW_TOL < abs(expected['yaw']) < 180 - YAW_TOL:  # the sign means nothing near 0, ±180
        assert math.copysign(1, pose.yaw) == math.copysign(1, expected['yaw']), pose


def test_loader_round_trip(tmp_path):
    scene = vs.Scene((8.0, 1.7, -30.0))
    rgb, xyz = scene.render()
    xyz[:5, :5] = np.nan
    meta = {'fx': vs.FX, 'fy': vs.FY, 'cx': vs.CX, 'cy': vs.CY, 'expected': None}
    vision_fixtures.save('case', rgb, xyz, meta, folder=str(tmp_path))
    assert vision_fixtures.names(str(tmp_path)) == ['case']
    rgb2, xyz2, meta2 = vision_fixtures.load('case', folder=str(tmp_path))
    np.testing.assert_array_equal(rgb2, rgb)
    assert np.isnan(xyz2[:5, :5]).all()
    np.testing.assert_allclose(xyz2[5:], xyz[5:], atol=0.0006 * 3)  # millimetre depth
    assert meta2 == meta
