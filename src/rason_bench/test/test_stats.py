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
    from rason_bench.experiments import median_run
    runs = [{'ms': 0.009, 'cpu_percent': 150}, {'ms': 0.005, 'cpu_percent': 140},
            {'ms': 0.006, 'cpu_percent': 145}]
    assert median_run(runs) == {'ms': 0.006, 'cpu_percent': 145}
    assert median_run(runs[:1]) == runs[0]
