"""The fleet campaign's PNG figures (matplotlib, Agg; no ROS):

- ``fleet_diagnosis.png``: each faulty robot's time to diagnosis per fleet size, from its call
  and from its award, contract net beside broadcast, with the medians;
- ``fleet_paired.png``: the same faulty robot of the same run in both arms, contract net
  against broadcast, with the diagonal (below it: contract net was sooner).
"""
import os

import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt  # noqa: E402

from rason_campaign import fleet_report, stats  # noqa: E402
from rason_campaign.figures import SIZE, save  # noqa: E402
from rason_campaign.fleet_plan import FLEET_ARMS  # noqa: E402

ARM_COLOURS = {'contract_net': '#4c72b0', 'broadcast': '#c44e52'}
WIDTH = 0.38


def diagnosis_figure(results, path):
    sizes = sorted({fleet_report.size_of(r) for r in results})
    fig, axes = plt.subplots(1, 2, figsize=(SIZE[0] * 1.6, SIZE[1]), sharey=True)
    for ax, since, title in zip(axes, ('time_to_diagnosis', 'award_to_diagnosis'),
                                ('from the first call for a watcher', 'from the award of the help')):
        for arm_index, arm in enumerate(FLEET_ARMS):
            offset = (arm_index - (len(FLEET_ARMS) - 1) / 2.0) * WIDTH
            for k, size in enumerate(sizes):
                group = [r for r in results if r['arm'] == arm and fleet_report.size_of(r) == size]
                times = fleet_report.diagnosis_times(group, since)
                if not times:
                    continue
                spread = [k + offset + WIDTH * 0.6 * ((i % 7) / 6.0 - 0.5) for i in range(len(times))]
                ax.scatter(spread, times, s=12, alpha=0.7, color=ARM_COLOURS[arm],
                           label=fleet_report.ARM_NAMES[arm] if k == 0 else None)
                m = stats.median(times)
                ax.plot([k + offset - WIDTH / 2, k + offset + WIDTH / 2], [m, m], color='black', lw=1.5)
        ax.set_xticks(range(len(sizes)))
        ax.set_xticklabels(['N = %d' % s for s in sizes])
        ax.set_xlim(-0.6, len(sizes) - 0.4)
        ax.set_title('Time to diagnosis %s' % title, fontsize=9)
    axes[0].set_ylabel('simulated s (bars: medians)')
    axes[0].set_ylim(bottom=0)
    axes[1].legend(fontsize=8, loc='upper right', framealpha=0.9)
    save(fig, path)


def paired_figure(results, path):
    pairs = fleet_report.paired(results)
    fig, ax = plt.subplots(figsize=(SIZE[1] * 1.15, SIZE[1]))
    if pairs:
        xs = [bc for _, _, _, bc in pairs]
        ys = [cn for _, _, cn, _ in pairs]
        top = max(xs + ys) * 1.05
        ax.plot([0, top], [0, top], color='grey', lw=0.8)
        ax.scatter(xs, ys, s=12, alpha=0.7, color=ARM_COLOURS['contract_net'])
        ax.set_xlim(0, top)
        ax.set_ylim(0, top)
    ax.set_xlabel('broadcast (s)')
    ax.set_ylabel('contract net (s)')
    ax.set_title('Same run, same robot', fontsize=9)
    save(fig, path)


def make_all(results, out_dir):
    """Writes the figures into out_dir; returns their file names."""
    names = []
    for name, draw in (('fleet_diagnosis.png', diagnosis_figure), ('fleet_paired.png', paired_figure)):
        draw(results, os.path.join(out_dir, name))
        names.append(name)
    return names
