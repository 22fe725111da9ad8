"""Robots' poses in time: true and believed, the odometry frame placed in the world by
/tf_static or by the first true pose, thinning, the map's bounds (no ROS)."""
import math

import pytest

from rason_dashboard import fleet_poses as fp
from rason_dashboard.fleet_poses import FleetPoses
from rason_dashboard.poses import anchor, compose, inverse, robot_of


def pose(x, y, yaw=0.0):
    return {'x': x, 'y': y, 'yaw': yaw}


def close(a, b):
    return a['x'] == pytest.approx(b['x']) and a['y'] == pytest.approx(b['y']) and \
        math.cos(a['yaw'] - b['yaw']) == pytest.approx(1.0)


def test_frames():
    a, b = pose(1, 2, math.pi / 2), pose(1, 0, 0.3)
    assert close(compose(a, b), pose(1, 3, math.pi / 2 + 0.3))
    assert close(compose(a, inverse(a)), pose(0, 0))
    assert close(compose(anchor(a, b), b), a)
    assert robot_of('/r1/true_pose') == 'r1' and robot_of('/r1/rason_mas') == 'r1' and robot_of('/odom') == ''


def test_believed_pose_from_the_odometry_frame_in_the_world():
    poses = FleetPoses()
    poses.add(0.0, 'origin', 'r1', pose(2, 0, math.pi))  # facing -x
    poses.add(0.0, 'true', 'r1', pose(2, 0, math.pi))
    poses.add(0.0, 'odom', 'r1', pose(0, 0))
    poses.add(1.0, 'true', 'r1', pose(1, 0, math.pi))
    poses.add(1.0, 'odom', 'r1', pose(1.2, 0))  # 20 % too far
    assert close(poses.at(1.0)['r1']['believed'], pose(0.8, 0, math.pi))
    assert close(poses.at(0.5)['r1']['true'], pose(2, 0, math.pi))
    assert poses.bounds() == pytest.approx([0.8 - fp.MARGIN, -fp.MARGIN, 2 + fp.MARGIN, fp.MARGIN])


def test_without_tf_static_the_first_true_pose_places_the_odometry():
    poses = FleetPoses()
    poses.add(0.0, 'true', 'r2', pose(0, 2, -math.pi / 2))
    poses.add(0.0, 'odom', 'r2', pose(0, 0))
    poses.add(1.0, 'odom', 'r2', pose(1, 0))
    assert close(poses.at(None)['r2']['believed'], pose(0, 1, -math.pi / 2))


def test_a_real_robot_without_truth_is_drawn_in_its_odometry_frame():
    poses = FleetPoses()
    poses.add(0.0, 'odom', 'rover', pose(0.5, 0))
    (only,) = poses.at(None).values()
    assert only['true'] is None and only['believed'] == dict(pose(0.5, 0), frame='odom')


def test_poses_thinned_and_none_before_the_first():
    poses = FleetPoses()
    for k in range(50):  # 50 Hz for a second
        poses.add(k * 0.02, 'true', 'r1', pose(k * 0.02, 0))
    kept = [poses.at(k * 0.02)['r1']['true']['x'] for k in range(50)]
    assert len(set(kept)) == pytest.approx(1.0 / fp.POSE_PERIOD, abs=1)
    assert poses.at(-1.0) == {} and FleetPoses().bounds() is None


def test_a_pose_that_is_not_finite_is_left_out():
    poses = FleetPoses()
    assert poses.add(0.0, 'true', 'r1', pose(1, 0)) is True
    assert poses.add(1.0, 'true', 'r1', pose(float('nan'), 0)) is False
    assert poses.add(2.0, 'odom', 'r1', pose(0, 0, float('inf'))) is False
    assert poses.at(None) == {'r1': {'true': pose(1, 0), 'believed': None}}
