"""The fleet campaign's report (issue 34): a row per fleet size and arm, the paired
comparison of the arms' times to diagnosis, the goals, and a row per run (no ROS).

A result is a RunSpec's dict plus :func:`rason_campaign.fleet_judge.judge_run`'s outcome and
the runner's wall, exit_code and timed_out.
"""
import csv
import io
import json

from rason_campaign import stats
from rason_campaign.fleet_plan import FLEET_ARMS

COMPLETION_GOAL = 0.95
ARM_NAMES = {'contract_net': 'contract net', 'broadcast': 'broadcast (first to offer)'}


def size_of(result):
    return len(result['args']['robots'].split())


def faulty_robots(result):
    return [r for r in result['robots'] if r['fault'] != 'none']


def diagnosis_times(results, since='time_to_diagnosis'):
    """Each faulty robot's time to diagnosis (``award_to_diagnosis``: from the award)."""
    return [r[since] for res in results for r in faulty_robots(res) if r[since] is not None]


def group_stats(results):
    """Counts and statistics of some runs (one size and arm, or all of an arm)."""
    n = len(results)
    completed = sum(bool(r['completed']) for r in results)
    low, high = stats.wilson(completed, n)
    faulty = [f for r in results for f in faulty_robots(r)]
    times = diagnosis_times(results)
    return {'runs': n, 'completed': completed, 'completion': completed / n if n else None,
            'completion_low': low, 'completion_high': high,
            'faulty': len(faulty), 'faulty_completed': sum(f['mission']['completed'] for f in faulty),
            'wrong': sum(r['wrong'] for r in results),
            'undiagnosed': sum(r['undiagnosed'] for r in results),
            'diagnosis_median': stats.median(times), 'diagnosis_p90': stats.percentile(times, 90),
            'award_median': stats.median(diagnosis_times(results, 'award_to_diagnosis')),
            'messages_median': stats.median([r['messages'] for r in results]),
            'wall_median': stats.median([r['wall'] for r in results])}


def summary(results):
    """A row per (size, arm), sizes in plan order, then one per arm over every size."""
    rows = []
    sizes = []
    for r in results:
        if size_of(r) not in sizes:
            sizes.append(size_of(r))
    for size in sizes + [None]:
        for arm in FLEET_ARMS:
            group = [r for r in results if r['arm'] == arm and size in (None, size_of(r))]
            if group:
                rows.append(dict(group_stats(group), size=size, arm=arm))
    return rows


def _both_arms(results):
    """{(run number, faulty robot): {arm: that robot's result}} where both arms were made."""
    by_run = {}
    for r in results:
        for f in faulty_robots(r):
            by_run.setdefault((r['number'], f['robot']), {})[r['arm']] = f
    return {k: v for k, v in sorted(by_run.items()) if len(v) == len(FLEET_ARMS)}


def paired(results, since='time_to_diagnosis'):
    """Per run (number), each faulty robot's time to diagnosis in both arms:
    [(number, robot, contract net s, broadcast s)] where both were diagnosed."""
    pairs = []
    for (number, robot), arms in _both_arms(results).items():
        cn, bc = arms['contract_net'][since], arms['broadcast'][since]
        if cn is not None and bc is not None:
            pairs.append((number, robot, cn, bc))
    return pairs


def other_watcher(results):
    """The (run number, faulty robot) whose first watcher the two arms chose differently."""
    return [k for k, arms in _both_arms(results).items()
            if arms['contract_net']['helpers'][:1] != arms['broadcast']['helpers'][:1]]


def by_fault(results):
    """A row per fault of the faulty robots: in each arm their count, missions completed and
    the medians of both times to diagnosis."""
    rows = []
    faults = sorted({f['fault'] for r in results for f in faulty_robots(r)})
    for fault in faults:
        row = {'fault': fault}
        for arm in FLEET_ARMS:
            robots = [f for r in results if r['arm'] == arm for f in faulty_robots(r) if f['fault'] == fault]
            row[arm] = {'robots': len(robots),
                        'completed': sum(f['mission']['completed'] for f in robots),
                        'call_median': stats.median([f['time_to_diagnosis'] for f in robots]),
                        'award_median': stats.median([f['award_to_diagnosis'] for f in robots])}
        rows.append(row)
    return rows


def by_fault_table(rows):
    lines = ['| fault | faulty robots (contract net / broadcast) | their missions completed | call to '
             'diagnosis, median (s) | award to diagnosis, median (s) |', '|---|---|---|---|---|']
    for row in rows:
        cn, bc = row['contract_net'], row['broadcast']
        lines.append('| %s | %d / %d | %d / %d | %s / %s | %s / %s |' % (
            row['fault'], cn['robots'], bc['robots'], cn['completed'], bc['completed'],
            _s(cn['call_median']), _s(bc['call_median']), _s(cn['award_median']), _s(bc['award_median'])))
    return '\n'.join(lines)


def goals(results):
    """The issue's campaign goals: [(text, met, measured)]."""
    n = len(results)
    completed = sum(bool(r['completed']) for r in results)
    wrong = sum(r['wrong'] for r in results)
    sizes = sorted({size_of(r) for r in results})
    return [('at least 100 runs, N = 4 and 6', n >= 100 and {4, 6} <= set(sizes),
             '%d runs, N = %s' % (n, ', '.join(map(str, sizes)))),
            ('missions completed >= 95 %', n > 0 and completed / n >= COMPLETION_GOAL,
             '%d of %d (%s)' % (completed, n, _pct(completed / n if n else None))),
            ('0 wrong diagnoses', wrong == 0, '%d' % wrong)]


def _pct(x):
    return '–' if x is None else '%.0f %%' % (100 * x)


def _s(x):
    return '–' if x is None else '%.1f' % x


def summary_table(rows):
    lines = ['| N | helpers chosen by | runs | every mission completed (95 % interval) | '
             'faulty robots\' missions | wrong diagnoses | undiagnosed | call to diagnosis '
             'median / p90 (s) | award to diagnosis median (s) | messages a run (median) | '
             'wall a run (median, s) |',
             '|---|---|---|---|---|---|---|---|---|---|---|']
    for r in rows:
        lines.append('| %s | %s | %d | %d (%s, %s–%s) | %d of %d | %d | %d | %s / %s | %s | %s | %s |' % (
            r['size'] if r['size'] is not None else 'all', ARM_NAMES[r['arm']], r['runs'],
            r['completed'], _pct(r['completion']), _pct(r['completion_low']),
            _pct(r['completion_high']), r['faulty_completed'], r['faulty'], r['wrong'],
            r['undiagnosed'], _s(r['diagnosis_median']), _s(r['diagnosis_p90']),
            _s(r['award_median']), _s(r['messages_median']), _s(r['wall_median'])))
    return '\n'.join(lines)


def runs_table(results):
    lines = ['| run | N | arm | faults | every mission | time to diagnosis (s) | helpers | '
             'messages | wall (s) | why |', '|---|---|---|---|---|---|---|---|---|---|']
    for r in results:
        faulty = faulty_robots(r)
        lines.append('| %d | %d | %s | %s | %s | %s | %s | %d | %s | %s |' % (
            r['number'], size_of(r), r['arm'], r['args']['faults'],
            'yes' if r['completed'] else 'no',
            ', '.join('%s %s' % (f['robot'], _s(f['time_to_diagnosis'])) for f in faulty),
            ', '.join('%s: %s' % (f['robot'], '→'.join(f['helpers']) or '–') for f in faulty),
            r['messages'], _s(r['wall']), r['reason'].replace('|', '/')))
    return '\n'.join(lines)


def markdown(meta, results, figures):
    rows = summary(results)
    pairs = paired(results)
    faster = sum(1 for _, _, cn, bc in pairs if cn < bc)
    differences = [bc - cn for _, _, cn, bc in pairs]
    out = ['# Fleet campaign: contract net against broadcast', '',
           '`%s` (%s; runs per fleet size: %s; seed %s)' % (
               meta.get('command', 'campaign'), meta.get('date', ''), meta.get('runs'),
               meta.get('seed')), '',
           'Every run in both arms with the same seed, start poses and faults; a run counts as '
           'completed when every robot\'s mission was claimed completed by its agent and '
           'confirmed by the simulator\'s true poses. Time to diagnosis: from a faulty robot\'s '
           'first call for a watcher to its diagnosis, simulated seconds (it includes waiting '
           'for a robot free to watch: one whose own mission ended); award to diagnosis: from '
           'the award of the help, which is what the choice of watcher decides.', '',
           summary_table(rows), '']
    if meta.get('planned', len(results)) > len(results):
        out[4:4] = ['**Made so far: %d of the plan\'s %d runs** (go on with `--resume`).'
                    % (len(results), meta['planned']), '']
    if pairs:
        chosen = other_watcher(results)
        apart = [(cn, bc) for number, robot, cn, bc in paired(results, 'award_to_diagnosis')
                 if (number, robot) in chosen]
        out += ['Paired by run and faulty robot (%d pairs): contract net diagnosed sooner in %d; '
                'broadcast minus contract net, median %s s, p10 %s s, p90 %s s.' % (
                    len(pairs), faster, _s(stats.median(differences)),
                    _s(stats.percentile(differences, 10)), _s(stats.percentile(differences, 90))),
                '',
                'The arms chose a different first watcher for %d of these %d faulty robots (for the '
                'others both chose the same robot, often the only one free to watch)%s.' % (
                    len(chosen), len(pairs),
                    '; for those, award to diagnosis median %s s by contract net, %s s by broadcast'
                    % (_s(stats.median([cn for cn, _ in apart])), _s(stats.median([bc for _, bc in apart])))
                    if apart else ''),
                '', by_fault_table(by_fault(results)), '']
    out += ['| goal | met | measured |', '|---|---|---|']
    out += ['| %s | %s | %s |' % (text, 'yes' if met else 'no', measured)
            for text, met, measured in goals(results)]
    out += ['']
    out += ['![%s](%s)' % (name, name) for name in figures]
    out += ['', '## Runs', '', runs_table(results), '']
    return '\n'.join(out)


def results_json(meta, results):
    return json.dumps({'meta': meta, 'summary': summary(results), 'goals': goals(results),
                       'runs': results}, indent=1, sort_keys=True)


def runs_csv(results):
    f = io.StringIO()
    w = csv.writer(f)
    w.writerow(['number', 'size', 'arm', 'seed', 'robot', 'fault', 'diagnosis', 'outcome',
                'time_to_diagnosis', 'helpers', 'mission_completed', 'recovery', 'goal_error',
                'start_error', 'messages', 'wall'])
    for r in results:
        for robot in r['robots']:
            m = robot['mission']
            w.writerow([r['number'], size_of(r), r['arm'], r['seed'], robot['robot'],
                        robot['fault'], robot['diagnosis'], robot['diagnosis_outcome'],
                        robot['time_to_diagnosis'], ' '.join(robot['helpers']),
                        m['completed'], m['recovery'], m['goal_error'], m['start_error'],
                        r['messages'], r['wall']])
    return f.getvalue()
