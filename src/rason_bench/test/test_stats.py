"""Percentiles and summaries of latency samples."""
import pytest

from rason_bench import stats


def test_percentile_interpolates_between_order_statistics():
    samples = [4.0, 1.0, 3.0, 2.0]
    assert stats.percentile(samples, 0) == 1.0
    assert stats.percentile(samples, 100) == 4.0
    assert stats.percentile(samples, 50) == pytest.approx(2.5)
    assert stats.percentile(samples, 99) == pytest.approx(3.97)


def test_percentile_of_one_sample_is_that_sample():
    assert stats.percentile([7.5], 99) == 7.5


@pytest.mark.parametrize('samples, p', [([], 50), ([1.0], -1), ([1.0], 101)])
def test_percentile_refuses_nonsense(samples, p):
    with pytest.raises(ValueError):
        stats.percentile(samples, p)


def test_summarize_has_the_reported_fields():
    s = stats.summarize([float(x) for x in range(1, 101)])
    assert s['n'] == 100
    assert s['p50'] == pytest.approx(50.5)
    assert s['p99'] == pytest.approx(99.01)
    assert (s['min'], s['max'], s['mean']) == (1.0, 100.0, 50.5)
    assert stats.summarize([]) == {'n': 0}


def test_ratio_needs_a_positive_baseline():
    assert stats.ratio(3.0, 2.0) == 1.5
    assert stats.ratio(3.0, 0.0) is None
    assert stats.ratio(None, 2.0) is None


def test_a_cell_is_its_median_run_not_an_average():
    runs = [{'ms': 0.009, 'cpu_percent': 150}, {'ms': 0.005, 'cpu_percent': 140},
            {'ms': 0.006, 'cpu_percent': 145}]
    assert stats.median_run(runs) == {'ms': 0.006, 'cpu_percent': 145}
    assert stats.median_run(runs[:1]) == runs[0]
    with pytest.raises(ValueError):
        stats.median_run([])


def test_pure_modules_do_not_import_rospy():
    """The modules the unit tests cover run without ROS (a fresh interpreter, so that
    another test's imports do not count)."""
    import subprocess
    import sys
    code = ('import sys; import rason_bench.stats, rason_bench.report, rason_bench.protocol, '
            'rason_bench.thesis; print(sorted(m for m in ("rospy", "rosgraph") if m in sys.modules))')
    out = subprocess.run([sys.executable, '-c', code], stdout=subprocess.PIPE, universal_newlines=True, check=True)
    assert out.stdout.strip() == '[]'


def test_cpu_per_message_takes_the_idle_use_off():
    # 0.5 CPU s over 2 wall s, idle 0.05 CPU s per s, 100 messages: (0.5 - 0.1) / 100 = 4 ms
    assert stats.cpu_per_message_us(0.5, 2.0, 0.05, 100) == pytest.approx(4000.0)
    assert stats.cpu_per_message_us(0.5, 2.0, 0.0, 100) == pytest.approx(5000.0)
    assert stats.cpu_per_message_us(0.5, 2.0, 0.05, 0) is None


def test_rate_counts_the_half_open_window():
    stamps = [0.0, 0.5, 1.0, 1.5, 2.0]
    assert stats.rate_hz(stamps, 0.0, 2.0) == 2.0   # 2.0 itself is outside
    assert stats.rate_hz(stamps, 0.25, 1.25) == 2.0
    assert stats.rate_hz([], 0.0, 1.0) == 0.0
    with pytest.raises(ValueError):
        stats.rate_hz(stamps, 1.0, 1.0)


def test_real_time_factor_is_sim_over_wall_between_first_and_last():
    assert stats.real_time_factor([(10.0, 100.0), (10.5, 100.4), (12.0, 101.8)]) == pytest.approx(0.9)
    assert stats.real_time_factor([(10.0, 100.0)]) is None
    assert stats.real_time_factor([]) is None
    assert stats.real_time_factor([(10.0, 100.0), (10.0, 100.1)]) is None


def test_update_rate_from_arrival_times():
    r = stats.update_rate([1000.0, 1200.0, 1450.0, 1650.0, 1850.0])  # order does not matter below
    assert r['n'] == 5
    assert r['per_s'] == pytest.approx(4 / 0.85)
    assert r['min_interval_ms'] == pytest.approx(200.0)
    assert stats.update_rate([1450.0, 1000.0, 1200.0])['min_interval_ms'] == pytest.approx(200.0)
    assert stats.update_rate([5.0]) == {'n': 1, 'per_s': None, 'min_interval_ms': None}
    assert stats.update_rate([]) == {'n': 0, 'per_s': None, 'min_interval_ms': None}
