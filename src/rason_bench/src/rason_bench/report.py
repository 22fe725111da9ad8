"""Turning measurements into verdicts and Markdown (pure: dicts in, text out)."""
from rason_bench import stats, thesis

#: The issue's goals.
CYCLE_RATIO_GOAL = 1.2
RTT_P50_GOAL_MS = 2.0
RTT_P99_GOAL_MS = 10.0
SEEN_P50_GOAL_MS = 5.0
#: Take-back -> zero twist on cmd_vel: one 50 Hz control period (20 ms) plus transport.
PREEMPT_P99_GOAL_MS = 60.0


def baseline_ms(mode_result):
    """Median ms per iteration of a mode's baseline runs."""
    return stats.median([c['baseline_ms'] for c in mode_result['cells']])


def slowdown(c):
    """A cell's ms over its own baseline run's."""
    return stats.ratio(c['ms'], c['baseline_ms'])


def cpu_slowdown(c):
    """The node's CPU time per iteration in a cell over its baseline run's: what the traffic
    costs the process, whatever share of the cores other programs left it."""
    return stats.ratio(c['ms'] * c['cpu_percent'], c['baseline_ms'] * c['baseline_cpu_percent'])


def cell(mode_result, perceptions, rate_hz):
    for c in mode_result['cells']:
        if c['perceptions'] == perceptions and c['rate_hz'] == rate_hz:
            return c
    return None


def goals(results):
    """[(goal, measured text, met)] for the goals whose measurements are in results."""
    out = []
    per_source = results.get('cycle', {}).get('per_source')
    if per_source:
        c = cell(per_source, 10, 50)
        if c is not None:
            r = slowdown(c)
            out.append(('cycle time at 10 perceptions x 50 Hz <= %.1f x baseline (thesis: %.1f x)'
                        % (CYCLE_RATIO_GOAL, thesis.THESIS_SLOWDOWN),
                        '%.2f x (%.4f ms vs %.4f ms; node CPU time per iteration %.2f x)'
                        % (r, c['ms'], c['baseline_ms'], cpu_slowdown(c)),
                        r <= CYCLE_RATIO_GOAL))
    idle = results.get('latency', {}).get('idle')
    if idle:
        rtt = idle['action_round_trip_ms']
        seen = idle['perception_to_belief_ms']
        out.append(('action round trip p50 <= %g ms' % RTT_P50_GOAL_MS, '%.2f ms' % rtt['p50'],
                    rtt['p50'] <= RTT_P50_GOAL_MS))
        out.append(('action round trip p99 <= %g ms' % RTT_P99_GOAL_MS, '%.2f ms' % rtt['p99'],
                    rtt['p99'] <= RTT_P99_GOAL_MS))
        out.append(('perception -> belief p50 <= %g ms' % SEEN_P50_GOAL_MS, '%.2f ms' % seen['p50'],
                    seen['p50'] <= SEEN_P50_GOAL_MS))
    stop = results.get('preemption', {}).get('stop_ms')
    if stop:
        goal = ('preemption: take-back -> zero twist p99 <= %g ms (one 50 Hz control period plus transport)'
                % PREEMPT_P99_GOAL_MS)
        if stop['n']:
            out.append((goal, '%.2f ms (%d take-backs)' % (stop['p99'], stop['n']),
                        stop['p99'] <= PREEMPT_P99_GOAL_MS))
        else:
            out.append((goal, 'no take-back measured', False))
    return out


def _row(cells):
    return '| ' + ' | '.join(cells) + ' |'


def cycle_table(mode, mode_result):
    """Markdown: ms per iteration (ratio to its baseline run; thesis ms) per perceptions x rate."""
    rates = sorted({c['rate_hz'] for c in mode_result['cells']})
    counts = sorted({c['perceptions'] for c in mode_result['cells']})
    lines = [_row(['perceptions'] + ['%g Hz' % r for r in rates]),
             _row(['---'] * (len(rates) + 1))]
    for p in counts:
        row = ['%d' % p]
        for r in rates:
            c = cell(mode_result, p, r)
            if c is None:
                row.append('')
                continue
            t = thesis.thesis_ms(mode, p, r)
            row.append('%.4f (%.2f×; %s)' % (c['ms'], slowdown(c),
                                             '%.2f' % t if t is not None else '–'))
        lines.append(_row(row))
    lines += ['', 'Node CPU time per iteration, ratio to the baseline run:', '',
              _row(['perceptions'] + ['%g Hz' % r for r in rates]), _row(['---'] * (len(rates) + 1))]
    for p in counts:
        lines.append(_row(['%d' % p] + ['%.2f×' % cpu_slowdown(c) if c else ''
                                        for c in (cell(mode_result, p, r) for r in rates)]))
    base = [c['baseline_ms'] for c in mode_result['cells']]
    return '\n'.join(lines) + ('\n\nBaseline (no ROS traffic, same agent and JVM; per cell the mean of a run '
                               'right before and one right after it): median %.4f ms, min %.4f, max %.4f; %d iterations per run.\n'
                               % (stats.median(base), min(base), max(base), mode_result['iterations']))


def latency_table(latency):
    lines = [_row(['', 'n', 'p50 ms', 'p90 ms', 'p99 ms', 'max ms']), _row(['---'] * 6)]
    for load in ('idle', 'burst'):
        if load not in latency:
            continue
        for key, label in (('action_round_trip_ms', 'action round trip'),
                           ('perception_to_belief_ms', 'perception → belief')):
            s = latency[load][key]
            if not s['n']:
                lines.append(_row(['%s, %s' % (label, load), '0', '', '', '', '']))
                continue
            lines.append(_row(['%s, %s' % (label, load), '%d' % s['n']] +
                              ['%.2f' % s[k] for k in ('p50', 'p90', 'p99', 'max')]))
    return '\n'.join(lines) + '\n'


def scale_table(rows):
    lines = [_row(['agents', 'cycle ms (baseline)', 'node CPU % (no traffic)', 'RSS MB']),
             _row(['---'] * 4)]
    for r in rows:
        lines.append(_row(['%d' % r['agents'], '%.3f (%.3f)' % (r['ms'], r['baseline_ms']),
                           '%.0f (%.0f)' % (r['cpu_percent'], r['idle_cpu_percent']), '%.0f' % r['rss_mb']]))
    return '\n'.join(lines) + '\n'


#: The preemption part's rows: key of its results, label.
PREEMPTION_ROWS = (('stop_ms', 'take-back → zero twist on `cmd_vel`'),
                   ('cancel_ms', 'take-back → `.cancel` heard on `jason/action`'),
                   ('cancel_to_stop_ms', '`.cancel` heard → zero twist'))


def preemption_table(preemption):
    """Markdown: n, p50, p90, p99, max (ms) of each leg of the take-backs."""
    lines = [_row(['', 'n', 'p50 ms', 'p90 ms', 'p99 ms', 'max ms']), _row(['---'] * 6)]
    for key, label in PREEMPTION_ROWS:
        s = preemption.get(key, {'n': 0})
        if not s['n']:
            lines.append(_row([label, '0', '', '', '', '']))
            continue
        lines.append(_row([label, '%d' % s['n']] + ['%.2f' % s[k] for k in ('p50', 'p90', 'p99', 'max')]))
    return '\n'.join(lines) + '\n'


def goals_table(results):
    lines = [_row(['goal', 'measured', 'met']), _row(['---'] * 3)]
    for goal, measured, met in goals(results):
        lines.append(_row([goal, measured, 'met' if met else '**not met**']))
    return '\n'.join(lines) + '\n'


def markdown(results):
    """The whole report.md."""
    m = results['machine']
    out = ['# Rason benchmarks', '',
           'Written by `make bench` on %s. Machine: %d cores (%s), load average at start %s%s. '
           'Each cell: the median of 3 runs of about %g s under the burst. Times are per iteration of thesis Listing 5.4 '
           '(the thesis\'s "reasoning cycle time"); in brackets the ratio to the baseline (no ROS '
           'traffic, same agent, same JVM, runs right before and after the cell) and the thesis\'s value (1.8 GHz dual-core AMD64).'
           % (m['date'], m['cpus'], m['cpu_model'], ' / '.join('%.2f' % x for x in m['load_at_start']),
              '; the simulator campaign was running' if m.get('simulator_running') else '',
              results['params']['seconds']), '',
           '## Goals', '', goals_table(results)]
    cycle = results.get('cycle', {})
    titles = {'accumulate': 'Without filtering (`perception_manager=accumulate`; thesis Table 5.1)',
              'per_source': 'Per-source replacement (`perception_manager=per_source`, the default; thesis Table 5.2)'}
    for mode in ('accumulate', 'per_source'):
        if mode in cycle:
            out += ['## ' + titles[mode], '', cycle_table(mode, cycle[mode])]
    if 'latency' in results:
        out += ['## Latencies (loopback)', '',
                'Action round trip: `ping` act → the harness, a rospy decomposer, answers `OK` → '
                'the intention resumed (measured by the agent with `rason.time_ms`). Perception → '
                'belief: a percept stamped when published → the agent\'s plan for its `+` event '
                'chosen (same monotonic clock). "burst": while 10 perceptions × 50 Hz arrive.', '',
                latency_table(results['latency'])]
    if 'scale' in results:
        out += ['## Scale: agents in one process, each hearing 10 perceptions × 10 Hz', '',
                scale_table(results['scale'])]
    if 'preemption' in results:
        p = results['preemption']
        out += ['## Preemption latency (loopback)', '',
                'The agent (`agents/preempt.asl`) starts `move(3)`; once the motion is under way '
                '(a non-zero twist on `cmd_vel`, plus a random 0–%g ms) the harness asks it to take '
                'it back: it reads `rason.time_ms(T)` right before `.drop_intention`. Measured from T '
                '(same monotonic clock) to the harness hearing the zero twist of the real `motion_decomp` '
                'node (`~rate` %g Hz; a kinematic stand-in base, `bench_base`, integrates `cmd_vel` into '
                '`odom` at %g Hz) and the bridge\'s `.cancel` on `jason/action`. %d unrecorded warm-up '
                'take-backs first; %d motions ended before their take-back (not counted); %.0f s.'
                % (1000 * p['max_delay_s'], p['control_rate_hz'], p['base_rate_hz'], p['warmup'],
                   p['ended_early'], p['seconds']), '',
                preemption_table(p)]
    return '\n'.join(out)
