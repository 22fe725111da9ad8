"""Statistics, the Markdown report, the JSON results, the figures, and a run's analysis
when the run or its bag went wrong."""
import json
import os

import pytest

from rason_campaign import cli, figures, plan, report, stats, thesis
from rason_campaign.runner import RunRecord

META = {'command': 'rosrun rason campaign --runs 2', 'date': '2026-01-01', 'runs': 2,
        'seed': 1, 'rate': 1.0, 'interaction': 'none'}


def result(number, fault, outcome, steps, component=None, reason=''):
    names = ('fault_detection', 'robot_location', 'diagnosis', 'total')
    return {'number': number, 'fault': fault, 'seed': 1000 + number, 'outcome': outcome,
            'reason': reason, 'component': component, 'steps': dict(zip(names, steps))}


def results():
    return [
        result(1, 'both_actuators', 'correct', (4.3, 14.7, 4.4, 23.4), 'both_actuators'),
        result(2, 'both_actuators', 'correct', (4.0, 14.2, 4.7, 22.9), 'both_actuators'),
        result(3, 'odometry', 'undiagnosed', (7.3, None, None, None), 'undiagnosed',
               'the helper could not find me'),
        result(4, 'odometry', 'wrong', (7.0, 7.0, 6.0, 20.0), 'both_actuators', 'x'),
        result(5, 'none', 'correct', (None, None, None, 11.0), 'none'),
    ]


def test_mean_sd_is_the_thesis_sample_sd():
    totals = [r[3] for r in thesis.TABLES['both_actuators'][1]]
    mean, sd = stats.mean_sd(totals)
    assert mean == pytest.approx(22.44)
    assert round(sd, 2) == thesis.STATED_TOTAL['both_actuators'][1]  # 0.78


@pytest.mark.parametrize('values,expected', [
    ([], (None, None)), ([None, None], (None, None)), ([2.0], (2.0, None)),
    ([1.0, None, 3.0], (2.0, pytest.approx(1.41421356)))])
def test_mean_sd_edges(values, expected):
    assert stats.mean_sd(values) == expected


def test_summary_counts_and_correct_only_means():
    s = stats.summary(results())
    assert s['counts'] == {'correct': 3, 'undiagnosed': 1, 'wrong': 1}
    assert s['correct_fraction'] == pytest.approx(0.6)
    assert list(s['faults']) == ['both_actuators', 'odometry', 'none']
    assert s['faults']['both_actuators']['steps']['total'][0] == pytest.approx(23.15)
    assert s['faults']['odometry']['steps']['total'] == (None, None)  # no correct run
    assert s['faults']['none']['steps']['fault_detection'] == (None, None)


def test_thesis_step_means():
    assert thesis.step_means('right_actuator') == pytest.approx((17.25, 10.625, 12.85, 40.725))
    # Table 7.2 run 5 has no diagnosis: averaged over the other six.
    assert thesis.step_means('odometry')[3] == pytest.approx(153.3 / 6)
    assert thesis.step_means('none') is None


def test_markdown_tables():
    text = report.markdown(META, results(), {'steps_none': 'steps_none.png', 'totals': 't.png'})
    lines = text.splitlines()
    assert '| both_actuators | 2 | 2 | 0 | 0 | 4.15 ± 0.21 | 14.45 ± 0.35 | 4.55 ± 0.21 | ' \
           '23.15 ± 0.35 | 22.42 ± 0.78 (Table 7.1) |' in lines
    assert '| **all** | 5 | 3 | 1 | 1 |  |  |  |  |  |' in lines
    assert 'Correct: 3 of 5 (60 %); undiagnosed: 1; wrong: 1.' in lines
    assert '## both_actuators (thesis Table 7.1)' in lines
    assert '| Run 1 | 1001 | 4.30 | 14.70 | 4.40 | 23.40 | both_actuators | correct |' in lines
    assert '| Thesis mean | Table 7.1 | 4.28 | 13.64 | 4.52 | 22.44 |  |  |' in lines
    assert '| Run 5 | 1005 | — | — | — | 11.00 | none | correct |' in lines
    assert '- Run 3: undiagnosed — the helper could not find me' in lines
    assert '![none latency by step](steps_none.png)' in lines
    assert '![Total latency per run](t.png)' in lines
    assert '## none' in lines and 'Outcomes' not in text  # no outcomes figure given


def test_results_json_round_trips():
    data = json.loads(report.results_json(META, results()))
    assert data['summary']['counts']['wrong'] == 1
    assert data['runs'][2]['reason'] == 'the helper could not find me'
    assert data['thesis']['left_actuator']['stated_total'] == [30.25, 1.52]


def test_figures_are_written(tmp_path):
    names = figures.make_all(results(), str(tmp_path))
    assert set(names) == {'steps_both_actuators', 'steps_odometry', 'steps_none', 'totals',
                          'outcomes'}
    for name in names.values():
        path = tmp_path / name
        with open(str(path), 'rb') as f:
            assert f.read(8) == b'\x89PNG\r\n\x1a\n'
        assert os.path.getsize(str(path)) < 200000


SPEC = plan.make_plan(('left_actuator',), 1, 1)[0]


def test_timed_out_run_is_undiagnosed_with_the_reason():
    record = RunRecord(None, 240.3, True, '/nowhere.bag', '/nowhere.log')
    r = cli.analyze(SPEC, record, lambda path: [])
    assert (r['outcome'], r['reason']) == ('undiagnosed', 'timed out after 240 s')
    assert r['timed_out'] is True and r['steps']['total'] is None


def test_missing_bag_is_undiagnosed_with_the_reason():
    def no_bag(path):
        raise IOError('no bag %s' % path)
    record = RunRecord(1, 3.0, False, '/nowhere.bag', '/nowhere.log')
    r = cli.analyze(SPEC, record, no_bag)
    assert r['outcome'] == 'undiagnosed'
    assert r['reason'] == 'roslaunch exited with code 1; no bag /nowhere.bag'


def test_run_never_made():
    r = cli.analyze(SPEC, None, lambda path: [])
    assert (r['outcome'], r['reason']) == ('undiagnosed', 'the run was never made')


def test_progress_line():
    r = cli.analyze(SPEC, RunRecord(0, 25.2, False, 'b', 'l'), lambda path: [
        (1.0, 'action', {'robot': 'faulty', 'action': 'move'}),
        (22.3, 'diagnosis', {'component': 'left_actuator', 'evidence': 'seen'})])
    assert cli.progress_start(SPEC, 25) == '[1/25] left_actuator seed=1001 ... '
    assert cli.progress_end(r) == 'correct in 21.3 s (wall 25 s)'


def test_confusion_matrix_rows_columns_and_wilson_intervals():
    matrix, columns = stats.confusion(results())
    assert columns == ['both_actuators', 'odometry', 'none', 'undiagnosed']
    assert matrix == {'both_actuators': {'both_actuators': 2},
                      'odometry': {'undiagnosed': 1, 'both_actuators': 1},
                      'none': {'none': 1}}
    lines = report.confusion_table(results())
    assert lines[0] == '| Injected ↓ diagnosed → | both_actuators | odometry | none | undiagnosed | ' \
                       'Correct (95 % CI) |'
    assert '| both_actuators | 2 |  |  |  | 100 % (34 %–100 %) |' in lines
    assert '| odometry | 1 |  |  | 1 | 0 % (0 %–66 %) |' in lines
    assert lines[-1] == '| **all** |  |  |  |  | 60 % (23 %–88 %) |'


def test_no_diagnosis_at_all_is_an_undiagnosed_column():
    runs = [result(1, 'left_actuator', 'undiagnosed', (None,) * 4, None),
            result(2, 'left_actuator', 'wrong', (None,) * 4, 'right_actuator')]
    matrix, columns = stats.confusion(runs)
    assert columns == ['left_actuator', 'right_actuator', 'undiagnosed']
    assert matrix == {'left_actuator': {'undiagnosed': 1, 'right_actuator': 1}}


def test_markdown_says_when_faulty_carries_the_third_cylinder():
    assert 'third (blue) cylinder' not in report.markdown(META, results(), {})
    text = report.markdown(dict(META, third_marker=True), results(), {})
    assert 'interaction fault: none; Faulty carries the third (blue) cylinder' in text


def test_markdown_states_the_wall_time_when_the_campaign_measured_it():
    assert 'Wall time' not in report.markdown(META, results(), {})  # e.g. an older plan.json
    text = report.markdown(dict(META, wall=1919, jobs=3), results(), {})
    assert 'Wall time: 1919 s (32.0 min) for the runs, 3 at a time (`--jobs 3`).' in text
    text = report.markdown(dict(META, wall=600, jobs=1), results(), {})
    assert 'Wall time: 600 s (10.0 min) for the runs, one at a time.' in text


def test_markdown_has_the_confusion_matrix():
    lines = report.markdown(META, results(), {}).splitlines()
    assert '## Confusion matrix' in lines
    assert '| none |  |  | 1 |  | 100 % (21 %–100 %) |' in lines
