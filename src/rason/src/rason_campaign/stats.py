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
