"""Run planning: deterministic, jitter within bounds, interaction faults as launch args."""
import math
import re

import pytest

from rason_campaign import cli, fleet_plan, plan, poses


def test_same_options_same_plan():
    a = plan.make_plan(plan.FAULTS, 3, 7)
    b = plan.make_plan(plan.FAULTS, 3, 7)
    assert a == b
    assert len(a) == 15


def test_numbers_seeds_and_fault_order():
    p = plan.make_plan(('left_actuator', 'none'), 2, 1)
    assert [(s.number, s.fault, s.seed) for s in p] == [
        (1, 'left_actuator', 1001), (2, 'left_actuator', 1002), (3, 'none', 1003), (4, 'none', 1004)]
    assert p[2].name == '003_none_1003'
    assert all(s.args['seed'] == s.seed and s.args['fault'] == s.fault for s in p)


def test_other_seed_other_jitter():
    a = plan.make_plan(('none',), 1, 1)[0].args
    b = plan.make_plan(('none',), 1, 2)[0].args
    assert a['faulty_x'] != b['faulty_x']


def test_jitter_within_bounds_around_nominal():
    for spec in plan.make_plan(plan.FAULTS, 20, 3):
        for key, nominal in plan.NOMINAL.items():
            bound = plan.YAW_JITTER if key.endswith('yaw') else plan.POSITION_JITTER
            assert abs(spec.args[key] - nominal) <= bound + 1e-4, key
        assert plan.BRIGHTNESS_RANGE[0] <= spec.args['brightness'] <= plan.BRIGHTNESS_RANGE[1]
    # Faulty still faces away from Helper (the nominal yaw is -90 degrees).
    assert abs(math.degrees(spec.args['faulty_yaw']) + 90) <= 3.01


def test_no_jitter_is_nominal():
    args = plan.make_plan(('none',), 1, 5, jitter=False)[0].args
    assert {k: args[k] for k in plan.NOMINAL} == plan.NOMINAL
    assert args['brightness'] == 1.0


@pytest.mark.parametrize('interaction', sorted(plan.INTERACTIONS))
def test_interaction_fault_is_a_launch_argument(interaction):
    spec = plan.make_plan(('odometry',), 2, 1, interaction=interaction)[1]
    args = plan.launch_arguments(spec, '/tmp/x.bag')
    assert 'interaction:=%s' % interaction in args
    # dim sets the brightness itself: a jittered one would override it.
    assert any(a.startswith('brightness:=') for a in args) == (interaction != 'dim')


def test_launch_arguments_record_to_the_bag():
    spec = plan.make_plan(('both_actuators',), 1, 1, rate=2.0)[0]
    args = plan.launch_arguments(spec, '/tmp/x.bag')
    assert 'record:=true' in args and 'bag:=/tmp/x.bag' in args
    assert 'fault:=both_actuators' in args and 'rate:=2.0' in args and 'seed:=1001' in args
    assert 'occlude:=true' not in args
    assert 'dialogue:=false' in args  # the bag holds what it would print


def test_spec_round_trips_through_dict():
    spec = plan.make_plan(('none',), 1, 9)[0]
    assert plan.RunSpec.from_dict(spec.to_dict()) == spec


@pytest.mark.parametrize('text,expected', [
    ('all', plan.FAULTS), ('none', ('none',)),
    (' odometry, left_actuator ', ('odometry', 'left_actuator'))])
def test_parse_faults(text, expected):
    assert plan.parse_faults(text) == expected


@pytest.mark.parametrize('text', ['', 'left', 'none,none', 'all,none'])
def test_parse_faults_rejects(text):
    with pytest.raises(plan.PlanError):
        plan.parse_faults(text)


@pytest.mark.parametrize('kwargs', [{'runs': 0}, {'interaction': 'fog'}, {'rate': -1}])
def test_bad_options(kwargs):
    options = dict(faults=plan.FAULTS, runs=1, seed=1)
    options.update(kwargs)
    with pytest.raises(plan.PlanError):
        plan.make_plan(**options)


def test_varied_runs_draw_poses_lighting_camera_noise_severity_and_slip_from_their_seed():
    specs = plan.make_plan(['left_actuator'], 40, 3, varied=True)
    assert plan.make_plan(['left_actuator'], 40, 3, varied=True)[7].args == specs[7].args
    for spec in specs:
        a = spec.args
        assert a['fault'] == 'left_actuator' and a['seed'] == spec.seed
        assert 1.0 - 1e-3 <= poses.distance(a) <= 3.0 + 1e-3
        assert 0.6 <= a['brightness'] <= 1.2
        assert 1.0 <= a['depth_noise'] <= 2.0
        assert 0.0 <= a['depth_dropout'] <= 0.05
        assert 0.3 <= a['severity'] <= 1.0
        for robot in ('helper', 'faulty'):
            left, right = a[robot + '_left_slip'], a[robot + '_right_slip']
            assert 0.0 <= left <= 0.055 and 0.0 <= right <= 0.055
            assert abs(left - right) <= 0.01 + 1e-4
        # the poses are spread_poses's of the run's seed: the other draws leave them alone
        assert {k: a[k] for k in poses.spread_poses(spec.seed)} == \
            poses.spread_poses(spec.seed, plan.VARIED_DISTANCE, plan.VARIED_FACING_AWAY)
    assert len({s.args['depth_noise'] for s in specs}) > 30   # each run draws its own
    severities = sorted(s.args['severity'] for s in specs)
    assert severities[0] < 0.45 and severities[-1] > 0.85      # mild ones and near-total ones
    slips = sorted(s.args['faulty_left_slip'] for s in specs)
    assert slips[0] < 0.01 and slips[-1] > 0.04
    assert any(s.args['faulty_left_slip'] != s.args['faulty_right_slip'] for s in specs)


def test_varied_dim_runs_leave_the_brightness_to_the_interaction():
    spec = plan.make_plan(['none'], 1, 1, interaction='dim', varied=True)[0]
    assert 'brightness' not in spec.args and 'depth_noise' in spec.args


@pytest.mark.parametrize('make', [
    lambda **kw: plan.make_plan(['left_actuator'], 2, 1, **kw),
    lambda **kw: plan.make_mission_plan(['left_actuator'], 1, 1, **kw)])
def test_third_marker_is_a_launch_argument_only_when_asked_for(make):
    assert all('third_marker' not in s.args for s in make())
    specs = make(third_marker=True)
    assert all('third_marker:=true' in plan.launch_arguments(s, '/tmp/x.bag') for s in specs)
    # the rest of the plan is what it was: the same poses and seeds
    assert [dict(s.args, third_marker=None) for s in specs] == \
        [dict(s.args, third_marker=None) for s in make()]


def _right_cylinder(args):
    yaw = args['faulty_yaw']
    return (args['faulty_x'] + plan.MARKER_SEPARATION / 2 * math.sin(yaw),
            args['faulty_y'] - plan.MARKER_SEPARATION / 2 * math.cos(yaw))


@pytest.mark.parametrize('args', [plan.NOMINAL] + [plan.varied_args(s) for s in range(1, 40)])
def test_the_box_stands_on_helper_s_line_of_sight_in_front_of_the_orange_cylinder(args):
    box = plan.occluding_box(args)
    hx, hy = args['helper_x'], args['helper_y']
    rx, ry = _right_cylinder(args)
    bx, by = box['box_x'], box['box_y']
    # on the segment from Helper to the cylinder (mm rounding), 0.5 m short of the cylinder
    cross = (rx - hx) * (by - hy) - (ry - hy) * (bx - hx)
    assert abs(cross) / math.hypot(rx - hx, ry - hy) < 2e-3
    assert math.hypot(rx - bx, ry - by) == pytest.approx(plan.BOX_IN_FRONT, abs=2e-3)
    assert math.hypot(bx - hx, by - hy) < math.hypot(rx - hx, ry - hy)


def test_the_nominal_box_is_the_launch_file_s_default():
    # faulty_helper.launch: box_at_x/box_at_y for interaction:=box
    assert plan.occluding_box(plan.NOMINAL) == {'box_x': -1.076, 'box_y': -0.251}


@pytest.mark.parametrize('make', [
    lambda **kw: plan.make_plan(['left_actuator'], 2, 1, **kw),
    lambda **kw: plan.make_plan(['left_actuator'], 2, 1, varied=True, **kw),
    lambda **kw: plan.make_mission_plan(['left_actuator'], 1, 1, **kw)])
def test_a_box_run_gets_its_box_for_its_own_poses_and_others_none(make):
    assert all('box_x' not in s.args for s in make(interaction='occlusion'))
    for spec in make(interaction='box'):
        assert spec.args['interaction'] == 'box'
        assert (spec.args['box_x'], spec.args['box_y']) == tuple(
            plan.occluding_box(spec.args).values())


def test_command_line_third_marker():
    assert cli.parse_args(['--out', 'x', '--third-marker']).third_marker
    assert not cli.parse_args(['--out', 'x']).third_marker


def test_varied_is_not_nominal():
    with pytest.raises(plan.PlanError, match='varied'):
        plan.make_plan(['none'], 1, 1, jitter=False, varied=True)


@pytest.mark.parametrize('argv', [['--varied', '--no-jitter'],
                                  ['--varied', '--scenario', 'fault_tolerance']])
def test_command_line_refuses_varied_with_what_it_contradicts(argv, capsys):
    with pytest.raises(SystemExit):
        cli.parse_args(['--out', 'x'] + argv)
    assert '--varied' in capsys.readouterr().err


def test_output_dirs_makes_a_new_report_directory_when_the_bags_go_elsewhere(tmp_path):
    out, bags = tmp_path / 'new' / 'report', tmp_path / 'bags'
    assert cli.output_dirs(str(out), str(bags)) == str(bags)
    assert out.is_dir() and bags.is_dir()


def test_output_dirs_puts_the_bags_under_the_report_by_default(tmp_path):
    out = tmp_path / 'report'
    assert cli.output_dirs(str(out)) == str(out / 'bags')
    assert (out / 'bags').is_dir()


def _declared_args(launch):
    import os
    import xml.etree.ElementTree as ET
    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'launch', launch)
    return {a.get('name'): a for a in ET.parse(path).getroot().findall('arg')}


@pytest.mark.parametrize('make', [
    lambda **kw: plan.make_plan(plan.FAULTS, 1, 1, **kw),
    lambda **kw: plan.make_plan(plan.FAULTS, 1, 1, varied=True, **kw),
    lambda **kw: plan.make_mission_plan(plan.FAULTS, 1, 1, fault_at=2.0, **kw),
    lambda **kw: fleet_plan.make_fleet_plan((4, 6), 2, 1)])
@pytest.mark.parametrize('interaction', sorted(plan.INTERACTIONS))
def test_every_argument_a_run_passes_is_one_its_launch_file_declares(make, interaction):
    # roslaunch stops at an argument its file does not declare
    for spec in make(interaction=interaction, third_marker=True, images=True):
        launch = spec.launch[-1]
        declared = _declared_args(launch)
        extra = {a.split(':=')[0] for a in plan.launch_arguments(spec, 'b')} - set(declared)
        assert not extra, '%s does not declare %s' % (launch, sorted(extra))


def test_the_launch_file_knows_the_same_interactions_as_the_plan():
    known = _declared_args('faulty_helper.launch')['interaction_is_known'].get('value')
    listed = re.search(r" in \(([^)]*)\)", known).group(1)   # str(interaction) in ('none', 'dim', ...)
    assert sorted(v.strip(" '") for v in listed.split(',')) == sorted(plan.INTERACTIONS)
