"""Goals, tables and the thesis's values in report.md."""
from rason_bench import report, thesis


def _cell(p, r, ms, base):
    return {'perceptions': p, 'rate_hz': r, 'ms': ms, 'baseline_ms': base, 'cpu_percent': 50.0,
            'baseline_cpu_percent': 50.0}


def _summary(p50, p99):
    return {'n': 50, 'p50': p50, 'p90': p99, 'p99': p99, 'max': p99}


def _preemption(stop_p99):
    return {'stop_ms': _summary(7.5, stop_p99), 'cancel_ms': _summary(1.3, 5.0),
            'cancel_to_stop_ms': _summary(4.0, stop_p99 - 5.0), 'take_backs': 50, 'warmup': 5,
            'ended_early': 0, 'control_rate_hz': 50.0, 'base_rate_hz': 50.0, 'max_delay_s': 0.1,
            'seconds': 6.0}


def _results(ratio_10x50=1.1, rtt=(1.0, 5.0), seen=2.0):
    per_source = {'iterations': 1000, 'cells': [_cell(1, 1, 0.020, 0.020), _cell(10, 50, 0.020 * ratio_10x50, 0.020)]}
    return {'machine': {'date': 'd', 'cpus': 2, 'cpu_model': 'cpu', 'load_at_start': [0.1, 0.2, 0.3]},
            'params': {'seconds': 5},
            'cycle': {'per_source': per_source, 'accumulate': per_source},
            'latency': {'idle': {'action_round_trip_ms': {'n': 10, 'p50': rtt[0], 'p90': rtt[1], 'p99': rtt[1], 'max': rtt[1]},
                                 'perception_to_belief_ms': {'n': 10, 'p50': seen, 'p90': seen, 'p99': seen, 'max': seen}}}}


def test_thesis_values_are_looked_up_by_mode_and_cell():
    assert thesis.thesis_ms('accumulate', 10, 50) == 6.23
    assert thesis.thesis_ms('per_source', 10, 50) == 2.58
    assert thesis.thesis_ms('per_source', 1, 1) == 0.49
    assert thesis.thesis_ms('per_source', 2, 50) is None
    assert thesis.THESIS_SLOWDOWN == 5.3


def test_goals_met():
    verdicts = report.goals(_results())
    assert [met for _, _, met in verdicts] == [True, True, True, True]


def test_goals_missed_are_reported_with_the_measurement():
    verdicts = report.goals(_results(ratio_10x50=1.5, rtt=(2.5, 12.0), seen=6.0))
    assert [met for _, _, met in verdicts] == [False, False, False, False]
    assert verdicts[0][1].startswith('1.50 x')


def test_goals_of_missing_parts_are_left_out():
    results = _results()
    del results['latency']
    assert len(report.goals(results)) == 1


def test_cycle_table_shows_ratio_and_thesis_value():
    table = report.cycle_table('per_source', _results(ratio_10x50=1.5)['cycle']['per_source'])
    rows = table.splitlines()
    assert rows[0] == '| perceptions | 1 Hz | 50 Hz |'
    assert rows[2] == '| 1 | 0.0200 (1.00×; 0.49) |  |'
    assert rows[3] == '| 10 |  | 0.0300 (1.50×; 2.58) |'
    assert 'median 0.0200 ms' in table


def test_markdown_has_every_section():
    text = report.markdown(_results())
    for heading in ('## Goals', 'thesis Table 5.1', 'thesis Table 5.2', '## Latencies'):
        assert heading in text
    assert '**not met**' not in text


def test_cpu_slowdown_counts_the_share_of_the_cores_the_node_got():
    c = {'ms': 0.03, 'cpu_percent': 50.0, 'baseline_ms': 0.02, 'baseline_cpu_percent': 100.0}
    assert report.slowdown(c) == 1.5
    assert report.cpu_slowdown(c) == 0.75   # slower only because it got half a core


def test_preemption_goal_is_p99_within_one_control_period_plus_transport():
    results = _results()
    results['preemption'] = _preemption(stop_p99=15.4)
    goal, measured, met = report.goals(results)[-1]
    assert goal.startswith('preemption: take-back -> zero twist p99 <= 60 ms')
    assert (measured, met) == ('15.40 ms (50 take-backs)', True)
    results['preemption'] = _preemption(stop_p99=60.5)
    assert report.goals(results)[-1][1:] == ('60.50 ms (50 take-backs)', False)


def test_preemption_goal_without_samples_is_not_met():
    results = _results()
    results['preemption'] = dict(_preemption(10.0), stop_ms={'n': 0})
    assert report.goals(results)[-1][1:] == ('no take-back measured', False)


def test_preemption_goal_left_out_without_the_part():
    assert not any(g.startswith('preemption') for g, _, _ in report.goals(_results()))


def test_preemption_table_shows_where_the_time_goes():
    rows = report.preemption_table(_preemption(stop_p99=15.4)).splitlines()
    assert rows[0] == '|  | n | p50 ms | p90 ms | p99 ms | max ms |'
    assert rows[2] == '| take-back → zero twist on `cmd_vel` | 50 | 7.50 | 15.40 | 15.40 | 15.40 |'
    assert rows[3].startswith('| take-back → `.cancel` heard on `jason/action` | 50 | 1.30 |')
    assert rows[4].startswith('| `.cancel` heard → zero twist | 50 | 4.00 |')


def test_markdown_preemption_section_states_the_control_rate_and_the_verdict():
    results = _results()
    results['preemption'] = _preemption(stop_p99=70.0)
    text = report.markdown(results)
    assert '## Preemption latency' in text
    assert '`~rate` 50 Hz' in text
    assert '| 70.00 ms (50 take-backs) | **not met** |' in text
