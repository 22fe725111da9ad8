"""The campaign's Markdown report and JSON results (no ROS)."""
import json

from rason_campaign import stats, thesis
from rason_campaign.steps import STEP_NAMES

STEP_TITLES = ('Fault detection (s)', 'Robot location (s)', 'Diagnosis (s)', 'Total (s)')
DASH = '—'


def fmt(value, digits=2):
    return DASH if value is None else '%.*f' % (digits, value)


def fmt_mean_sd(pair):
    mean, sd = pair
    if mean is None:
        return DASH
    return fmt(mean) if sd is None else '%s ± %s' % (fmt(mean), fmt(sd))


def _row(cells):
    return '| ' + ' | '.join(str(c) for c in cells) + ' |'


def table(header, rows):
    lines = [_row(header), _row(['---'] * len(header))]
    return lines + [_row(r) for r in rows]


def thesis_total(fault):
    """'22.42 ± 0.78 (7.1)' or a dash when the thesis has no runs of the fault."""
    if fault not in thesis.STATED_TOTAL:
        return DASH
    return '%s (Table %s)' % (fmt_mean_sd(thesis.STATED_TOTAL[fault]), thesis.TABLES[fault][0])


def summary_table(summary):
    """Markdown lines: one row per fault, counts and mean ± sd of each step beside the
    thesis's mean total."""
    header = ['Fault', 'Runs', 'Correct', 'Undiagnosed', 'Wrong'] + list(STEP_TITLES) + \
        ['Thesis total (s)']
    rows = []
    for fault, s in summary['faults'].items():
        c = s['counts']
        rows.append([fault, s['runs'], c['correct'], c['undiagnosed'], c['wrong']] +
                    [fmt_mean_sd(s['steps'][n]) for n in STEP_NAMES] + [thesis_total(fault)])
    c = summary['counts']
    rows.append(['**all**', summary['runs'], c['correct'], c['undiagnosed'], c['wrong']] +
                [''] * len(STEP_NAMES) + [''])
    return table(header, rows)


def percent(fraction):
    """'96 %', or a dash for None."""
    return DASH if fraction is None else '%.0f %%' % (100 * fraction)


def percent_interval(successes, n):
    """'96 % (86 %–99 %)': the rate and its Wilson 95 % interval, or a dash for no runs."""
    low, high = stats.wilson(successes, n)
    if low is None:
        return DASH
    return '%s (%s–%s)' % (percent(successes / n), percent(low), percent(high))


def confusion_table(results, key='component'):
    """Markdown lines: a row per injected fault, a column per diagnosed component, then
    the correct rate with its Wilson 95 % interval; a last row for all runs."""
    matrix, columns = stats.confusion(results, key)
    header = ['Injected ↓ diagnosed →'] + columns + ['Correct (95 % CI)']
    rows = []
    for fault, row in matrix.items():
        n = sum(row.values())
        rows.append([fault] + [row.get(c, 0) or '' for c in columns] +
                    [percent_interval(row.get(fault, 0), n)])
    correct = sum(row.get(fault, 0) for fault, row in matrix.items())
    rows.append(['**all**'] + [''] * len(columns) + [percent_interval(correct, len(results))])
    return table(header, rows)


def fault_table(fault, results, fault_summary):
    """Markdown lines like thesis Tables 7.1-7.4: a row per run, then mean, sd (correct
    runs) and the thesis's mean of each column."""
    header = ['Run', 'Seed'] + list(STEP_TITLES) + ['Diagnosis', 'Outcome']
    rows = [['Run %d' % r['number'], r['seed']] + [fmt(r['steps'][n]) for n in STEP_NAMES] +
            [r['component'] or DASH, r['outcome']] for r in results]
    steps = fault_summary['steps']
    rows.append(['Mean'] + [''] + [fmt(steps[n][0]) for n in STEP_NAMES] + ['', ''])
    rows.append(['SD'] + [''] + [fmt(steps[n][1]) for n in STEP_NAMES] + ['', ''])
    means = thesis.step_means(fault)
    if means:
        rows.append(['Thesis mean', 'Table %s' % thesis.TABLES[fault][0]] +
                    [fmt(m) for m in means] + ['', ''])
    return table(header, rows)


def wall_line(meta):
    """The report's line on how long the runs took, when the campaign measured it (meta
    'wall', 'jobs'), followed by an empty line; else nothing."""
    if 'wall' not in meta:
        return []
    jobs = meta.get('jobs', 1)
    return ['Wall time: %d s (%.1f min) for the runs, %s.' % (
        meta['wall'], meta['wall'] / 60.0,
        'one at a time' if jobs == 1 else '%d at a time (`--jobs %d`)' % (jobs, jobs)), '']


# What the report says of Faulty's cylinders (meta 'third_marker').
MARKERS = {False: '', True: '; Faulty carries the third (blue) cylinder behind the other two'}


def markdown(meta, results, figures):
    """The whole report.

    :param meta: dict with 'command', 'date', 'rate', 'interaction', 'runs', 'seed'
    :param figures: dict figure name -> file name relative to the report ('steps_<fault>',
        'totals', 'outcomes'); missing ones are left out
    :rtype: str
    """
    summary = stats.summary(results)
    frac = summary['correct_fraction']
    lines = ['# Case study campaign', '',
             'Command: `%s`  ' % meta['command'],
             'Date: %s; %d run(s) per fault, seed %s, real-time factor %s, interaction fault: %s%s.'
             % (meta['date'], meta['runs'], meta['seed'], meta['rate'], meta['interaction'],
                MARKERS[bool(meta.get('third_marker'))]),
             '',
             ] + wall_line(meta) + [
             'Times are simulated seconds (the recorded /clock). Step boundaries come from the '
             'recorded messages: start = Faulty\'s first `move` action, help = Faulty\'s '
             '`helpme` broadcast, found = Helper\'s `found(...)` to Faulty, diagnosis = the '
             'first `rason/diagnosis` status on /diagnostics. Fault detection = help − start, '
             'robot location = found − help, diagnosis = diagnosis − found, total = diagnosis '
             '− start. With no fault there is no help: only the total. Means and standard '
             'deviations (n − 1) are over the correct runs; the thesis\'s means are over its '
             'successful runs.', '',
             '## Summary', '']
    lines += summary_table(summary)
    lines += ['', 'Correct: %d of %d (%s); undiagnosed: %d; wrong: %d.'
              % (summary['counts']['correct'], summary['runs'],
                 DASH if frac is None else '%.0f %%' % (100 * frac),
                 summary['counts']['undiagnosed'], summary['counts']['wrong']), '']
    lines += ['## Confusion matrix', '',
              'Runs per injected fault (rows) and diagnosis (columns); the correct rate with its '
              'Wilson 95 % interval.', '']
    lines += confusion_table(results)
    lines.append('')
    for name, title in (('totals', 'Total latency per run'), ('outcomes', 'Outcomes')):
        if name in figures:
            lines += ['![%s](%s)' % (title, figures[name]), '']
    for fault, rs in stats.by_fault(results).items():
        thesis_table = thesis.TABLES.get(fault)
        lines += ['## %s%s' % (fault, ' (thesis Table %s)' % thesis_table[0]
                               if thesis_table else ''), '']
        lines += fault_table(fault, rs, summary['faults'][fault])
        notes = ['- Run %d: %s — %s' % (r['number'], r['outcome'], r['reason'])
                 for r in rs if r['outcome'] != 'correct']
        if notes:
            lines += [''] + notes
        if 'steps_' + fault in figures:
            lines += ['', '![%s latency by step](%s)' % (fault, figures['steps_' + fault])]
        lines.append('')
    return '\n'.join(lines)


def results_json(meta, results):
    """Everything as one JSON text: meta, summary, runs and the thesis's tables."""
    data = {'meta': meta, 'summary': stats.summary(results), 'runs': results,
            'thesis': {f: {'table': t, 'runs': rows, 'step_means': thesis.step_means(f),
                           'stated_total': thesis.STATED_TOTAL[f]}
                       for f, (t, rows) in thesis.TABLES.items()}}
    return json.dumps(data, indent=1, ensure_ascii=False)
