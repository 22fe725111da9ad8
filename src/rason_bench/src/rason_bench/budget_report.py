"""The budget part's goals and Markdown (pure: the ``budget`` dict of results.json in, text out)."""

#: Issue 35: a robot's Rason on half a core of a small computer, and its memory.
CPU_GOAL_CORES = 0.5
MAS_RSS_GOAL_MB = 200.0
ROBOT_RSS_GOAL_MB = 512.0


def _free_runs(budget):
    return [r for r in budget.get('runs', []) if r['quota_cores'] is None]


def _held_runs(budget):
    return [r for r in budget.get('runs', []) if r['quota_cores'] is not None]


def _per_robot(runs, value, fmt):
    return '; '.join('%s: %s' % (run['fault'], ', '.join('%s %s' % (robot, fmt % value(r))
                                                       for robot, r in sorted(run['robots'].items())))
                     for run in runs)


def _mas_rss(r):
    return max([p['rss_peak_mb'] for p in r['processes'] if p['name'] == 'rason_mas'] or [0.0])


def goals(budget):
    """[(goal, measured, met)] of the budget part (none if it did not run)."""
    free, held = _free_runs(budget), _held_runs(budget)
    out = []
    if free:
        windows = 'p95 over %g s windows while running (after the first %g s, until a node ends)' % (
            free[0]['interval_s'], _start_up_s(budget))
        for key, what in (('cpu_mean_cores', 'mean'), ('cpu_p95_running_cores', windows)):
            out.append(('robot budget: each robot\'s CPU in the case study (no quota), %s <= %g core' % (what, CPU_GOAL_CORES),
                        _per_robot(free, lambda r: r[key], '%.2f'),
                        all(r[key] <= CPU_GOAL_CORES for run in free for r in run['robots'].values())))
        out.append(('robot budget: each robot\'s rason_mas RSS peak <= %g MB' % MAS_RSS_GOAL_MB,
                    _per_robot(free, _mas_rss, '%.0f MB'),
                    all(_mas_rss(r) <= MAS_RSS_GOAL_MB for run in free for r in run['robots'].values())))
        out.append(('robot budget: each robot\'s processes together, RSS peak <= %g MB' % ROBOT_RSS_GOAL_MB,
                    _per_robot(free, lambda r: r['rss_total_peak_mb'], '%.0f MB'),
                    all(r['rss_total_peak_mb'] <= ROBOT_RSS_GOAL_MB for run in free for r in run['robots'].values())))
    if held:
        cores = held[0]['quota_cores']
        out.append(('robot budget: the case study diagnoses right with each robot held to %g core' % cores,
                    '; '.join('%s: %s (%s)' % (r['fault'], r['outcome'], r['component']) for r in held),
                    all(r['outcome'] == 'correct' for r in held)))
    return out


def _start_up_s(budget):
    runs = budget.get('runs') or [{'robots': {}}]
    return next(iter(runs[0]['robots'].values()), {}).get('start_up_s', 0)


def _row(cells):
    return '| ' + ' | '.join(cells) + ' |'


def _quota(cores):
    return 'none' if cores is None else '%g core' % cores


def runs_table(budget):
    lines = [_row(['fault', 'quota', 'diagnosis', 'scenario s (simulated)', 'wall s', 'robot', 'CPU mean', 'p95',
                   'p95 running', 'max', 'CPU s', 'throttled periods', 'RSS peak, all its processes']),
             _row(['---'] * 13)]
    for run in budget['runs']:
        for robot, r in sorted(run['robots'].items()):
            t = r.get('throttling') or {}
            lines.append(_row([run['fault'], _quota(run['quota_cores']),
                               '%s (%s)' % (run['outcome'], run['component']),
                               '%.1f' % run['steps_s']['total'] if run['steps_s'].get('total') is not None else '–',
                               '%.0f' % run['wall_s'] if run['wall_s'] is not None else '–', robot,
                               '%.2f' % r['cpu_mean_cores'], '%.2f' % r['cpu_p95_cores'],
                               '%.2f' % r['cpu_p95_running_cores'] if r.get('cpu_p95_running_cores')
                               is not None else '–', '%.2f' % r['cpu_max_cores'],
                               '%.1f' % r['cpu_s'],
                               '%d of %d (%.1f s)' % (t.get('throttled_periods', 0), t.get('periods', 0),
                                                      t.get('throttled_s', 0.0)),
                               '%.0f MB' % r['rss_total_peak_mb']]))
    return '\n'.join(lines) + '\n'


def processes_table(free, held):
    """Per process of each robot (and outside every group): CPU and RSS peak without a quota
    and (if measured) on the quota, for one fault."""
    def index(run):
        rows = {}
        for robot, r in run['robots'].items():
            for p in r['processes']:
                rows[(robot, p['name'])] = p
        for p in (run.get('outside') or {}).get('processes', []):
            if p['name']:
                rows[('outside', p['name'])] = p
        return rows
    a, b = index(free), index(held) if held else {}
    lines = [_row(['robot', 'process', 'CPU s', 'core (mean)', 'RSS peak MB', 'CPU s on %s' % _quota(held['quota_cores'])
                   if held else 'on a quota']), _row(['---'] * 6)]
    order = sorted(a, key=lambda k: (k[0] == 'outside', k[0], -a[k]['cpu_s']))
    for key in order:
        p = a[key]
        lines.append(_row([key[0], p['name'], '%.2f' % p['cpu_s'],
                           '%.3f' % p['cpu_mean_cores'] if p['cpu_mean_cores'] is not None else '–',
                           '%.0f' % p['rss_peak_mb'], '%.2f' % b[key]['cpu_s'] if key in b else '–']))
    return '\n'.join(lines) + '\n'


def text(budget):
    out = ['`faulty_helper.launch budget:=true` at real-time factor 1, lockstep off (a campaign run on a master of its '
           'own, nominal poses): each robot\'s nodes start through `in_budget ROBOT` in a CPU cgroup of their own; the '
           'simulator, master, rosout and the bag recorder run outside every group. Each fault once with no quota (what '
           'a robot takes) and once with each robot held to %g core. CPU from the group\'s `cpuacct.usage`: mean over '
           'the run (from the launch\'s start to its end), p95 and max over %g s windows; per process from '
           '`/proc/PID/stat`; RSS from `/proc/PID/status` (peak: `VmHWM`). rason_mas runs with a robot\'s JVM options '
           '(`rason_bridge.jvm`), not the campaign\'s for short runs.' % (budget['quota_cores'],
                                                                         budget['runs'][0]['interval_s']
                                                                         if budget['runs'] else 0.5), '',
           runs_table(budget), '"scenario s": the case study\'s own steps, fault detection to diagnosis, in simulated '
           'seconds (rason_campaign.steps); the wall time adds the start-up and shut-down. "p95 running": over the '
           'windows after the first %g s (the JVMs\' and nodes\' start-up) and before the first node of a robot ends '
           '(Faulty\'s agents stop after the diagnosis, then the launch shuts down). CPU over one run: '
           '[budget.png](budget.png).' % _start_up_s(budget), '',
           'In the case study both robots share one ROS master; a robot on its own computer would also run its own '
           '`rosmaster` and `rosout` (the "outside" rows: about 1 s of CPU and 60 MB in a run).', '']
    free, held = _free_runs(budget), _held_runs(budget)
    if free:
        first = free[0]
        same = [r for r in held if r['fault'] == first['fault']]
        out += ['Per process, %s:' % first['fault'], '', processes_table(first, same[0] if same else None)]
    return '\n'.join(out)
