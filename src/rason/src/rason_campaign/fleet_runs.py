"""The fleet scenario of ``rosrun rason campaign`` (issue 34): analysing each run's bag and
writing the report; cli.py plans and runs them as it does the others'."""
import os
import time

from rason_campaign import fleet_figures, fleet_judge, fleet_report


def analyze(spec, record, read_events):
    """Result dict of one fleet run from its record (runner.RunRecord or None) and its bag;
    ``read_events(path, poses=True, robots=...)`` reads the bag."""
    failure = record.failure if record else 'the run was never made'
    events = []
    if record is not None:
        try:
            events = read_events(record.bag, poses=True, robots=spec.args['robots'].split())
        except IOError as e:
            failure = '%s; %s' % (failure, e) if failure else str(e)
    result = spec.to_dict()
    result.update(fleet_judge.judge_run(spec.args, events, failure))
    result.update({'wall': record.wall if record else None,
                   'exit_code': record.exit_code if record else None,
                   'timed_out': record.timed_out if record else None})
    return result


def progress_start(index, spec, total):
    return '[%d/%d] N=%d %s %s seed=%d ... ' % (index, total, len(spec.args['robots'].split()),
                                               spec.args['faults'], spec.arm, spec.seed)


def progress_end(result):
    """e.g. 'completed; diagnosed r3 in 18.5 s, r4 in 12.8 s (wall 91 s)'; why when not."""
    times = ', '.join('%s in %s s' % (r['robot'], '–' if r['time_to_diagnosis'] is None
                                      else '%.1f' % r['time_to_diagnosis'])
                      for r in fleet_report.faulty_robots(result))
    wall = ' (wall %.0f s)' % result['wall'] if result['wall'] is not None else ''
    head = 'completed' if result['completed'] else 'NOT completed'
    why = '' if result['completed'] and not result['wrong'] else ': %s' % result['reason']
    return '%s; diagnosed %s%s%s' % (head, times, wall, why)


def write_report(out, meta, results):
    names = fleet_figures.make_all(results, out)
    for name, text in (('report.md', fleet_report.markdown(meta, results, names)),
                       ('results.json', fleet_report.results_json(meta, results)),
                       ('runs.csv', fleet_report.runs_csv(results))):
        with open(os.path.join(out, name), 'w') as f:
            f.write(text)


def run_fleet(args, meta, specs, bags, runner, bagread, run_all):
    """The fleet campaign's runs (or, with --analyze-only, their bags) and the report of the
    runs made (of a campaign stopped part-way, the report says how many of the plan's).

    :returns: the exit status: 1 when a run was diagnosed wrongly, else 0"""
    t0 = time.monotonic()
    results = run_all(args, specs, bags, runner,
                      lambda index, spec: progress_start(index, spec, len(specs)),
                      lambda spec, record: analyze(spec, record, bagread.read_events),
                      progress_end)
    made = [r for r in results if r['wall'] is not None]  # a campaign stopped part-way
    write_report(args.out, dict(meta, planned=len(specs)), made)
    wrong = sum(r['wrong'] for r in made)
    completed = sum(bool(r['completed']) for r in made)
    met = all(m for _, m, _ in fleet_report.goals(made))
    print('campaign: %d of %d runs made (%d planned) completed, %d wrong diagnoses, in %.0f s; '
          'goals %s; report %s' % (completed, len(made), len(specs), wrong, time.monotonic() - t0,
                                   'met' if met else 'not met', os.path.join(args.out, 'report.md')))
    return 0 if wrong == 0 else 1
