"""Goals, tables and the thesis's values in report.md."""
from rason_bench import report, thesis


def _cell(p, r, ms, base):
    return {'perceptions': p, 'rate_hz': r, 'ms': ms, 'baseline_ms': base, 'cpu_percent': 50.0,
            'baseline_cpu_percent': 50.0}


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
