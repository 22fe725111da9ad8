"""The fault-tolerance campaign's statistics, acceptance goals, report, CSV/JSON, figures
and command line (no ROS)."""
import csv
import io
import json
import os

import pytest

from rason_campaign import cli, mission_figures, mission_report, plan, stats
from rason_campaign.runner import RunRecord

META = {'command': 'rosrun rason campaign --scenario fault_tolerance --runs 2',
        'date': '2026-01-01', 'runs': 2, 'seed': 1, 'rate': 1.0, 'fault_at': 0.0,
        'interaction': 'none', 'scenario': 'fault_tolerance'}


def result(number, fault, arm, completed, time=None, goal_error=None, diagnosis=None,
           outcome='correct', by=('faulty',), recovery='none', claimed=None, reason=''):
    claimed = completed if claimed is None else claimed
    return {'number': number, 'fault': fault, 'seed': 1000 + number, 'arm': arm,
            'args': {}, 'claimed': claimed, 'completed': completed,
            'by': list(by) if claimed else [], 'recovery': recovery,
            'diagnosis': diagnosis or fault, 'diagnosis_outcome': outcome, 'start': 5.0,
            'end': None if time is None else 5.0 + time, 'time': time, 'goal': (0.0, 1.0),
            'goal_error': goal_error, 'start_error': 0.05 if completed and 'faulty' in by else None,
            'reason': reason or ('completed' if completed else 'stopped'), 'wall': 60.0,
            'exit_code': 0, 'timed_out': False}


def results():
    return [
        result(1, 'none', 'recovery', True, 20.0, 0.04),
        result(1, 'none', 'baseline', True, 19.0, 0.05),
        result(2, 'none', 'recovery', True, 22.0, 0.06),
        result(2, 'none', 'baseline', True, 21.0, 0.03),
        result(3, 'left_actuator', 'recovery', True, 50.0, 0.08, recovery='compensate'),
        result(3, 'left_actuator', 'baseline', False),
        result(4, 'left_actuator', 'recovery', False, goal_error=0.21, claimed=True,
               recovery='compensate', reason='goal missed by 0.210 m (> 0.15 m)'),
        result(4, 'left_actuator', 'baseline', False, diagnosis='none', outcome='wrong'),
    ]


@pytest.mark.parametrize('k,n,low,high', [
    (10, 10, 0.7225, 1.0), (0, 10, 0.0, 0.2775), (5, 10, 0.2366, 0.7634), (1, 1, 0.2065, 1.0)])
def test_wilson_interval(k, n, low, high):
    lo, hi = stats.wilson(k, n)
    assert (lo, hi) == (pytest.approx(low, abs=1e-4), pytest.approx(high, abs=1e-4))


def test_wilson_without_runs():
    assert stats.wilson(0, 0) == (None, None)


@pytest.mark.parametrize('values,q,expected', [
    ([], 50, None), ([None], 90, None), ([3.0], 90, 3.0), ([1.0, 2.0, 3.0, 4.0], 50, 2.5),
    ([4.0, 1.0, None, 3.0, 2.0], 90, 3.7), (list(range(11)), 90, 9.0)])
def test_percentile(values, q, expected):
    assert stats.percentile(values, q) == (None if expected is None else pytest.approx(expected))


def test_summary_per_fault_and_arm():
    rows = {(r['fault'], r['arm']): r for r in mission_report.summary(results())}
    assert list(rows) == [('none', 'recovery'), ('none', 'baseline'),
                          ('left_actuator', 'recovery'), ('left_actuator', 'baseline')]
    left = rows[('left_actuator', 'recovery')]
    assert (left['runs'], left['completed'], left['claimed'], left['rate']) == (2, 1, 2, 0.5)
    assert (left['ci_low'], left['ci_high']) == stats.wilson(1, 2)
    assert left['time_median'] == left['time_p90'] == 50.0
    # against the same arm's fault-free median (21 s)
    assert left['time_vs_none'] == pytest.approx(29.0)
    assert left['time_ratio_none'] == pytest.approx(50.0 / 21.0)
    # goal errors of the runs the agents said they completed, the failed check included
    assert left['goal_error_median'] == pytest.approx(0.145)
    assert left['goal_error_max'] == pytest.approx(0.21)
    base = rows[('left_actuator', 'baseline')]
    assert (base['completed'], base['wrong'], base['time_median'], base['time_vs_none'],
            base['goal_error_max']) == (0, 1, None, None, None)
    assert rows[('none', 'baseline')]['time_median'] == pytest.approx(20.0)


def test_goals_not_met_by_a_partial_campaign_with_failures():
    goals = mission_report.goals(results())
    assert [g['met'] for g in goals] == [False, False, False, False]   # faults missing
    assert goals[0]['detail'] == ('none 2/2, left_actuator 1/2; not run: right_actuator, '
                                  'both_actuators, odometry')
    assert goals[1]['detail'].startswith('left_actuator 0/2; not run: ')
    assert goals[2]['detail'] == '1 wrong of 8 runs; run 4 baseline: none'
    assert 'none recovery: 2' in goals[3]['detail']


def test_goals_of_a_campaign_without_faults_name_what_was_not_run():
    goals = mission_report.goals([result(1, 'none', 'recovery', True, 20.0, 0.04),
                                  result(1, 'none', 'baseline', True, 19.0, 0.05)])
    assert goals[0]['detail'] == ('none 1/1; not run: left_actuator, right_actuator, '
                                  'both_actuators, odometry')
    assert goals[1]['detail'] == ('not run: left_actuator, right_actuator, both_actuators, '
                                  'odometry')
    assert not goals[1]['met']


def full_campaign(runs=10, recovery_done=None, baseline_done=0):
    """runs per fault and arm; recovery_done / baseline_done of them completed."""
    out = []
    recovery_done = runs if recovery_done is None else recovery_done
    for i, fault in enumerate(plan.FAULTS):
        for k in range(runs):
            number = i * runs + k + 1
            out.append(result(number, fault, 'recovery', k < recovery_done, 30.0, 0.05))
            done = fault == 'none' or k < baseline_done
            out.append(result(number, fault, 'baseline', done, 20.0 if done else None,
                              0.05 if done else None))
    return out


def test_goals_met_by_a_complete_successful_campaign():
    goals = mission_report.goals(full_campaign())
    assert all(g['met'] for g in goals), goals
    assert goals[3]['detail'] == 'all'


def test_goals_fail_on_nine_of_ten_with_recovery_or_a_completing_baseline():
    assert [g['met'] for g in mission_report.goals(full_campaign(recovery_done=9))] == [
        False, True, True, True]
    assert [g['met'] for g in mission_report.goals(full_campaign(baseline_done=1))] == [
        True, False, True, True]
    assert [g['met'] for g in mission_report.goals(full_campaign(runs=9))] == [
        True, True, True, False]


def test_markdown_report():
    text = mission_report.markdown(META, results(), {'completion': 'completion.png'})
    lines = text.splitlines()
    assert lines[0] == '# Fault-tolerance campaign'
    assert '| Fault | Arm | Runs | Completed | Rate (95 % CI) | Wrong diagnoses | Median time ' \
           '(s) | p90 time (s) | vs none (s) | Median goal error (m) | Max goal error (m) |' \
        in lines
    assert '| left_actuator | recovery | 2 | 1 | 50 % (9 %–91 %) | 0 | 50.0 | 50.0 | ' \
           '+29.0 (×2.38) | 0.145 | 0.210 |' in lines
    assert '| left_actuator | baseline | 2 | 0 | 0 % (0 %–66 %) | 1 | — | — | — | — | — |' \
        in lines
    assert '| none | recovery | 2 | 2 | 100 % (34 %–100 %) | 0 | 21.0 | 21.8 | +0.0 (×1.00) | ' \
           '0.050 | 0.060 |' in lines
    assert '| 0 wrong diagnoses (false positives included) | **no** | 1 wrong of 8 runs; ' \
           'run 4 baseline: none |' in lines
    assert 'All goals met: no.' in lines
    assert '| 4 | 1004 | left_actuator | recovery | left_actuator | compensate | faulty | no ' \
           '| — | 0.210 | — | goal missed by 0.210 m (> 0.15 m) |' in lines
    assert '| 4 | 1004 | left_actuator | baseline | none (wrong) | none | — | no | — | — ' \
           '| — | stopped |' in lines
    assert 'fault injected at the start' in text
    assert '![Completion rate per fault](completion.png)' in lines
    assert 'Time to completion per fault' not in text     # no times figure given
    # both arms' diagnoses: the baseline's 'none' under a left-actuator fault is wrong
    assert '| left_actuator | 1 | 3 |  | 75 % (30 %–95 %) |' in lines


def test_markdown_states_a_mid_mission_fault_and_met_goals():
    meta = dict(META, fault_at=3.0)
    text = mission_report.markdown(meta, full_campaign(), {})
    assert '3.0 s after Faulty first moves (mid-mission)' in text
    assert 'All goals met: yes.' in text.splitlines()


def test_json_and_csv():
    data = json.loads(mission_report.results_json(META, results()))
    assert data['meta']['scenario'] == 'fault_tolerance'
    assert [g['met'] for g in data['goals']] == [False, False, False, False]
    assert data['summary'][2]['completed'] == 1 and len(data['runs']) == 8
    summary = list(csv.DictReader(io.StringIO(mission_report.summary_csv(results()))))
    assert list(summary[0]) == list(mission_report.SUMMARY_COLUMNS)
    assert (summary[2]['fault'], summary[2]['arm'], summary[2]['completed'],
            summary[2]['time_median']) == ('left_actuator', 'recovery', '1', '50.0')
    assert summary[3]['time_median'] == ''           # not measured: an empty cell
    runs = list(csv.DictReader(io.StringIO(mission_report.runs_csv(results()))))
    assert len(runs) == 8 and runs[4]['by'] == 'faulty' and runs[5]['by'] == ''
    assert runs[6]['reason'] == 'goal missed by 0.210 m (> 0.15 m)'


def test_figures_are_written(tmp_path):
    names = mission_figures.make_all(results(), str(tmp_path))
    assert set(names) == {'completion', 'times'}
    for name in names.values():
        with open(str(tmp_path / name), 'rb') as f:
            assert f.read(8) == b'\x89PNG\r\n\x1a\n'
        assert os.path.getsize(str(tmp_path / name)) < 200000


SPECS = plan.make_mission_plan(('none',), 1, 1)


def test_analyze_mission_reads_the_bag_with_true_poses():
    asked = []

    def read_events(path, poses=False):
        asked.append((path, poses))
        return [(0.0, 'pose', {'robot': 'faulty', 'x': 0.0, 'y': 0.0, 'yaw': 0.0}),
                (1.0, 'action', {'robot': 'faulty', 'agent': 'faulty', 'action': 'move'}),
                (5.0, 'pose', {'robot': 'faulty', 'x': 1.02, 'y': 0.0, 'yaw': 0.0}),
                (9.0, 'pose', {'robot': 'faulty', 'x': 0.01, 'y': 0.0, 'yaw': 0.0}),
                (9.5, 'diagnosis', {'component': 'none', 'evidence': 'destination reached'}),
                (10.0, 'mission', {'completed': 'true', 'by': 'faulty', 'recovery': 'none',
                                   'diagnosis': 'none'})]
    r = cli.analyze_mission(SPECS[0], RunRecord(0, 25.2, False, 'b.bag', 'l'), read_events)
    assert asked == [('b.bag', True)]
    assert r['completed'] and r['arm'] == 'recovery' and r['time'] == 9.0
    assert r['goal_error'] == pytest.approx(0.02) and r['wall'] == 25.2
    assert cli.mission_progress_start(1, SPECS[0], 2) == '[1/2] none seed=1001 recovery ... '
    assert cli.mission_progress_end(r) == \
        'completed by faulty (none) in 9.0 s, goal error 0.020 m (wall 25 s)'


def test_analyze_mission_without_a_bag_or_a_run():
    def no_bag(path, poses=False):
        raise IOError('no bag %s' % path)
    r = cli.analyze_mission(SPECS[1], RunRecord(1, 3.0, False, '/x.bag', 'l'), no_bag)
    assert not r['completed']
    assert r['reason'] == 'roslaunch exited with code 1; no bag /x.bag; no diagnosis recorded'
    assert cli.mission_progress_end(r).startswith('not completed: roslaunch exited')
    r = cli.analyze_mission(SPECS[1], None, no_bag)
    assert r['reason'] == 'the run was never made; no diagnosis recorded'


def test_command_line_scenario_options():
    args = cli.parse_args(['--out', 'o'])
    assert (args.scenario, args.timeout, args.fault_at) == ('diagnosis', 240.0, 0.0)
    args = cli.parse_args(['--out', 'o', '--scenario', 'fault_tolerance', '--fault-at', '2'])
    assert (args.scenario, args.timeout, args.fault_at) == ('fault_tolerance', 420.0, 2.0)
    assert cli.parse_args(['--out', 'o', '--scenario', 'fault_tolerance',
                           '--timeout', '100']).timeout == 100.0


@pytest.mark.parametrize('argv', [['--fault-at', '2'],
                                  ['--scenario', 'fault_tolerance', '--no-jitter'],
                                  ['--scenario', 'rescue']])
def test_command_line_refuses_options_of_the_other_scenario(argv, capsys):
    with pytest.raises(SystemExit) as e:
        cli.parse_args(['--out', 'o'] + argv)
    assert e.value.code == 2
    assert 'error' in capsys.readouterr().err
