"""The fleet part's arithmetic: reading the processes' lines, tail latency with lost
messages, the rate search, departure delays and scaling."""
import math

import pytest

from rason_bench import fleetcalc


def test_round_trips_are_read_in_sequence_order_after_the_warmup():
    lines = ['[INFO] [1.0]: [alice] rtt 1 2.5', '[INFO] [1.0]: [alice] rtt 0 9.0', '[bob] rtt 2 1.0',
             '[INFO] [1.0]: [alice] rtt 2 3.25', '[alice] rtt 3 1.5E1', '[alice] present bob 12.0']
    assert fleetcalc.round_trips(lines, 'alice', 1, 10) == [2.5, 3.25, 15.0]
    assert fleetcalc.round_trips(lines, 'alice', 1, 2) == [2.5, 3.25]
    assert fleetcalc.round_trips(lines, 'alice', 0, 10)[0] == 9.0


def test_a_load_line_gives_the_answers_and_the_rate_achieved():
    run = fleetcalc.load_run('load 3 2000.0 4000 2.000 1.5 2.0 103.25\n')
    assert run == {'run': 3, 'rate': 2000.0, 'sent': 4000, 'answered': 3, 'send_seconds': 2.0,
                   'achieved_rate': 2000.0, 'ms': [1.5, 2.0, 103.25]}
    assert fleetcalc.load_run('load 1 500.0 10 0.020')['answered'] == 0
    assert fleetcalc.load_run('killed 3 12.0') is None


def test_tail_latency_is_the_percentile_when_everything_was_answered():
    samples = [float(x) for x in range(1, 101)]
    assert fleetcalc.tail_ms(samples, 100, 50) == pytest.approx(50.5)
    assert fleetcalc.tail_ms(samples, 100, 99) == pytest.approx(99.01)


def test_unanswered_messages_count_as_slower_than_any_answer():
    answered = [1.0] * 995
    assert fleetcalc.tail_ms(answered, 1000, 99) == 1.0      # 5 lost of 1000: p99 is still an answer
    assert fleetcalc.tail_ms(answered[:980], 1000, 99) == math.inf   # 20 lost: p99 falls among them
    assert fleetcalc.tail_ms([], 10, 50) == math.inf
    with pytest.raises(ValueError):
        fleetcalc.tail_ms([1.0, 2.0], 1, 50)
    with pytest.raises(ValueError):
        fleetcalc.tail_ms([], 0, 50)


def _search(p99_of, **kw):
    search = fleetcalc.RateSearch(**kw)
    rate = search.next_rate()
    while rate is not None:
        search.record(rate, p99_of(rate))
        rate = search.next_rate()
    return search


def test_the_rate_is_doubled_until_p99_passes_the_bound_then_the_interval_halved_twice():
    search = _search(lambda rate: 5.0 if rate <= 2600 else 500.0, start=500, factor=2, limit=16000,
                     bound_ms=100.0, refinements=2)
    assert [r for r, _ in search.steps] == [500, 1000, 2000, 4000, 3000, 2500]
    assert (search.highest_within, search.lowest_beyond) == (2500, 3000)


def test_the_rate_search_stops_at_its_limit_when_the_bound_is_never_passed():
    search = _search(lambda rate: 5.0, start=500, factor=2, limit=4000)
    assert [r for r, _ in search.steps] == [500, 1000, 2000, 4000]
    assert (search.highest_within, search.lowest_beyond) == (4000, None)


def test_a_bound_passed_at_the_first_rate_ends_the_search_with_nothing_within():
    search = _search(lambda rate: math.inf, start=500)
    assert [r for r, _ in search.steps] == [500]
    assert (search.highest_within, search.lowest_beyond) == (None, 500)


def test_departure_delay_is_from_the_kill_to_the_first_notice_after_it():
    killed = {7: 1000.0, 8: 2000.0, 9: 3000.0}
    absent = [(7, 900.0), (7, 1040.5), (7, 1500.0), (8, 2100.0), (5, 2500.0)]
    assert fleetcalc.departure_delays(killed, absent) == {7: 40.5, 8: 100.0}


def test_absent_now_is_each_robots_last_word():
    lines = ['[w] present sim1 1.0', '[w] present sim2 1.0', '[w] absent sim1 2.0', '[w] absent sim2 2.0',
             '[w] present sim2 3.0']
    assert fleetcalc.absent_now(lines) == {'sim1'}
    assert fleetcalc.absent_now(lines + ['[w] present sim1 4.0']) == set()


def test_events_in_a_window_are_scaled_to_ten_minutes():
    assert fleetcalc.per_period(3, 120.0) == 15.0
    assert fleetcalc.per_period(0, 30.0) == 0.0
    with pytest.raises(ValueError):
        fleetcalc.per_period(1, 0.0)
