"""The budget part's goals and its section of report.md."""
from rason_bench import budget_report, report


def _robot(mean, p95, mas_rss, total_rss, quota):
    procs = [{'name': 'rason_mas', 'pid': 1, 'cpu_s': 3.0, 'cpu_mean_cores': 0.1, 'rss_peak_mb': mas_rss,
              'rss_last_mb': mas_rss},
             {'name': 'motion_decomp', 'pid': 2, 'cpu_s': 1.5, 'cpu_mean_cores': 0.05, 'rss_peak_mb': 50.0,
              'rss_last_mb': 50.0}]
    return {'quota_cores': quota, 'seconds': 30.0, 'cpu_s': mean * 30, 'cpu_mean_cores': mean, 'cpu_p95_cores': p95,
            'cpu_max_cores': p95 + 0.2, 'start_up_s': 15.0, 'cpu_p95_running_cores': p95,
            'cores_series': [[0.5, 0.9], [1.0, p95]], 'throttling': {'periods': 300, 'throttled_periods': 80, 'throttled_s': 9.0},
            'rss_total_peak_mb': total_rss, 'rss_sum_of_peaks_mb': total_rss + 5, 'processes': procs}


def _run(fault, quota, outcome='correct', mean=0.3, p95=0.45, mas_rss=150.0):
    return {'fault': fault, 'quota_cores': quota, 'outcome': outcome,
            'component': fault if outcome == 'correct' else 'none', 'reason': '', 'wall_s': 31.0,
            'steps_s': {'total': 14.5},
            'interval_s': 0.5,
            'robots': {'faulty': _robot(mean, p95, mas_rss, 280.0, quota), 'helper': _robot(mean, p95, mas_rss, 420.0, quota)},
            'outside': {'cpu_s': 8.0, 'processes': [{'name': 'rason_sim', 'pid': 9, 'cpu_s': 4.5, 'cpu_mean_cores': 0.15,
                                                     'rss_peak_mb': 100.0, 'rss_last_mb': 100.0}]}}


def _budget(**kw):
    held = kw.pop('held_outcome', 'correct')
    return {'quota_cores': 0.5, 'runs': [_run('both_actuators', None, **kw), _run('both_actuators', 0.5, held)]}


def test_goals_met_when_each_robot_fits_half_a_core_and_the_diagnosis_is_right():
    goals = budget_report.goals(_budget())
    assert len(goals) == 5 and all(met for _, _, met in goals)
    assert goals[0][1] == 'both_actuators: faulty 0.30, helper 0.30'


def test_each_goal_fails_on_its_own_measure():
    assert [met for _, _, met in budget_report.goals(_budget(p95=0.6))] == [True, False, True, True, True]
    assert [met for _, _, met in budget_report.goals(_budget(mas_rss=250.0))] == [True, True, False, True, True]
    assert [met for _, _, met in budget_report.goals(_budget(held_outcome='wrong'))] == [True, True, True, True, False]


def test_no_budget_part_no_goals_and_no_section():
    assert budget_report.goals({}) == []
    results = {'machine': {'date': 'd', 'cpus': 2, 'cpu_model': 'c', 'load_at_start': [0.1, 0.1, 0.1]}, 'params': {}}
    assert 'What a robot needs' not in report.markdown(results)


def test_the_section_lists_each_run_per_robot_and_each_process():
    results = {'machine': {'date': 'd', 'cpus': 2, 'cpu_model': 'c', 'load_at_start': [0.1, 0.1, 0.1]}, 'params': {},
               'budget': _budget()}
    text = report.markdown(results)
    assert '## What a robot needs: the case study per robot' in text
    assert ('| both_actuators | 0.5 core | correct (both_actuators) | 14.5 | 31 | helper | 0.30 | 0.45 | 0.45 | 0.65 | 9.0 '
            '| 80 of 300 (9.0 s) | 420 MB |') in text
    assert '| faulty | rason_mas | 3.00 | 0.100 | 150 | 3.00 |' in text
    assert '| outside | rason_sim | 4.50 | 0.150 | 100 | 4.50 |' in text
    assert 'robot budget: the case study diagnoses right with each robot held to 0.5 core' in text


def test_the_plot_is_written(tmp_path):
    from rason_bench import plots
    plots.budget_plot(_budget(), str(tmp_path / 'budget.png'))
    assert (tmp_path / 'budget.png').stat().st_size > 1000
