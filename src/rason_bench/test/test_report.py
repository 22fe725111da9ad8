"""Goals, tables and the thesis's values in report.md."""
import os
import re

import pytest

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


def _cpu(us, quiet=500.0, silent=None):
    def row(u):
        return {'literals_per_message': 10, 'rate_hz': 50, 'window_s': 3, 'idle_cpu_percent': 2.0,
                'cpu_percent': 30.0, 'us_per_message': u,
                'runs': [{'cpu_s': 1.0, 'wall_s': 3.0, 'messages': 150, 'us_per_message': u}]}
    out = {'listing_5_4': row(us), 'no_plans': row(quiet)}
    if silent is not None:
        out['no_print'] = row(silent)
    return out


def _reaction(p50, p99, seen=50, sent=50):
    def row(a, b, n):
        return {'reaction_ms': {'n': n, 'p50': a, 'p90': b, 'p99': b, 'max': b}, 'triggers_sent': sent,
                'reaction_samples': [a] * n}
    load = row(p50, p99, seen)
    load.update(busy_intentions=50, busy_turns_per_s=9000.0, busy_intentions_reported=50, cpu_percent=150.0)
    return {'idle': row(1.0, 3.0, sent), 'load': load}


def _behaviour(wakeup_max=4.0, limited=4.8, plain=48.0, rtf=0.99, vision=9.8):
    return {'wakeup': {'gap_s': 2.0, 'stamps_sent': 3, 'wakeup_samples': [3.0, 3.5, wakeup_max],
                       'wakeup_ms': {'n': 3, 'p50': 3.5, 'p90': wakeup_max, 'p99': wakeup_max, 'max': wakeup_max}},
            'rate_limit': {'sent': 150, 'sent_hz': 50.0, 'seconds': 3.0,
                           'agents': {'limited': {'n': 15, 'per_s': limited, 'min_interval_ms': 200.0},
                                      'plain': {'n': 148, 'per_s': plain, 'min_interval_ms': 15.0}}},
            'sim': {'window_s': 10.0, 'settle_s': 2.0, 'real_time_factor': rtf,
                    'rates_hz': {'faulty odom': 49.9, 'helper odom': 49.9, 'camera': 10.0, 'vision': vision}}}


def _goal(results, start):
    found = [(measured, met) for goal, measured, met in report.goals(results) if goal.startswith(start)]
    assert len(found) == 1, found
    return found[0]


def test_new_measurements_each_have_a_goal():
    results = _results()
    results.update(cpu=_cpu(800.0), reaction=_reaction(5.0, 40.0), behaviour=_behaviour())
    verdicts = report.goals(results)
    assert len(verdicts) == 4 + 1 + 2 + 1 + 1 + 5
    assert all(met for _, _, met in verdicts)
    assert _goal(results, 'node CPU per perception message') == ('800 µs (without perception plans: 500 µs)', True)


def test_a_printed_line_costs_the_listing_agent_s_cpu_less_the_same_plans_without_print_per_literal():
    results = dict(_results(), cpu=_cpu(1800.0, quiet=900.0, silent=1000.0))
    measured, met = _goal(results, 'node CPU per line an agent prints')
    assert measured.startswith('80 µs') and met                   # (1800 - 1000) / 10
    results['cpu'] = _cpu(2300.0, quiet=900.0, silent=1000.0)
    assert _goal(results, 'node CPU per line an agent prints') == (
        "130 µs (Listing 5.4's agent 2300 µs a message, the same plans without .print 1000 µs, 10 lines a message)", False)
    assert 'the same plans without `.print`' in report.cpu_table(results['cpu'])


def test_cpu_goal_is_on_the_listing_agent():
    results = dict(_results(), cpu=_cpu(2500.0, quiet=100.0))
    assert _goal(results, 'node CPU')[1] is False
    results['cpu']['listing_5_4']['us_per_message'] = None
    assert _goal(results, 'node CPU') == ('no messages heard', False)


def test_reaction_goals_need_every_trigger_answered():
    base = _results()
    assert _goal(dict(base, reaction=_reaction(25.0, 40.0)), 'perception -> action p50')[1] is False
    assert _goal(dict(base, reaction=_reaction(5.0, 120.0)), 'perception -> action p99')[1] is False
    measured, met = _goal(dict(base, reaction=_reaction(5.0, 40.0, seen=49)), 'perception -> action p99')
    assert not met and '49 of 50' in measured


def test_wakeup_goal_is_on_the_slowest_and_on_every_stamp():
    base = _results()
    assert _goal(dict(base, behaviour=_behaviour(wakeup_max=499.0)), 'idle agent wakes up')[1] is True
    assert _goal(dict(base, behaviour=_behaviour(wakeup_max=500.0)), 'idle agent wakes up')[1] is False
    b = _behaviour()
    b['wakeup']['wakeup_ms']['n'] = 2
    assert _goal(dict(base, behaviour=b), 'idle agent wakes up') == ('only 2 of 3 seen', False)


@pytest.mark.parametrize('limited, plain, met', [(4.8, 48.0, True), (5.0, 48.0, True), (5.3, 48.0, False),
                                                 (None, 48.0, False), (4.8, 4.9, False)])
def test_rate_limit_goal_needs_a_burst_above_the_limit(limited, plain, met):
    results = dict(_results(), behaviour=_behaviour(limited=limited, plain=plain))
    assert _goal(results, 'perception_rate=5')[1] is met


def test_rate_limit_goal_matches_the_agents_project():
    with open(os.path.join(os.path.dirname(__file__), '..', 'agents', 'rate_limit.mas2j')) as f:
        text = f.read()
    assert re.search(r'limited bench\.asl \[perception_rate=(\d+)\]', text).group(1) == str(report.RATE_LIMIT_PER_S)
    assert re.search(r'^\s*plain bench\.asl;', text, re.M)


def test_sim_goals_are_the_rostests_bounds():
    base = _results()
    verdicts = dict((g, met) for g, _, met in report.goals(dict(base, behaviour=_behaviour(rtf=0.95, vision=8.9))))
    assert verdicts['simulator real-time factor at rate 1, both execution layers running > 0.95'] is False
    assert verdicts['simulator: vision >= 9 Hz'] is False
    assert verdicts['simulator: camera >= 9.5 Hz'] is True
    b = _behaviour()
    b['sim']['real_time_factor'] = None
    assert _goal(dict(base, behaviour=b), 'simulator real-time factor') == ('no /clock', False)


def test_markdown_has_the_new_sections_and_failed_parts():
    results = dict(_results(), cpu=_cpu(800.0), reaction=_reaction(5.0, 40.0), behaviour=_behaviour(),
                   errors={'behaviour.sim': 'RuntimeError: the vision synthesizer never published'},
                   duration_s=100.4, durations_s={'cpu': 60.2, 'behaviour.sim': 30.0})
    text = report.markdown(results)
    for heading in ('## Node CPU time per perception message', '## Reaction: perception → action',
                    '## Behaviour', '## Failed parts'):
        assert heading in text
    assert '| burst + 50 busy intentions | 50 of 50 | 5.00 | 40.00 | 40.00 | 40.00 |' in text
    assert '| limited (`perception_rate=5`) | 15 | 4.80 | 200 |' in text
    assert '| vision | 9.8 | ≥ 9 |' in text
    assert 'behaviour.sim: RuntimeError' in text
    assert 'Duration: 100 s in all; cpu 60 s, behaviour.sim 30 s.' in text
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


def _hostile(worst_ms=40.0, answered=5, newest=12.0, before=100.0, after=115.0):
    row = {'reaction_ms': {'n': 5, 'p50': 3.0, 'p90': 5.0, 'p99': 6.0, 'max': 6.0, 'min': 2.0, 'mean': 3.0},
           'send_s': 0.1, 'rss_mb_before': 100.0, 'rss_mb_after': 101.0}
    slow = dict(row, reaction_ms={'n': answered, 'p50': 9.0, 'p90': worst_ms, 'p99': worst_ms, 'max': worst_ms,
                                  'min': 2.0, 'mean': 9.0} if answered else {'n': 0})
    return {'inputs': {'seed': 13, 'triggers_per_input': 5, 'perception_ttl_s': 10.0,
                       'rounds': [{'deep': row, 'huge_agent_names': slow, 'reserved': row},
                                  {'deep': row, 'huge_agent_names': row, 'reserved': row}]},
            'flood': {'seconds': 20.0, 'rate_hz': 1000.0, 'literals': 50, 'mark_period_s': 1.0, 'after_s': 10.0,
                      'newest_ms': newest, 'marks_ms': {'n': 20, 'p50': 8.0, 'max': 60.0},
                      'messages_published': 19000, 'cpu_s': 15.0, 'flood_wall_s': 21.0,
                      'rss_mb_before': before, 'rss_mb_peak': 400.0, 'rss_mb_after': after}}


def test_hostile_goals_met():
    results = dict(_results(), hostile=_hostile())
    verdicts = [_goal(results, start) for start in ('hostile input', 'after a 20 s', '10 s after')]
    assert [met for _, met in verdicts] == [True, True, True]
    assert verdicts[0][0] == 'slowest 40.0 ms (after huge_agent_names, round 1); last round slowest 6.0 ms (deep)'
    assert verdicts[2][0] == '115 MB, 1.15 x before (100 MB; peak 400 MB)'


@pytest.mark.parametrize('kwargs, which', [(dict(worst_ms=150.0), 0), (dict(answered=4), 0), (dict(answered=0), 0),
                                           (dict(newest=60.0), 1), (dict(newest=None), 1), (dict(after=121.0), 2)])
def test_hostile_goals_missed(kwargs, which):
    results = dict(_results(), hostile=_hostile(**kwargs))
    verdicts = [_goal(results, start) for start in ('hostile input', 'after a 20 s', '10 s after')]
    assert [met for _, met in verdicts] == [i != which for i in range(3)]


def test_an_unanswered_trigger_is_the_worst_input():
    r, name, ms, complete = report.worst_input(_hostile(worst_ms=1.0, answered=4)['inputs'])
    assert (r, name, complete) == (1, 'huge_agent_names', False)


def test_the_report_has_a_hostile_section():
    text = report.markdown(dict(_results(), hostile=_hostile()))
    assert '## Hostile input' in text
    assert '| huge_agent_names | 0.10 | 5 of 5, 5 of 5 | 40.0 | 6.0 | 100 → 101 |' in text
    assert 'newest (final) 12.0 ms' in text
