"""The PNG plots of report.md (matplotlib, no display)."""
import matplotlib

matplotlib.use('Agg')
import matplotlib.pyplot as plt  # noqa: E402

from rason_bench import report, thesis  # noqa: E402

_DPI = 80


def cycle_plot(cycle, path):
    """Slowdown (ms / baseline) against publishing rate, ours solid, the thesis's dashed
    (relative to its 1 perception x 1 Hz cell), one panel per mode."""
    modes = [m for m in ('accumulate', 'per_source') if m in cycle]
    fig, axes = plt.subplots(1, len(modes), figsize=(5 * len(modes), 3.6), sharey=True, squeeze=False)
    for ax, mode in zip(axes[0], modes):
        table = thesis.TABLES[mode]
        for i, p in enumerate(sorted({c['perceptions'] for c in cycle[mode]['cells']})):
            cells = sorted((c for c in cycle[mode]['cells'] if c['perceptions'] == p), key=lambda c: c['rate_hz'])
            colour = 'C%d' % i
            ax.plot([c['rate_hz'] for c in cells], [report.slowdown(c) for c in cells], 'o-', color=colour,
                    label='%d perceptions' % p)
            ax.plot(thesis.RATES_HZ, [v / table[1][0] for v in table[p]], '--', color=colour, alpha=0.5)
        ax.axhline(report.CYCLE_RATIO_GOAL, color='grey', lw=0.8, ls=':')
        ax.set_title('%s (thesis Table %s dashed)' % (mode, '5.1' if mode == 'accumulate' else '5.2'))
        ax.set_xlabel('publishing rate (Hz)')
        ax.set_yscale('log')
        ax.grid(alpha=0.3)
    axes[0][0].set_ylabel('cycle time / baseline')
    axes[0][0].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=_DPI)
    plt.close(fig)


def latency_plot(latency, path):
    """Cumulative distributions of the latency samples."""
    fig, axes = plt.subplots(1, 2, figsize=(9, 3.4))
    for ax, key, title, goal in ((axes[0], 'action_round_trip_samples', 'action round trip', report.RTT_P50_GOAL_MS),
                                 (axes[1], 'perception_to_belief_samples', 'perception → belief',
                                  report.SEEN_P50_GOAL_MS)):
        for load, style in (('idle', '-'), ('burst', '--')):
            samples = sorted(latency.get(load, {}).get(key, []))
            if samples:
                ax.plot(samples, [(i + 1) / len(samples) for i in range(len(samples))], style, label=load)
        ax.axvline(goal, color='grey', lw=0.8, ls=':')
        ax.set_xscale('log')
        ax.set_xlabel('ms')
        ax.set_title(title)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
    axes[0].set_ylabel('fraction')
    fig.tight_layout()
    fig.savefig(path, dpi=_DPI)
    plt.close(fig)


def scale_plot(rows, path):
    fig, axes = plt.subplots(1, 3, figsize=(11, 3.2))
    n = [r['agents'] for r in rows]
    axes[0].plot(n, [r['ms'] for r in rows], 'o-', label='10 perceptions x 10 Hz')
    axes[0].plot(n, [r['baseline_ms'] for r in rows], 'o--', label='no traffic')
    axes[0].set_ylabel('ms per cycle (one agent)')
    axes[0].legend(fontsize=8)
    axes[1].plot(n, [r['cpu_percent'] for r in rows], 'o-', label='10 perceptions x 10 Hz')
    axes[1].plot(n, [r['idle_cpu_percent'] for r in rows], 'o--', label='no traffic')
    axes[1].set_ylabel('node CPU (% of one core)')
    axes[1].legend(fontsize=8)
    axes[2].plot(n, [r['rss_mb'] for r in rows], 'o-')
    axes[2].set_ylabel('node RSS (MB)')
    for ax in axes:
        ax.set_xscale('log')
        ax.set_xlabel('agents in the process')
        ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(path, dpi=_DPI)
    plt.close(fig)




def reaction_plot(reaction, path):
    """Cumulative distributions of perception -> action, idle and under load."""
    fig, ax = plt.subplots(figsize=(5, 3.4))
    for load, style, label in (('idle', '-', 'idle'), ('load', '--', 'burst + busy intentions')):
        samples = sorted(reaction.get(load, {}).get('reaction_samples', []))
        if samples:
            ax.plot(samples, [(i + 1) / len(samples) for i in range(len(samples))], style, label=label)
    ax.axvline(report.REACTION_P99_GOAL_MS, color='grey', lw=0.8, ls=':')
    ax.set_xscale('log')
    ax.set_xlabel('ms')
    ax.set_ylabel('fraction')
    ax.set_title('perception → action')
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=_DPI)
    plt.close(fig)


def budget_plot(budget, path):
    """Each robot's CPU (cores, per sampling window) over one run of the first fault, without a
    quota and on it."""
    runs = [r for r in budget['runs'] if r['fault'] == budget['runs'][0]['fault']]
    fig, ax = plt.subplots(figsize=(8, 3.4))
    for i, robot in enumerate(sorted(runs[0]['robots'])):
        for run in runs:
            series = run['robots'][robot].get('cores_series') or []
            ax.plot([t for t, _ in series], [c for _, c in series], '-' if run['quota_cores'] is None else '--',
                    color='C%d' % i, label='%s, %s' % (robot, 'no quota' if run['quota_cores'] is None
                                                        else '%g core' % run['quota_cores']))
    ax.axhline(budget['quota_cores'], color='grey', lw=0.8, ls=':')
    ax.set_title('%s: CPU per robot' % runs[0]['fault'])
    ax.set_xlabel('s after the launch started')
    ax.set_ylabel('cores')
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=_DPI)
    plt.close(fig)
