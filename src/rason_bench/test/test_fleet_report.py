"""The fleet part's goals and its section of report.md."""
import math

from rason_bench import fleet_report, report


def _s(p50, p99, n=100):
    return {'n': n, 'p50': p50, 'p90': p99, 'p99': p99, 'max': p99 + 1.0}


def _fleet(rtt_p99=8.0, within=4000.0, beyond=8000.0, slowest=60.0, false10=0, unnoticed=()):
    return {
        'loopback': {'round_trip_ms': _s(3.0, rtt_p99), 'warmup': 200},
        'namespaces': {'skipped': 'network namespaces need root'},
        'rate': {'seconds_per_step': 2.0, 'bound_ms': 100.0, 'highest_within': within, 'lowest_beyond': beyond,
                 'steps': [{'rate': 500.0, 'achieved_rate': 499.0, 'sent': 1000, 'answered': 1000, 'p50_ms': 2.0,
                            'p99_ms': 5.0, 'max_ms': 9.0},
                           {'rate': 8000.0, 'achieved_rate': 7000.0, 'sent': 16000, 'answered': 12000,
                            'p50_ms': 300.0, 'p99_ms': math.inf, 'max_ms': 2900.0}]},
        'departures': {'robots': 100, 'singles': 10, 'batch': 10, 'single_ms': _s(20.0, slowest - 1.0, 10),
                       'batch_ms': _s(30.0, 40.0, 10), 'unnoticed': list(unnoticed), 'other_departures': []},
        'false_departures': {'robots': 100, 'window_s': 120.0, 'lossy_link': 'robots',
                             'levels': [{'loss_percent': 10, 'departures': false10, 'robots_affected': min(false10, 100),
                                         'per_10_min': false10 * 5.0},
                                        {'loss_percent': 20, 'departures': 7, 'robots_affected': 3,
                                         'per_10_min': 35.0}]}}


def test_every_goal_of_the_issue_is_reported_and_a_skipped_one_is_neither_met_nor_failed():
    goals = fleet_report.goals(_fleet())
    assert len(goals) == 5
    assert [met for _, _, met in goals] == [True, None, True, True, True]
    assert 'skipped: network namespaces need root' in goals[1][1]
    assert goals[2][1] == 'within up to 4000/s; passed at 8000/s'


def test_each_goal_fails_on_its_own_measurement():
    assert [met for _, _, met in fleet_report.goals(_fleet(rtt_p99=25.0))][0] is False
    assert [met for _, _, met in fleet_report.goals(_fleet(within=1500.0))][2] is False
    assert [met for _, _, met in fleet_report.goals(_fleet(slowest=2500.0))][3] is False
    assert [met for _, _, met in fleet_report.goals(_fleet(false10=1))][4] is False


def test_a_departure_never_noticed_fails_the_goal_whatever_the_times():
    text, met = fleet_report.departure_verdict(_fleet(unnoticed=[97])['departures'])
    assert not met
    assert '1 never noticed' in text
    text, met = fleet_report.departure_verdict(_fleet()['departures'])
    assert met and text.startswith('slowest 60.0 ms')


def test_a_rate_beyond_the_bound_from_the_start_fails():
    fleet = _fleet(within=None, beyond=500.0)
    assert fleet_report.goals(fleet)[2][2] is False


def test_the_section_has_a_row_per_measurement_and_shows_lost_answers_as_inf():
    text = fleet_report.text(_fleet())
    assert '| loopback | 100 (after 200) | 3.00 | 8.00 | 8.00 | 9.00 |' in text
    assert '| network namespaces | skipped: network namespaces need root |' in text
    assert '| 8000 | 7000 | 12000 of 16000 | 300.0 | inf | 2900.0 |' in text
    assert '| 10 % | 0 | 0 | 0.0 |' in text
    assert '| 20 % | 7 | 3 | 35.0 |' in text


def test_the_whole_report_carries_the_fleet_goals_and_section():
    results = {'machine': {'date': 'd', 'cpus': 2, 'cpu_model': 'cpu', 'load_at_start': [0.1, 0.2, 0.3]},
               'params': {'seconds': 1}, 'fleet': _fleet()}
    md = report.markdown(results)
    assert '## Fleet channel (MQTT)' in md
    assert '| skipped |' in md
    assert 'Each cell' not in md  # the Listing 5.4 cells are not in this run
    assert report.verdict(None) == 'skipped' and report.verdict(False) == '**not met**'
