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


def cpu_per_message_us(cpu_s, wall_s, idle_cpu_per_s, messages):
    """A process's CPU time per message received, in µs: the CPU seconds it used over
    ``wall_s`` while receiving ``messages``, less what it uses idle (``idle_cpu_per_s``
    CPU seconds per wall second) over the same time; None without messages."""
    if not messages:
        return None
    return 1e6 * (cpu_s - idle_cpu_per_s * wall_s) / messages


def rate_hz(stamps, start, end):
    """Events per second among ``stamps`` (seconds) in [start, end).

    :raises ValueError: an empty or reversed window
    """
    if not end > start:
        raise ValueError('window [%r, %r) is empty' % (start, end))
    return sum(1 for t in stamps if start <= t < end) / (end - start)


def real_time_factor(pairs):
    """Simulated seconds per wall second from (wall, sim) pairs (e.g. /clock messages and
    when they arrived), between the first and the last; None with fewer than two."""
    if len(pairs) < 2:
        return None
    (w0, s0), (w1, s1) = pairs[0], pairs[-1]
    if w1 <= w0:
        return None
    return (s1 - s0) / (w1 - w0)


def update_rate(times_ms):
    """How often updates came, from the times (ms) they came: n, updates per second between
    the first and the last ((n - 1) / span; None with fewer than two) and the shortest
    interval between two consecutive ones (ms)."""
    times = sorted(times_ms)
    out = {'n': len(times), 'per_s': None, 'min_interval_ms': None}
    if len(times) >= 2 and times[-1] > times[0]:
        out['per_s'] = (len(times) - 1) * 1000.0 / (times[-1] - times[0])
        out['min_interval_ms'] = min(b - a for a, b in zip(times, times[1:]))
    return out
