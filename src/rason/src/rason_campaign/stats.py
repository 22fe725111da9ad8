"""Per-fault statistics of a campaign's results (no ROS)."""
import math

from rason_campaign.steps import OUTCOMES, STEP_NAMES


def mean_sd(values):
    """Mean and sample standard deviation (n - 1, as the thesis's 0.78 s of Table 7.1) of
    the values that are not None; (None, None) when there are none, sd None for one value.

    :rtype: (float or None, float or None)
    """
    values = [v for v in values if v is not None]
    if not values:
        return None, None
    mean = sum(values) / len(values)
    if len(values) < 2:
        return mean, None
    return mean, math.sqrt(sum((v - mean) ** 2 for v in values) / (len(values) - 1))


def counts(results):
    """Outcome -> number of results with it (every outcome present)."""
    c = {o: 0 for o in OUTCOMES}
    for r in results:
        c[r['outcome']] += 1
    return c


def by_fault(results):
    """Fault -> its results, faults in the order they first appear."""
    groups = {}
    for r in results:
        groups.setdefault(r['fault'], []).append(r)
    return groups


def step_stats(results):
    """Step name -> (mean, sd) over the correct runs (the thesis too averages its
    successful runs only)."""
    correct = [r for r in results if r['outcome'] == 'correct']
    return {s: mean_sd([r['steps'][s] for r in correct]) for s in STEP_NAMES}


def summary(results):
    """Fault -> {'runs', 'counts', 'steps'} and the overall counts and correct fraction.

    :rtype: dict
    """
    faults = {f: {'runs': len(rs), 'counts': counts(rs), 'steps': step_stats(rs)}
              for f, rs in by_fault(results).items()}
    total = counts(results)
    n = len(results)
    return {'faults': faults, 'counts': total, 'runs': n,
            'correct_fraction': total['correct'] / n if n else None}


UNDIAGNOSED = 'undiagnosed'


def confusion(results, key='component'):
    """Injected fault -> {diagnosed component -> runs}, and the columns in order: every
    injected fault (in order of appearance), then any other component diagnosed, then
    'undiagnosed' (no diagnosis at all counts as undiagnosed). ``key``: the field of a
    result that holds the diagnosed component.

    :rtype: (dict, list)
    """
    matrix = {}
    columns = []
    for r in results:
        matrix.setdefault(r['fault'], {})
        if r['fault'] not in columns:
            columns.append(r['fault'])
    for r in results:
        diagnosed = r.get(key) or UNDIAGNOSED
        row = matrix[r['fault']]
        row[diagnosed] = row.get(diagnosed, 0) + 1
        if diagnosed not in columns and diagnosed != UNDIAGNOSED:
            columns.append(diagnosed)
    return matrix, columns + [UNDIAGNOSED]


def wilson(successes, n, z=1.96):
    """Wilson score interval of a proportion (95 % for z = 1.96): unlike p ± z·se it stays
    inside [0, 1] and is not empty at 0 or n successes, which is where a campaign's rates
    are. (None, None) when n is 0.

    :rtype: (float or None, float or None)
    """
    if n <= 0:
        return None, None
    p = successes / n
    denominator = 1 + z * z / n
    centre = (p + z * z / (2 * n)) / denominator
    half = z * math.sqrt(p * (1 - p) / n + z * z / (4 * n * n)) / denominator
    return max(0.0, centre - half), min(1.0, centre + half)


def percentile(values, q):
    """The q-th percentile (0-100) of the values that are not None, interpolated linearly
    between the closest ranks; None when there are none.

    :rtype: float or None
    """
    values = sorted(v for v in values if v is not None)
    if not values:
        return None
    position = (len(values) - 1) * q / 100.0
    low = int(math.floor(position))
    high = min(low + 1, len(values) - 1)
    return values[low] + (values[high] - values[low]) * (position - low)


def median(values):
    """The median of the values that are not None, or None."""
    return percentile(values, 50)
