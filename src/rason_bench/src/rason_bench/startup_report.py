"""The start-up part's goals and Markdown (pure: the ``startup`` dict of results.json in, text out)."""

#: Issue 35: a robot's rason_mas is reasoning within a second of its start, in 200 MB.
FIRST_CYCLE_GOAL_S = 1.0
RSS_GOAL_MB = 200.0


def goals(startup):
    """[(goal, measured, met)] of the start-up part (none if it did not run)."""
    runs = startup.get('runs')
    if not runs:
        return []
    span = '%d starts, %.2f–%.2f s' % (len(runs), min(r['to_first_cycle_s'] for r in runs),
                                        max(r['to_first_cycle_s'] for r in runs))
    return [('start-up of a one-agent rason_mas to its first reasoning cycle, median <= %g s' % FIRST_CYCLE_GOAL_S,
             '%.2f s (%s; CPU %.2f s)' % (startup['to_first_cycle_s'], span, startup.get('cpu_s', float('nan'))),
             startup['to_first_cycle_s'] <= FIRST_CYCLE_GOAL_S),
            ('RSS of a one-agent rason_mas, peak after start-up, median <= %g MB' % RSS_GOAL_MB,
             '%.0f MB (RSS when asked: %.0f MB)' % (startup['rss_peak_mb'], startup['rss_mb']),
             startup['rss_peak_mb'] <= RSS_GOAL_MB)]


def text(startup):
    """The section of report.md: one row per start."""
    lines = ['From starting the `rason_mas` process (its script, not `rosrun`) with one agent '
             '(`agents/startup.asl`) to the agent\'s first reasoning cycle (it reads the monotonic clock '
             'there), and the CPU time (user + sys) and RSS of the process when the harness then asks, and its '
             'peak RSS. %s.'
             % (startup.get('cds') or 'The node logged no class-data sharing line'), '',
             '| start | to the first cycle (s) | CPU (s) | RSS (MB) | RSS peak (MB) |', '|---|---|---|---|---|']
    for i, r in enumerate(startup.get('runs', []), 1):
        lines.append('| %d | %.2f | %.2f | %.0f | %.0f |' % (i, r['to_first_cycle_s'], r.get('cpu_s', float('nan')),
                                                         r['rss_mb'], r['rss_peak_mb']))
    return '\n'.join(lines) + '\n'
