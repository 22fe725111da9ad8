"""Summary statistics of latency samples and cycle times (standard library only)."""
import math


def percentile(samples, p):
    """The p-th percentile (0..100) of samples, linearly interpolated between order statistics.

    :raises ValueError: no samples, or p outside 0..100
    """
    if not samples:
        raise ValueError('percentile of no samples')
    if not 0 <= p <= 100:
        raise ValueError('percentile %r outside 0..100' % (p,))
    ordered = sorted(samples)
    rank = (len(ordered) - 1) * p / 100.0
    low = int(math.floor(rank))
    high = min(low + 1, len(ordered) - 1)
    return ordered[low] + (ordered[high] - ordered[low]) * (rank - low)


def median(samples):
    return percentile(samples, 50)


def summarize(samples):
    """n, p50, p90, p99, min, max and mean of samples (a dict; only n when there are none)."""
    if not samples:
        return {'n': 0}
    return {'n': len(samples), 'p50': percentile(samples, 50), 'p90': percentile(samples, 90),
            'p99': percentile(samples, 99), 'min': min(samples), 'max': max(samples),
            'mean': sum(samples) / len(samples)}


def ratio(value, baseline):
    """value / baseline, or None when either is missing or the baseline is not positive."""
    if value is None or baseline is None or baseline <= 0:
        return None
    return value / baseline


def median_run(runs):
    """The run (a dict with ``ms``) with the median time; a copy. With an odd count it is a
    run that happened, not an average of two."""
    if not runs:
        raise ValueError('median of no runs')
    ordered = sorted(runs, key=lambda x: x['ms'])
    return dict(ordered[len(ordered) // 2])
