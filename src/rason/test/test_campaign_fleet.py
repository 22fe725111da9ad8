"""The fleet campaign (issue 34): its plan, the judging of a run from its events, the report
and the node that ends a run (no ROS master)."""
import json
import math
import os

import pytest

from diagnostic_msgs.msg import DiagnosticStatus, KeyValue

from rason_campaign import cli, fleet_judge, fleet_plan, fleet_report, fleet_runs, plan
from rason_tools.missions_done import MissionsAwaited


# --- the plan ---

def test_same_options_same_plan_and_both_arms_share_seed_poses_and_faults():
    a = fleet_plan.make_fleet_plan((4, 6), 3, 7)
    assert [s.to_dict() for s in a] == [s.to_dict() for s in fleet_plan.make_fleet_plan((4, 6), 3, 7)]
    assert len(a) == 2 * 2 * 3
    for cn, bc in zip(a[::2], a[1::2]):
        assert (cn.arm, bc.arm) == fleet_plan.FLEET_ARMS
        assert cn.number == bc.number and cn.seed == bc.seed == 7000 + cn.number
        assert dict(cn.args, helpers=None) == dict(bc.args, helpers=None)
        assert (cn.args['helpers'], bc.args['helpers']) == ('contract_net', 'broadcast')
        assert cn.launch == ('rason', 'fleet_case_study.launch')
    assert [len(s.args['robots'].split()) for s in a] == [4] * 6 + [6] * 6
    assert fleet_plan.make_fleet_plan((4,), 1, 8)[0].args['poses'] != a[0].args['poses']


def test_every_fault_comes_first_in_turn_and_a_run_has_one_or_two_faulty_robots_of_its_fleet():
    specs = fleet_plan.make_fleet_plan((4, 6), 40, 1)[::2]
    counts = {1: 0, 2: 0}
    for index, spec in enumerate(specs):
        faults = fleet_judge.parse_pairs(spec.args['faults'])
        assert fleet_plan.FLEET_FAULTS[(index % 40) % 4] in faults.values()
        assert set(faults) <= set(spec.args['robots'].split())
        assert set(faults.values()) <= set(fleet_plan.FLEET_FAULTS)
        counts[len(faults)] += 1
        assert spec.fault == '+'.join(faults[r] for r in sorted(faults))
    assert counts[1] > 20 and counts[2] > 20          # about half and half of 80


def test_start_poses_on_the_ring_facing_the_centre_and_apart():
    for seed in range(1, 200):
        poses = fleet_plan.fleet_poses(seed, fleet_plan.robots_of(8))
        for x, y, yaw in poses.values():
            assert fleet_plan.RADIUS[0] - 1e-3 <= math.hypot(x, y) <= fleet_plan.RADIUS[1] + 1e-3
            to_centre = math.atan2(-y, -x)
            off = abs(math.atan2(math.sin(yaw - to_centre), math.cos(yaw - to_centre)))
            assert off <= fleet_plan.HEADING_JITTER + 1e-3
        points = list(poses.values())
        closest = min(math.hypot(a[0] - b[0], a[1] - b[1])
                      for i, a in enumerate(points) for b in points[i + 1:])
        assert closest >= 1.1


def test_the_launch_arguments_of_a_fleet_run():
    spec = fleet_plan.make_fleet_plan((4,), 1, 1)[0]
    args = dict(a.split(':=', 1) for a in plan.launch_arguments(spec, '/b/x.bag'))
    assert args['record'] == 'true' and args['bag'] == '/b/x.bag' and args['end_when_done'] == 'true'
    assert 'dialogue' not in args
    assert args['robots'] == 'r1 r2 r3 r4' and args['recovery'] == 'true' and args['rate'] == '0.0'
    entries = args['poses'].split()
    assert [e.split(':')[0] for e in entries] == ['r1', 'r2', 'r3', 'r4']
    assert all(len(e.split(':')[1].split(',')) == 3 for e in entries)


@pytest.mark.parametrize('sizes, runs', [((3,), 1), ((9,), 1), ((), 1), ((4,), 0)])
def test_bad_fleet_options(sizes, runs):
    with pytest.raises(plan.PlanError):
        fleet_plan.make_fleet_plan(sizes, runs, 1)


def test_parse_sizes():
    assert fleet_plan.parse_sizes('4,6') == (4, 6)
    for bad in ('four', '4,4'):
        with pytest.raises(plan.PlanError):
            fleet_plan.parse_sizes(bad)


@pytest.mark.parametrize('extra', [['--faults', 'odometry'], ['--interaction', 'dim'], ['--images']])
def test_the_fleet_scenario_refuses_what_it_draws_itself(extra, capsys):
    with pytest.raises(SystemExit):
        cli.parse_args(['--scenario', 'fleet', '--out', 'x'] + extra)
    assert 'not for --scenario fleet' in capsys.readouterr().err


def test_the_fleet_scenario_runs_on_the_lockstep_by_default():
    args = cli.parse_args(['--scenario', 'fleet', '--out', 'x'])
    assert (args.rate, args.timeout, args.sizes) == (0.0, 600.0, '4,6')


def test_resume_needs_a_plan(tmp_path):
    with pytest.raises(SystemExit) as e:
        cli.main(['--scenario', 'fleet', '--resume', '--out', str(tmp_path / 'none')])
    assert 'no ' in str(e.value) and 'plan.json' in str(e.value)


# --- judging a run ---

def pose(t, robot, x, y, yaw=0.0):
    return (t, 'pose', {'robot': robot, 'x': x, 'y': y, 'yaw': yaw})


def msg(t, sender, receiver, content):
    return (t, 'message', {'sender': sender, 'receiver': receiver, 'performative': 'achieve',
                           'content': content})


def status(t, kind, agent, **values):
    return (t, kind, dict(values, agent=agent))


def there_and_back(robot, t0, x0, y0, yaw=0.0, reach=1.0, back=0.0):
    """True poses of a robot that drives ``reach`` m ahead and ends ``back`` m from its start."""
    gx, gy = x0 + reach * math.cos(yaw), y0 + reach * math.sin(yaw)
    return [pose(t0, robot, x0, y0, yaw), pose(t0 + 5, robot, gx, gy, yaw),
            pose(t0 + 10, robot, x0 + back, y0, yaw)]


ARGS = {'robots': 'r1 r2 r3 r4', 'faults': 'r4:left_actuator'}


def good_run():
    events = []
    for robot, x in (('r1', 2.0), ('r2', 0.0), ('r3', -2.0)):
        events += there_and_back(robot, 0, x, 2.0)
        events.append(status(10.0, 'diagnosis', robot + '_robot', component='none'))
        events.append(status(10.0, 'mission', robot + '_robot', completed='true', by=robot + '_robot',
                             recovery='none', diagnosis='none'))
    events += there_and_back('r4', 20, 0.0, -2.0)
    events += [msg(3.0, 'r4_robot', 'r1_robot', 'callForBids(contract(r4_robot,1),help(r4_robot,unknown))'),
               msg(4.0, 'r4_robot', 'r2_robot', 'award(contract(r4_robot,1),help(r4_robot,unknown))'),
               msg(4.1, 'r2_robot', 'r4_robot', 'accepted(contract(r4_robot,1))'),
               status(15.5, 'diagnosis', 'r4_robot', component='left_actuator'),
               status(31.0, 'mission', 'r4_robot', completed='true', by='r4_robot',
                      recovery='compensate', diagnosis='left_actuator')]
    return events


def test_a_run_whose_missions_all_ended_where_they_should_is_completed():
    out = fleet_judge.judge_run(ARGS, good_run())
    assert out['completed'] and out['wrong'] == 0 and out['undiagnosed'] == 0
    r4 = out['robots'][3]
    assert (r4['fault'], r4['diagnosis'], r4['diagnosis_outcome']) == ('left_actuator', 'left_actuator', 'correct')
    assert r4['time_to_diagnosis'] == 12.5 and r4['award_to_diagnosis'] == 11.5 and r4['helpers'] == ['r2']
    assert r4['mission']['recovery'] == 'compensate' and r4['mission']['goal_error'] == 0.0
    assert out['messages'] == 3 and out['faulty_completed'] == 1


def test_a_healthy_robot_that_reports_no_diagnosis_is_right_and_one_that_reports_a_fault_is_wrong():
    events = [e for e in good_run() if not (e[1] == 'diagnosis' and e[2]['agent'] == 'r1_robot')]
    assert fleet_judge.judge_run(ARGS, events)['wrong'] == 0
    events.append(status(9.0, 'diagnosis', 'r1_robot', component='odometry'))
    out = fleet_judge.judge_run(ARGS, events)
    assert out['wrong'] == 1 and 'r1 diagnosed odometry (fault none)' in out['reason']


def test_a_faulty_robot_without_a_diagnosis_is_undiagnosed_and_its_time_unknown():
    events = [e for e in good_run() if not (e[1] == 'diagnosis' and e[2]['agent'] == 'r4_robot')]
    out = fleet_judge.judge_run(ARGS, events)
    assert out['undiagnosed'] == 1 and out['robots'][3]['time_to_diagnosis'] is None


@pytest.mark.parametrize('reach, back, says', [(0.7, 0.0, 'goal missed by 0.300 m'),
                                               (1.0, 0.4, 'ended 0.400 m from its start')])
def test_a_mission_the_true_poses_contradict_is_not_completed(reach, back, says):
    events = [e for e in good_run() if not (e[1] == 'pose' and e[2]['robot'] == 'r4')]
    events += there_and_back('r4', 20, 0.0, -2.0, reach=reach, back=back)
    out = fleet_judge.judge_run(ARGS, events)
    assert not out['completed'] and 'r4: %s' % says in out['reason']


def test_a_delegated_mission_is_judged_on_the_delegate_s_true_poses():
    events = [e for e in good_run() if not (e[1] == 'mission' and e[2]['agent'] == 'r4_robot')]
    events = [e for e in events if not (e[1] == 'pose' and e[2]['robot'] == 'r4')]
    events += [pose(20, 'r4', 0.0, -2.0), pose(40, 'r2', 1.0, -2.05),
               status(41.0, 'mission', 'r4_robot', completed='true', by='r2_robot',
                      recovery='delegate', diagnosis='both_actuators')]
    r4 = fleet_judge.judge_run(ARGS, events)['robots'][3]
    assert r4['mission']['completed'] and r4['mission']['by'] == ['r2']
    assert r4['mission']['goal_error'] == 0.05 and r4['mission']['start_error'] is None


def test_no_mission_outcome_or_a_failed_run_is_not_completed():
    events = [e for e in good_run() if not (e[1] == 'mission' and e[2]['agent'] == 'r4_robot')]
    out = fleet_judge.judge_run(ARGS, events)
    assert not out['completed'] and 'r4: no mission outcome reported' in out['reason']
    out = fleet_judge.judge_run(ARGS, good_run(), failure='timed out after 600 s')
    assert not out['completed'] and out['reason'].startswith('timed out after 600 s')


def test_only_the_robot_that_accepted_an_award_of_help_is_a_helper():
    events = good_run() + [msg(5.0, 'r3_robot', 'r4_robot', 'accepted(contract(r4_robot,9))'),
                           msg(6.0, 'r4_robot', 'r1_robot', 'award(contract(r4_robot,2),guide(r4_robot,unknown))'),
                           msg(6.1, 'r1_robot', 'r4_robot', 'accepted(contract(r4_robot,2))')]
    assert fleet_judge.contractors(sorted(events, key=lambda e: e[0]), 'r4_robot') == ['r2_robot']
    assert fleet_judge.contractors(sorted(events, key=lambda e: e[0]), 'r4_robot', 'guide') == ['r1_robot']
    # recorded in one clock tick, the acceptance may come first
    answered_first = [msg(4.0, 'r2_robot', 'r4_robot', 'accepted(contract(r4_robot,1))'),
                      msg(4.0, 'r4_robot', 'r2_robot', 'award(contract(r4_robot,1),help(r4_robot,unknown))')]
    assert fleet_judge.contractors(answered_first, 'r4_robot') == ['r2_robot']


# --- the report ---

def results():
    out = []
    for spec in fleet_plan.make_fleet_plan((4,), 2, 1):
        events = good_run()
        if spec.arm == 'broadcast':  # the diagnosis 3 s later
            events = [(t + 3.0, k, f) if k == 'diagnosis' and f['agent'] == 'r4_robot' else (t, k, f)
                      for t, k, f in events]
        spec.args['faults'] = ARGS['faults']
        r = spec.to_dict()
        r.update(fleet_judge.judge_run(spec.args, events))
        r.update({'wall': 90.0, 'exit_code': 0, 'timed_out': False})
        out.append(r)
    return out


def test_summary_paired_times_and_goals():
    rs = results()
    rows = fleet_report.summary(rs)
    assert [(r['size'], r['arm']) for r in rows] == [(4, 'contract_net'), (4, 'broadcast'),
                                                    (None, 'contract_net'), (None, 'broadcast')]
    assert rows[0]['runs'] == 2 and rows[0]['completed'] == 2 and rows[0]['diagnosis_median'] == 12.5
    assert rows[1]['diagnosis_median'] == 15.5 and rows[1]['award_median'] == 14.5
    assert fleet_report.paired(rs) == [(1, 'r4', 12.5, 15.5), (2, 'r4', 12.5, 15.5)]
    goals = {text: met for text, met, _ in fleet_report.goals(rs)}
    assert goals['0 wrong diagnoses'] and not goals['at least 100 runs, N = 4 and 6']


def test_by_fault_and_the_robots_the_arms_chose_differently():
    rs = results()
    rows = fleet_report.by_fault(rs)
    assert [r['fault'] for r in rows] == ['left_actuator']
    assert rows[0]['contract_net'] == {'robots': 2, 'completed': 2, 'call_median': 12.5, 'award_median': 11.5}
    assert rows[0]['broadcast']['call_median'] == 15.5
    assert fleet_report.other_watcher(rs) == []
    rs[1]['robots'][3]['helpers'] = ['r3']          # run 1's broadcast arm chose r3 first
    assert fleet_report.other_watcher(rs) == [(1, 'r4')]
    assert 'a different first watcher for 1 of these 2' in fleet_report.markdown({}, rs, [])


def test_report_files(tmp_path):
    rs = results()
    fleet_runs.write_report(str(tmp_path), {'command': 'campaign --scenario fleet', 'runs': 2}, rs)
    md = (tmp_path / 'report.md').read_text()
    assert 'contract net diagnosed sooner in 2' in md and '| 4 | contract net | 2 | 2 (100 %' in md
    assert json.loads((tmp_path / 'results.json').read_text())['runs'][0]['robots'][3]['helpers'] == ['r2']
    assert len((tmp_path / 'runs.csv').read_text().splitlines()) == 1 + 4 * 4
    for name in ('fleet_diagnosis.png', 'fleet_paired.png'):
        assert os.path.getsize(str(tmp_path / name)) > 1000


def test_a_run_never_made_is_not_completed():
    spec = fleet_plan.make_fleet_plan((4,), 1, 1)[0]
    r = fleet_runs.analyze(spec, None, lambda *a, **k: [])
    assert not r['completed'] and r['reason'].startswith('the run was never made')
    assert 'NOT completed' in fleet_runs.progress_end(r)


# --- the end of a run ---

def mission_status(agent):
    return DiagnosticStatus(name='rason/mission', values=[KeyValue('agent', agent)])


def test_missions_done_waits_for_every_agent_s_mission_status():
    awaited = MissionsAwaited(['r1_robot', 'r2_robot'])
    other = DiagnosticStatus(name='rason/diagnosis', values=[KeyValue('agent', 'r1_robot')])
    assert awaited.note([other, mission_status('r9_robot')]) == [] and not awaited.all_done
    assert awaited.note([mission_status('r1_robot')]) == ['r1_robot'] and not awaited.all_done
    assert awaited.note([mission_status('r1_robot')]) == []
    assert awaited.note([mission_status('r2_robot')]) == ['r2_robot'] and awaited.all_done


def test_missions_done_needs_agents():
    with pytest.raises(ValueError):
        MissionsAwaited([])


def test_a_campaign_stopped_part_way_reports_the_runs_made_and_resume_keeps_them(tmp_path):
    rs = results()
    never = dict(rs[0], number=9, seed=1009, wall=None, exit_code=None, timed_out=None)
    (tmp_path / 'results.json').write_text(json.dumps({'runs': rs + [never]}))
    reported = cli.reported_runs(str(tmp_path))
    assert sorted(reported) == sorted(plan.RunSpec.from_dict(r).name for r in rs)  # not the unmade one
    fleet_runs.write_report(str(tmp_path), {'planned': 8}, rs)
    assert "Made so far: 4 of the plan's 8 runs" in (tmp_path / 'report.md').read_text()


def test_resume_reuses_a_reported_run_whose_bag_is_gone(tmp_path):
    rs = results()
    (tmp_path / 'results.json').write_text(json.dumps({'runs': rs}))
    specs = fleet_plan.make_fleet_plan((4,), 3, 1)    # runs 1 and 2 reported, 3 not
    made = []

    class Runner(object):
        def run(self, spec, bags, timeout, port):
            made.append(spec.name)
            return 'record'

        def stop_all(self):
            pass

    args = cli.parse_args(['--scenario', 'fleet', '--resume', '--out', str(tmp_path)])
    out = cli.run_all(args, specs, str(tmp_path / 'bags'), Runner(), lambda i, s: '',
                      lambda spec, record: {'made': spec.name}, lambda r: '')
    assert made == [s.name for s in specs[4:]]
    assert out[:4] == rs and out[4:] == [{'made': s.name} for s in specs[4:]]


def test_the_campaign_s_last_line_counts_the_runs_made(tmp_path, capsys):
    rs = results()
    unmade = dict(rs[0], number=3, wall=None, completed=False, reason='the run was never made')
    args = cli.parse_args(['--scenario', 'fleet', '--analyze-only', '--out', str(tmp_path)])
    status = fleet_runs.run_fleet(args, {}, [None] * 5, 'bags', None, None,
                                  lambda *a: rs + [unmade])
    assert status == 0
    assert 'campaign: 4 of 4 runs made (5 planned) completed, 0 wrong diagnoses' in capsys.readouterr().out
    assert "Made so far: 4 of the plan's 5 runs" in (tmp_path / 'report.md').read_text()
