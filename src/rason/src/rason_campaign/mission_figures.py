"""The fault-tolerance campaign's PNG figures (matplotlib, Agg; no ROS):

- ``completion.png``: completion rate per fault, recovery beside baseline, with the 95 %
  Wilson interval and the 95 % target line;
- ``times.png``: time to completion of every completed run per fault and arm, with the
  medians.
"""
import os

import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt  # noqa: E402

from rason_campaign import mission_report  # noqa: E402
from rason_campaign.figures import SIZE, save  # noqa: E402
from rason_campaign.plan import ARMS  # noqa: E402

ARM_COLOURS = {'recovery': '#4c72b0', 'baseline': '#c44e52'}
WIDTH = 0.38    # bar width; the arms sit side by side around each fault


def _faults(rows):
    faults = []
    for r in rows:
        if r['fault'] not in faults:
            faults.append(r['fault'])
    return faults


def _offset(arm):
    return (ARMS.index(arm) - (len(ARMS) - 1) / 2.0) * WIDTH


def completion_figure(rows, path):
    faults = _faults(rows)
    fig, ax = plt.subplots(figsize=SIZE)
    for arm in ARMS:
        mine = {r['fault']: r for r in rows if r['arm'] == arm}
        xs = [i + _offset(arm) for i, f in enumerate(faults) if f in mine]
        rs = [mine[f] for f in faults if f in mine]
        if not rs:
            continue
        heights = [100 * r['rate'] for r in rs]
        errors = [[100 * (r['rate'] - r['ci_low']) for r in rs],
                  [100 * (r['ci_high'] - r['rate']) for r in rs]]
        ax.bar(xs, heights, WIDTH, yerr=errors, capsize=3, color=ARM_COLOURS[arm], label=arm)
        for x, r in zip(xs, rs):  # the counts, readable on a 0 % bar too
            ax.text(x, 2, '%d/%d' % (r['completed'], r['runs']), ha='center', va='bottom',
                    fontsize=6, rotation=90)
    ax.axhline(100 * mission_report.TARGET_RECOVERY, color='k', ls='--', lw=0.8,
               label='target (recovery)')
    ax.set_xticks(range(len(faults)))
    ax.set_xticklabels([f.replace('_', '\n') for f in faults], fontsize=8)
    ax.set_ylim(0, 105)
    ax.set_ylabel('missions completed (%)')
    ax.set_title('Completion rate per fault (95 % Wilson interval)')
    ax.legend(fontsize=7, loc='upper left', bbox_to_anchor=(1.0, 1.0))
    save(fig, path)


def times_figure(results, rows, path):
    faults = _faults(rows)
    fig, ax = plt.subplots(figsize=SIZE)
    for arm in ARMS:
        times = [(faults.index(r['fault']), r['time']) for r in results
                 if r['arm'] == arm and r['completed'] and r['time'] is not None]
        ax.plot([i + _offset(arm) for i, _ in times], [t for _, t in times], 'o', ms=3,
                alpha=0.7, color=ARM_COLOURS[arm], label=arm)
        for r in rows:
            if r['arm'] == arm and r['time_median'] is not None:
                x = faults.index(r['fault']) + _offset(arm)
                ax.hlines(r['time_median'], x - WIDTH / 2, x + WIDTH / 2,
                          colors=ARM_COLOURS[arm])
    ax.set_xticks(range(len(faults)))
    ax.set_xticklabels([f.replace('_', '\n') for f in faults], fontsize=8)
    ax.set_xlim(-0.6, len(faults) - 0.4)
    ax.set_ylim(bottom=0)
    ax.set_ylabel('time to completion (s)')
    ax.set_title('Time to completion per fault (lines: medians)')
    ax.legend(fontsize=7, loc='upper left', bbox_to_anchor=(1.0, 1.0))
    save(fig, path)


def make_all(results, out_dir):
    """Write every figure into ``out_dir``.

    :rtype: dict figure name -> file name (relative to out_dir)
    """
    rows = mission_report.summary(results)
    names = {'completion': 'completion.png', 'times': 'times.png'}
    completion_figure(rows, os.path.join(out_dir, names['completion']))
    times_figure(results, rows, os.path.join(out_dir, names['times']))
    return names
