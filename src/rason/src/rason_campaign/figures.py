"""The campaign's PNG figures (matplotlib, Agg; no ROS):

- ``steps_<fault>.png``: latency by step, a stacked bar per run and one for the thesis's
  mean (like thesis Figures 7.1, 7.3, 7.5, 7.7);
- ``totals.png``: total latency of every run, per fault, beside the thesis's mean total
  (like Figures 7.2, 7.4, 7.6, 7.8);
- ``outcomes.png``: correct / undiagnosed / wrong per fault.
"""
import os

import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt  # noqa: E402

from rason_campaign import stats, thesis  # noqa: E402
from rason_campaign.steps import OUTCOMES  # noqa: E402

STEPS = (('fault_detection', 'fault detection', '#4c72b0'),
         ('robot_location', 'robot location', '#dd8452'),
         ('diagnosis', 'diagnosis', '#55a868'))
OUTCOME_COLOURS = {'correct': '#55a868', 'undiagnosed': '#ccb974', 'wrong': '#c44e52'}
SIZE = (5.5, 3.2)
DPI = 100


def save(fig, path):
    """Writes a figure laid out at the campaigns' size and resolution, and frees it."""
    fig.tight_layout()
    fig.savefig(path, dpi=DPI)
    plt.close(fig)


def steps_figure(fault, results, path):
    labels, columns = [], []
    for r in results:
        labels.append('%d%s' % (r['number'], '' if r['outcome'] == 'correct' else '*'))
        columns.append([r['steps'][k] for k, _, _ in STEPS] + [r['steps']['total']])
    means = thesis.step_means(fault)
    if means:
        labels.append('thesis')
        columns.append(list(means))
    fig, ax = plt.subplots(figsize=SIZE)
    x = range(len(columns))
    bottom = [0.0] * len(columns)
    for i, (_, title, colour) in enumerate(STEPS):
        heights = [c[i] or 0.0 for c in columns]
        ax.bar(x, heights, bottom=bottom, color=colour, label=title)
        bottom = [b + h for b, h in zip(bottom, heights)]
    # Runs with no help step (no fault) have only a total.
    rest = [max((c[3] or 0.0) - b, 0.0) for c, b in zip(columns, bottom)]
    if any(rest):
        ax.bar(x, rest, bottom=bottom, color='#8c8c8c', label='total (no help asked)')
    ax.set_xticks(list(x))
    ax.set_xticklabels(labels)
    ax.set_xlabel('run (* not correct)')
    ax.set_ylabel('latency (s)')
    ax.set_title('%s - latency by step' % fault)
    ax.legend(fontsize=7, loc='upper left', bbox_to_anchor=(1.0, 1.0))
    save(fig, path)


def totals_figure(results, path):
    groups = stats.by_fault(results)
    fig, ax = plt.subplots(figsize=SIZE)
    for i, (fault, rs) in enumerate(groups.items()):
        for j, r in enumerate(rs):
            total = r['steps']['total']
            if total is None:
                continue
            ax.plot(i + (j - (len(rs) - 1) / 2) * 0.08, total, 'o', ms=4,
                    color=OUTCOME_COLOURS[r['outcome']])
        if fault in thesis.STATED_TOTAL:
            ax.hlines(thesis.STATED_TOTAL[fault][0], i - 0.35, i + 0.35, colors='k',
                      linestyles='dashed')
    handles = [plt.Line2D([], [], marker='o', ls='', color=OUTCOME_COLOURS[o], label=o)
               for o in OUTCOMES] + [plt.Line2D([], [], ls='--', color='k', label='thesis mean')]
    ax.legend(handles=handles, fontsize=7)
    ax.set_xticks(range(len(groups)))
    ax.set_xticklabels([f.replace('_', '\n') for f in groups], fontsize=8)
    ax.set_ylabel('total latency (s)')
    ax.set_title('Total latency per run')
    ax.set_ylim(bottom=0)
    save(fig, path)


def outcomes_figure(results, path):
    groups = stats.by_fault(results)
    fig, ax = plt.subplots(figsize=SIZE)
    left = [0] * len(groups)
    y = range(len(groups))
    for o in OUTCOMES:
        widths = [stats.counts(rs)[o] for rs in groups.values()]
        ax.barh(y, widths, left=left, color=OUTCOME_COLOURS[o], label=o)
        left = [a + b for a, b in zip(left, widths)]
    ax.set_yticks(list(y))
    ax.set_yticklabels(list(groups), fontsize=8)
    ax.invert_yaxis()
    ax.set_xlabel('runs')
    ax.set_title('Outcomes')
    ax.legend(fontsize=7, loc='lower right')
    save(fig, path)


def make_all(results, out_dir):
    """Write every figure into ``out_dir``.

    :rtype: dict figure name -> file name (relative to out_dir)
    """
    names = {}
    for fault, rs in stats.by_fault(results).items():
        names['steps_' + fault] = 'steps_%s.png' % fault
        steps_figure(fault, rs, os.path.join(out_dir, names['steps_' + fault]))
    names['totals'] = 'totals.png'
    totals_figure(results, os.path.join(out_dir, names['totals']))
    names['outcomes'] = 'outcomes.png'
    outcomes_figure(results, os.path.join(out_dir, names['outcomes']))
    return names
