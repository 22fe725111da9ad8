"""The fault-tolerance campaign's statistics, acceptance goals, Markdown report and
CSV/JSON results (issue 15; no ROS).

A result is a dict per run: the RunSpec's (number, fault, seed, args, arm), the
MissionOutcome's fields (completed, by, recovery, diagnosis, diagnosis_outcome, time,
goal_error, start_error, reason, ...) and the runner's (wall, exit_code, timed_out).
"""
import csv
import io
import json

from rason_campaign import stats
from rason_campaign.mission import MISSION_LENGTH, TOLERANCE
from rason_campaign.plan import ARMS, FAULTS
from rason_campaign.report import DASH, MARKERS, confusion_table, fmt, percent, table

TARGET_RECOVERY = 0.95      # completion rate every fault must reach with recovery
TARGET_BASELINE = 0.0       # completion rate of the baseline under the four faults
TARGET_RUNS = 10            # seeded runs per fault (and arm)

SUMMARY_COLUMNS = ('fault', 'arm', 'runs', 'completed', 'rate', 'ci_low', 'ci_high',
                   'claimed', 'wrong', 'undiagnosed', 'time_median', 'time_p90',
                   'time_vs_none', 'time_ratio_none', 'goal_error_median', 'goal_error_max')
RUN_COLUMNS = ('number', 'seed', 'fault', 'arm', 'diagnosis', 'diagnosis_outcome', 'recovery',
               'by', 'claimed', 'completed', 'time', 'goal_error', 'start_error', 'wall',
               'reason')


def groups(results):
    """(fault, arm) -> its results; faults in the order they first appear, arms as ARMS."""
    faults = []
    for r in results:
        if r['fault'] not in faults:
            faults.append(r['fault'])
    out = {}
    for fault in faults:
        for arm in ARMS:
            rs = [r for r in results if r['fault'] == fault and r['arm'] == arm]
            if rs:
                out[(fault, arm)] = rs
    return out


def group_stats(rs):
    """Counts, completion rate with its 95 % Wilson interval, times of the completed runs
    and goal errors of the runs whose agents said they completed the mission."""
    n = len(rs)
    done = sum(1 for r in rs if r['completed'])
    low, high = stats.wilson(done, n)
    times = [r['time'] for r in rs if r['completed']]
    goal_errors = [r['goal_error'] for r in rs if r['claimed'] and r['goal_error'] is not None]
    return {'runs': n, 'completed': done, 'rate': done / n if n else None,
            'ci_low': low, 'ci_high': high,
            'claimed': sum(1 for r in rs if r['claimed']),
            'wrong': sum(1 for r in rs if r['diagnosis_outcome'] == 'wrong'),
            'undiagnosed': sum(1 for r in rs if r['diagnosis_outcome'] == 'undiagnosed'),
            'time_median': stats.median(times), 'time_p90': stats.percentile(times, 90),
            'goal_error_median': stats.median(goal_errors),
            'goal_error_max': max(goal_errors) if goal_errors else None}


def summary(results):
    """A row per (fault, arm): group_stats plus the median time against the same arm's
    fault-free (``none``) runs (difference in seconds and ratio).

    :rtype: list of dict with SUMMARY_COLUMNS
    """
    rows = []
    for (fault, arm), rs in groups(results).items():
        row = {'fault': fault, 'arm': arm}
        row.update(group_stats(rs))
        rows.append(row)
    reference = {r['arm']: r['time_median'] for r in rows if r['fault'] == 'none'}
    for row in rows:
        ref = reference.get(row['arm'])
        if ref is not None and row['time_median'] is not None:
            row['time_vs_none'] = row['time_median'] - ref
            row['time_ratio_none'] = row['time_median'] / ref if ref > 0 else None
        else:
            row['time_vs_none'] = row['time_ratio_none'] = None
    return rows


def _goal(text, met, detail):
    return {'goal': text, 'met': met, 'detail': detail}


def _rates(by, faults, arm, missing):
    """'none 10/10, left_actuator 9/10; not run: odometry'."""
    parts = [', '.join('%s %d/%d' % (f, by[(f, arm)]['completed'], by[(f, arm)]['runs'])
                       for f in faults if (f, arm) in by)]
    if missing:
        parts.append('not run: %s' % ', '.join(missing))
    return '; '.join(p for p in parts if p)


def goals(results, rows=None):
    """The issue's acceptance goals and whether this campaign meets them; a fault that was
    not run leaves its goal not met.

    :rtype: list of dict goal, met (bool), detail
    """
    rows = summary(results) if rows is None else rows
    by = {(r['fault'], r['arm']): r for r in rows}
    out = []

    missing = [f for f in FAULTS if (f, 'recovery') not in by]
    low = [f for f in FAULTS if (f, 'recovery') in by
           and by[(f, 'recovery')]['rate'] < TARGET_RECOVERY]
    out.append(_goal('completion ≥ %.0f %% for every fault with recovery'
                     % (100 * TARGET_RECOVERY),
                     not missing and not low, _rates(by, FAULTS, 'recovery', missing)))

    faults = [f for f in FAULTS if f != 'none']
    missing = [f for f in faults if (f, 'baseline') not in by]
    high = [f for f in faults if (f, 'baseline') in by
            and by[(f, 'baseline')]['rate'] > TARGET_BASELINE]
    out.append(_goal('baseline (thesis behaviour) completes 0 % under the four faults',
                     not missing and not high, _rates(by, faults, 'baseline', missing)))

    wrong = [r for r in results if r['diagnosis_outcome'] == 'wrong']
    out.append(_goal('0 wrong diagnoses (false positives included)', not wrong,
                     '%d wrong of %d runs%s' % (len(wrong), len(results), ''.join(
                         '; run %d %s: %s' % (r['number'], r['arm'], r['diagnosis'])
                         for r in wrong))))

    few = ['%s %s: %d' % (f, a, by[(f, a)]['runs']) for f in FAULTS for a in ARMS
           if (f, a) in by and by[(f, a)]['runs'] < TARGET_RUNS]
    missing = ['%s %s' % (f, a) for f in FAULTS for a in ARMS if (f, a) not in by]
    out.append(_goal('≥ %d seeded runs per fault and arm' % TARGET_RUNS, not few and not missing,
                     '; '.join(few + (['not run: %s' % ', '.join(missing)] if missing else []))
                     or 'all'))
    return out


def _vs_none(row):
    if row['time_vs_none'] is None:
        return DASH
    ratio = '' if row['time_ratio_none'] is None else ' (×%.2f)' % row['time_ratio_none']
    return '%+.1f%s' % (row['time_vs_none'], ratio)


def summary_table(rows):
    """Markdown lines: a row per fault and arm."""
    header = ['Fault', 'Arm', 'Runs', 'Completed', 'Rate (95 % CI)', 'Wrong diagnoses',
              'Median time (s)', 'p90 time (s)', 'vs none (s)', 'Median goal error (m)',
              'Max goal error (m)']
    body = []
    for r in rows:
        ci = DASH if r['ci_low'] is None else '%s–%s' % (percent(r['ci_low']), percent(r['ci_high']))
        body.append([r['fault'], r['arm'], r['runs'], r['completed'],
                     '%s (%s)' % (percent(r['rate']), ci), r['wrong'],
                     fmt(r['time_median'], 1), fmt(r['time_p90'], 1), _vs_none(r),
                     fmt(r['goal_error_median'], 3), fmt(r['goal_error_max'], 3)])
    return table(header, body)


def goals_table(goal_list):
    return table(['Acceptance goal', 'Met', 'Measured'],
                  [[g['goal'], 'yes' if g['met'] else '**no**', g['detail']] for g in goal_list])


def runs_table(results):
    """Markdown lines: a row per run."""
    header = ['Run', 'Seed', 'Fault', 'Arm', 'Diagnosis', 'Recovery', 'By', 'Completed',
              'Time (s)', 'Goal error (m)', 'Start error (m)', 'Note']
    body = []
    for r in results:
        outcome = '' if r['diagnosis_outcome'] == 'correct' else ' (%s)' % r['diagnosis_outcome']
        note = '' if r['completed'] and not r.get('timed_out') else r['reason']
        body.append([r['number'], r['seed'], r['fault'], r['arm'],
                     (r['diagnosis'] or DASH) + outcome, r['recovery'] or DASH,
                     ','.join(r['by']) or DASH, 'yes' if r['completed'] else 'no',
                     fmt(r['time'], 1), fmt(r['goal_error'], 3), fmt(r['start_error'], 3), note])
    return table(header, body)


def markdown(meta, results, figures):
    """The whole report.

    :param meta: dict with 'command', 'date', 'runs', 'seed', 'rate', 'fault_at', 'interaction'
    :param figures: figure name ('completion', 'times') -> file name relative to the report;
        missing ones are left out
    :rtype: str
    """
    rows = summary(results)
    goal_list = goals(results, rows)
    when = ('at the start' if not meta.get('fault_at') else
            '%s s after Faulty first moves (mid-mission)' % meta['fault_at'])
    lines = ['# Fault-tolerance campaign', '',
             'Command: `%s`  ' % meta['command'],
             'Date: %s; %d run(s) per fault, each in both arms with the same seed and start '
             'poses; seed %s, real-time factor %s, fault injected %s, interaction fault: %s%s.'
             % (meta['date'], meta['runs'], meta['seed'], meta['rate'], when,
                meta.get('interaction', 'none'), MARKERS[bool(meta.get('third_marker'))]),
             '',
             'Arms: *recovery* = `fault_tolerance.launch` (diagnosis, then recovery); '
             '*baseline* = `faulty_helper.launch` with the same arguments (the thesis\'s '
             'behaviour: diagnose and stop). Start poses are random per seed: Helper–Faulty '
             '1.2–2.2 m, Faulty facing away from Helper within ±25°, Helper\'s heading '
             'anywhere.',
             '',
             'Times are simulated seconds (the recorded /clock), from Faulty\'s first `move` to '
             'the `rason/mission` status (baseline: to its diagnosis when it ends its mission '
             'normally, `none` without asking for help; after any other diagnosis it stops, '
             'not completed). Goal = %.0f m ahead of Faulty\'s true start pose; goal error = '
             'the completing robot\'s smallest true distance to it; start error = Faulty\'s '
             'true distance from its start at the end. A run is *completed* when the agents '
             'say so and the goal error (and, when Faulty completed it, the start error) is '
             '≤ %.2f m. Rates with a 95 %% Wilson interval; times over the completed runs; '
             '"vs none" = median time − the same arm\'s fault-free median (and the ratio); goal '
             'errors over the runs whose agents said completed. A wrong diagnosis names '
             'another component than the injected one (a false positive, `none` under a '
             'fault, included).' % (MISSION_LENGTH, TOLERANCE),
             '', '## Acceptance goals', '']
    lines += goals_table(goal_list)
    lines += ['', 'All goals met: %s.' % ('yes' if all(g['met'] for g in goal_list) else 'no'),
              '', '## Summary', '']
    lines += summary_table(rows)
    lines.append('')
    for name, title in (('completion', 'Completion rate per fault'),
                        ('times', 'Time to completion per fault')):
        if name in figures:
            lines += ['![%s](%s)' % (title, figures[name]), '']
    lines += ['## Diagnoses', '',
              'Runs of both arms per injected fault (rows) and diagnosis (columns); the correct '
              'rate with its Wilson 95 % interval.', '']
    lines += confusion_table(results, key='diagnosis')
    lines += ['', '## Runs', '']
    lines += runs_table(results)
    lines.append('')
    return '\n'.join(lines)


def results_json(meta, results):
    """Everything as one JSON text: meta, goals, summary rows and runs."""
    rows = summary(results)
    data = {'meta': meta, 'goals': goals(results, rows), 'summary': rows, 'runs': results}
    return json.dumps(data, indent=1, ensure_ascii=False)


def _csv(columns, rows):
    out = io.StringIO()
    writer = csv.writer(out, lineterminator='\n')
    writer.writerow(columns)
    for row in rows:
        writer.writerow(['' if row.get(c) is None else
                         (','.join(row[c]) if isinstance(row[c], list) else row[c])
                         for c in columns])
    return out.getvalue()


def summary_csv(results):
    """A CSV line per fault and arm (SUMMARY_COLUMNS; empty cells where not measured)."""
    return _csv(SUMMARY_COLUMNS, summary(results))


def runs_csv(results):
    """A CSV line per run (RUN_COLUMNS)."""
    return _csv(RUN_COLUMNS, results)
