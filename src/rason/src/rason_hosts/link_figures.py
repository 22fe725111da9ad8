"""The figure of a campaign across hosts (matplotlib, Agg; no ROS): by loss on the robots'
links, the share of missions completed and the time to Faulty's diagnosis, each drawn link
beside the same runs on a clean link.
"""
import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt  # noqa: E402

from rason_hosts.link_campaign import MISSION_GOAL, by_factor, missions  # noqa: E402

DRAWN, CLEAN = '#c44e52', '#4c72b0'
CUT_MARK = 'x'          # drawn runs with a cut
SIZE = (8.0, 3.2)
DPI = 100


def loss_columns(records):
    """Per loss level the drawn links took: (level, (completed, counted) drawn, the same on the
    clean twins, [(diagnosis_s, cut?) of the drawn correct runs], [diagnosis_s of the clean])."""
    columns = []
    for factor, level, runs, twins in by_factor(records):
        if factor != 'loss':
            continue
        times = [(r['diagnosis_s'], bool(r['scenario']['partition'])) for r in runs
                 if r['verdict']['outcome'] == 'correct' and r.get('diagnosis_s')]
        clean_times = [r['diagnosis_s'] for r in twins if r['verdict']['outcome'] == 'correct' and r.get('diagnosis_s')]
        columns.append((level, missions(runs)[:2], missions(twins)[:2], times, clean_times))
    return columns


def links_figure(records, path):
    columns = loss_columns(records)
    fig, (left, right) = plt.subplots(1, 2, figsize=SIZE)
    x = range(len(columns))
    for offset, index, colour, name in ((-0.2, 1, DRAWN, 'drawn link'), (0.2, 2, CLEAN, 'same runs, clean')):
        shares = [100.0 * c[index][0] / c[index][1] if c[index][1] else 0.0 for c in columns]
        bars = left.bar([k + offset for k in x], shares, width=0.4, color=colour, label=name)
        for bar, c in zip(bars, columns):
            left.annotate('%d/%d' % c[index], (bar.get_x() + bar.get_width() / 2, bar.get_height()),
                          ha='center', va='bottom', fontsize=7)
    left.axhline(100 * MISSION_GOAL, color='#555555', linestyle='--', linewidth=0.8)
    left.annotate('goal', (len(columns) - 0.5, 100 * MISSION_GOAL), ha='right', va='bottom', fontsize=7)
    left.set_ylim(0, 112)
    left.set_ylabel('missions completed (%)')
    left.set_title('missions completed, by loss')
    for k, c in enumerate(columns):
        plain = [t for t, cut in c[3] if not cut]
        cut = [t for t, is_cut in c[3] if is_cut]
        right.scatter([k - 0.15] * len(plain), plain, color=DRAWN, s=14)
        right.scatter([k - 0.15] * len(cut), cut, color=DRAWN, marker=CUT_MARK, s=20)
        right.scatter([k + 0.15] * len(c[4]), c[4], color=CLEAN, s=14)
    right.scatter([], [], color=DRAWN, marker=CUT_MARK, s=20, label='drawn, with a cut')
    right.set_ylabel('time to diagnosis (s, wall)')
    right.set_title('time to diagnosis (correct runs), by loss')
    for ax in (left, right):
        ax.set_xticks(list(x))
        ax.set_xticklabels(['%s loss' % c[0] for c in columns])
    left.legend(fontsize=7, loc='lower left')
    right.legend(fontsize=7, loc='upper left')
    fig.tight_layout()
    fig.savefig(path, dpi=DPI)
    plt.close(fig)
