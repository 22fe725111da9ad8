"""The fault-tolerance campaign's plan: spread start poses (distance, facing away, any
heading for the Helper, inside the room, a pure function of the seed) and each planned run
made in both arms with the same seed and poses."""
import math

import pytest

from rason_campaign import plan, poses

SEEDS = range(1000, 1400)
LIMIT = poses.ROOM_HALF - poses.WALL_MARGIN     # 2.5 m: 1.5 m from the 8 x 8 m room's walls
EPS = 1e-3                                      # rounding of the launch arguments


def angle_between(a, b):
    return abs(poses.wrap(a - b))


def test_same_seed_same_poses_other_seed_other_poses():
    assert poses.spread_poses(1234) == poses.spread_poses(1234)
    assert poses.spread_poses(1234) != poses.spread_poses(1235)


def test_distance_is_within_1_2_and_2_2_m_and_spread_over_it():
    distances = [poses.distance(poses.spread_poses(s)) for s in SEEDS]
    assert all(1.2 - EPS <= d <= 2.2 + EPS for d in distances)
    # uniform, not piled up at one end: both ends of the range are drawn
    assert min(distances) < 1.3 and max(distances) > 2.1
    assert 1.6 < sum(distances) / len(distances) < 1.8


def test_faulty_faces_away_from_the_helper_within_25_degrees():
    offsets = []
    for s in SEEDS:
        p = poses.spread_poses(s)
        offsets.append(math.degrees(angle_between(p['faulty_yaw'], poses.bearing(p))))
    assert max(offsets) <= 25.0 + 0.01
    assert max(offsets) > 20.0   # the whole ±25° is used


def test_helper_heading_is_anywhere_so_it_must_search():
    headings = [poses.spread_poses(s)['helper_yaw'] for s in SEEDS]
    assert all(-math.pi - EPS < h <= math.pi + EPS for h in headings)
    # every quarter of the circle is drawn, and the Helper often does not face Faulty
    quarters = {int((h + math.pi) // (math.pi / 2)) % 4 for h in headings}
    assert quarters == {0, 1, 2, 3}
    away = [s for s in SEEDS if angle_between(poses.spread_poses(s)['helper_yaw'],
                                              poses.bearing(poses.spread_poses(s))) > math.pi / 2]
    assert len(away) > len(SEEDS) / 4


def test_both_robots_start_at_least_1_5_m_from_the_walls():
    for s in SEEDS:
        p = poses.spread_poses(s)
        for key in ('helper_x', 'helper_y', 'faulty_x', 'faulty_y'):
            assert abs(p[key]) <= LIMIT + EPS, (s, key, p[key])
        # the mission's goal (1 m ahead of Faulty) stays in the room with room to spare
        gx = p['faulty_x'] + math.cos(p['faulty_yaw'])
        gy = p['faulty_y'] + math.sin(p['faulty_yaw'])
        assert max(abs(gx), abs(gy)) <= LIMIT + 1.0 + EPS


def test_positions_cover_the_allowed_square():
    xs = [poses.spread_poses(s)['helper_x'] for s in SEEDS]
    assert min(xs) < -2.0 and max(xs) > 2.0


@pytest.mark.parametrize('angle,expected', [
    (0.0, 0.0), (math.pi, math.pi), (-math.pi, math.pi), (3 * math.pi / 2, -math.pi / 2)])
def test_wrap(angle, expected):
    assert poses.wrap(angle) == pytest.approx(expected)


def test_mission_plan_runs_each_planned_run_in_both_arms_with_the_same_seed_and_poses():
    p = plan.make_mission_plan(('left_actuator', 'none'), 2, 3, fault_at=2.5)
    assert [(s.number, s.fault, s.seed, s.arm) for s in p] == [
        (1, 'left_actuator', 3001, 'recovery'), (1, 'left_actuator', 3001, 'baseline'),
        (2, 'left_actuator', 3002, 'recovery'), (2, 'left_actuator', 3002, 'baseline'),
        (3, 'none', 3003, 'recovery'), (3, 'none', 3003, 'baseline'),
        (4, 'none', 3004, 'recovery'), (4, 'none', 3004, 'baseline')]
    for recovery, baseline in zip(p[::2], p[1::2]):
        assert recovery.args == baseline.args
        assert {k: recovery.args[k] for k in poses.spread_poses(0)} == \
            poses.spread_poses(recovery.seed)
        assert recovery.args['fault_at'] == 2.5 and recovery.args['seed'] == recovery.seed
    assert p[0].args != p[2].args                      # another seed, other poses
    assert plan.make_mission_plan(('left_actuator', 'none'), 2, 3, fault_at=2.5) == p


def test_arms_run_their_launch_files_with_the_same_arguments():
    recovery, baseline = plan.make_mission_plan(('odometry',), 1, 1)
    assert recovery.launch == ('rason', 'fault_tolerance.launch')
    assert baseline.launch == ('rason', 'faulty_helper.launch')
    assert recovery.name == '001_odometry_1001_recovery'
    assert baseline.name == '001_odometry_1001_baseline'
    args = plan.launch_arguments(baseline, '/tmp/b.bag')
    assert plan.launch_arguments(recovery, '/tmp/b.bag') == args
    assert 'fault_at:=0.0' in args and 'fault:=odometry' in args and 'record:=true' in args
    # fault_tolerance.launch declares no brightness: the scenario leaves it at the default
    assert not any(a.startswith('brightness:=') for a in args)


def test_a_diagnosis_run_keeps_its_launch_name_and_dict():
    spec = plan.make_plan(('none',), 1, 1)[0]
    assert spec.arm is None and spec.launch == ('rason', 'faulty_helper.launch')
    assert 'arm' not in spec.to_dict() and spec.name == '001_none_1001'


def test_mission_spec_round_trips_through_dict():
    spec = plan.make_mission_plan(('none',), 1, 9)[1]
    assert plan.RunSpec.from_dict(spec.to_dict()) == spec
    assert spec.to_dict()['arm'] == 'baseline'


@pytest.mark.parametrize('kwargs', [{'runs': 0}, {'interaction': 'fog'}, {'rate': -1},
                                    {'fault_at': -1.0}, {'fault_at': float('nan')},
                                    {'fault_at': float('inf')}])
def test_bad_mission_options(kwargs):
    options = dict(faults=plan.FAULTS, runs=1, seed=1)
    options.update(kwargs)
    with pytest.raises(plan.PlanError):
        plan.make_mission_plan(**options)


def test_spread_poses_takes_other_ranges():
    distances, offsets = [], []
    for s in SEEDS:
        p = poses.spread_poses(s, (1.0, 3.0), math.radians(30))
        distances.append(poses.distance(p))
        offsets.append(math.degrees(angle_between(p['faulty_yaw'], poses.bearing(p))))
        for key in ('helper_x', 'helper_y', 'faulty_x', 'faulty_y'):
            assert abs(p[key]) <= LIMIT + EPS, (s, key, p[key])
    assert all(1.0 - EPS <= d <= 3.0 + EPS for d in distances)
    assert min(distances) < 1.1 and max(distances) > 2.9
    assert 25.0 < max(offsets) <= 30.0 + 0.01
