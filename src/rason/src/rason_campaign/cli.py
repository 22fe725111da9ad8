"""``rosrun rason campaign``: run the case study per fault, then report.

    rosrun rason campaign --faults all --runs 5 --seed 1 --out results/campaign
    rosrun rason campaign --scenario fault_tolerance --runs 10 --out results/fault_tolerance
    rosrun rason campaign --scenario fleet --sizes 4,6 --runs 25 --out results/fleet

Writes into --out: plan.json, report.md, results.json and the PNG figures (the
fault-tolerance scenario also summary.csv and runs.csv); the bags, the launch logs and each
run's record go to --bags (default: <out>/bags). --analyze-only makes the report again from
what --out and --bags hold; --resume goes on with the plan in --out, making only the runs
that have neither a record in --bags nor a result in --out's results.json.
"""
import argparse
import datetime
import json
import os
import shlex
import signal
import sys
import time

from rason_campaign import (figures, fleet_plan, fleet_runs, mission, mission_figures,
                            mission_report, plan, report, slots, stats, steps)

PLAN_FILE = 'plan.json'
PORTS_PER_SLOT = 100  # master ports each run slot (--jobs) picks from
# Wall seconds before a run is stopped, per scenario: a recovery (a delegated mission above
# all) takes longer than the diagnosis alone.
TIMEOUTS = {'diagnosis': 240.0, 'fault_tolerance': 420.0, 'fleet': 600.0}
# The simulator's real-time factor per scenario: a fleet runs as fast as its lockstep lets it.
RATES = {'diagnosis': 1.0, 'fault_tolerance': 1.0, 'fleet': 0.0}


def parse_args(argv):
    p = argparse.ArgumentParser(prog='campaign', description=__doc__.split('\n\n')[0])
    p.add_argument('--scenario', default='diagnosis', choices=plan.SCENARIOS,
                   help='diagnosis (the thesis\'s case study, default), fault_tolerance '
                   '(each run with recovery and as the thesis\'s baseline) or fleet (N robots '
                   'running one program, helpers by contract net and by broadcast)')
    p.add_argument('--sizes', default=','.join(map(str, fleet_plan.SIZES)),
                   help='fleet: the fleet sizes, robots r1 ... rN of fleet.yaml (default %(default)s)')
    p.add_argument('--fault-at', type=float, default=0.0,
                   help='fault_tolerance: inject the fault this many seconds after Faulty '
                   'first moves (default 0: at the start)')
    p.add_argument('--faults', default='all', help='all, or a comma list of %s' %
                   ', '.join(plan.FAULTS))
    p.add_argument('--runs', type=int, default=5,
                   help='runs per fault (fleet: per size, each in both arms; default 5)')
    p.add_argument('--seed', type=int, default=1, help='campaign seed (default 1)')
    p.add_argument('--out', required=True, help='directory of the report')
    p.add_argument('--bags', help='directory of the bags and logs (default: OUT/bags)')
    p.add_argument('--rate', type=float,
                   help='simulator real-time factor (default 1; fleet: 0, as fast as the lockstep lets it)')
    p.add_argument('--interaction', default='none', choices=sorted(plan.INTERACTIONS),
                   help='interaction fault of thesis §7.5-7.6 (default none)')
    p.add_argument('--no-jitter', action='store_true',
                   help='diagnosis: nominal start poses and brightness in every run')
    p.add_argument('--varied', action='store_true',
                   help='diagnosis: start poses 1-3 m apart in any relative pose, Faulty facing '
                   'away within ±30°, the camera\'s depth noise and dropouts and the lighting '
                   'drawn per run')
    p.add_argument('--timeout', type=float,
                   help='wall seconds before a run is stopped (default %s)' % ', '.join(
                       '%.0f for %s' % (t, s) for s, t in sorted(TIMEOUTS.items())))
    p.add_argument('--port', type=int, default=11611,
                   help='first ROS master port to try (default 11611; run slot k tries '
                   'from PORT + 100 k)')
    p.add_argument('--jobs', type=int, default=1,
                   help='runs at the same time, each on a master of its own (default 1); '
                   'the report is the same, the wall time shorter while the CPU has room')
    p.add_argument('--third-marker', action='store_true',
                   help='Faulty also carries a blue cylinder behind the other two (thesis '
                   '§8.1): two of three are in view from any side')
    p.add_argument('--images', action='store_true', help='bags also hold the camera images')
    p.add_argument('--analyze-only', action='store_true',
                   help='no runs: report again from the bags in --bags')
    p.add_argument('--resume', action='store_true',
                   help='go on with the plan in --out: runs with a record in --bags or a result in '
                   'OUT/results.json are not made again')
    args = p.parse_args(argv)
    if args.timeout is None:
        args.timeout = TIMEOUTS[args.scenario]
    if args.rate is None:
        args.rate = RATES[args.scenario]
    if args.scenario == 'fleet':
        drawn = [name for name, given in (('--faults', args.faults != 'all'),
                                          ('--interaction', args.interaction != 'none'),
                                          ('--no-jitter', args.no_jitter), ('--images', args.images),
                                          ('--third-marker', args.third_marker)) if given]
        if drawn:
            p.error('%s: not for --scenario fleet (its faults and poses are drawn per run)'
                    % ', '.join(drawn))
    if args.jobs < 1:
        p.error('--jobs must be at least 1')
    if args.fault_at and args.scenario != 'fault_tolerance':
        p.error('--fault-at is for --scenario fault_tolerance')
    if args.varied and args.scenario != 'diagnosis':
        p.error('--varied is for --scenario diagnosis')
    if args.varied and args.no_jitter:
        p.error('--varied goes without --no-jitter')
    if args.no_jitter and args.scenario != 'diagnosis':
        p.error('--no-jitter is for --scenario diagnosis (fault_tolerance spreads the poses)')
    return args


def analyze(spec, record, read_events):
    """Result dict of one run from its record (runner.RunRecord or None) and its bag."""
    failure = record.failure if record else 'the run was never made'
    events = []
    if record is not None:
        try:
            events = read_events(record.bag)
        except IOError as e:
            failure = '%s; %s' % (failure, e) if failure else str(e)
    s = steps.extract_steps(events)
    outcome, reason = steps.judge(spec.fault, s, failure)
    result = spec.to_dict()
    result.update({'outcome': outcome, 'reason': reason, 'component': s.component,
                   'evidence': s.evidence, 'steps': s.durations(), 'boundaries': s.to_dict(),
                   'wall': record.wall if record else None,
                   'exit_code': record.exit_code if record else None,
                   'timed_out': record.timed_out if record else None})
    return result


def analyze_mission(spec, record, read_events):
    """Result dict of one fault-tolerance run from its record (runner.RunRecord or None)
    and its bag; ``read_events(path, poses=True)`` reads the bag."""
    failure = record.failure if record else 'the run was never made'
    events = []
    if record is not None:
        try:
            events = read_events(record.bag, poses=True)
        except IOError as e:
            failure = '%s; %s' % (failure, e) if failure else str(e)
    outcome = mission.judge_mission(spec.fault, spec.arm, events, failure)
    result = spec.to_dict()
    result.update(outcome.to_dict())
    result.update({'wall': record.wall if record else None,
                   'exit_code': record.exit_code if record else None,
                   'timed_out': record.timed_out if record else None})
    return result


def progress_start(spec, total):
    return '[%d/%d] %s seed=%d ... ' % (spec.number, total, spec.fault, spec.seed)


def progress_end(result):
    """e.g. 'correct in 21.3 s (wall 25 s)'; the reason when not correct."""
    total_s = result['steps']['total']
    took = ' in %.1f s' % total_s if total_s is not None else ''
    why = '' if result['outcome'] == 'correct' else ': %s' % result['reason']
    wall = ' (wall %.0f s)' % result['wall'] if result['wall'] is not None else ''
    return '%s%s%s%s' % (result['outcome'], took, wall, why)


def mission_progress_start(index, spec, total):
    return '[%d/%d] %s seed=%d %s ... ' % (index, total, spec.fault, spec.seed, spec.arm)


def mission_progress_end(result):
    """e.g. 'completed by faulty (compensate) in 41.2 s, goal error 0.052 m (wall 60 s)';
    the reason when not completed."""
    wall = ' (wall %.0f s)' % result['wall'] if result['wall'] is not None else ''
    if not result['completed']:
        return 'not completed: %s%s' % (result['reason'], wall)
    return 'completed by %s (%s) in %.1f s, goal error %.3f m%s' % (
        ','.join(result['by']), result['recovery'], result['time'], result['goal_error'], wall)


def write_mission_report(out, meta, results):
    names = mission_figures.make_all(results, out)
    for name, text in (('report.md', mission_report.markdown(meta, results, names)),
                       ('results.json', mission_report.results_json(meta, results)),
                       ('summary.csv', mission_report.summary_csv(results)),
                       ('runs.csv', mission_report.runs_csv(results))):
        with open(os.path.join(out, name), 'w') as f:
            f.write(text)


def write_report(out, meta, results):
    names = figures.make_all(results, out)
    with open(os.path.join(out, 'report.md'), 'w') as f:
        f.write(report.markdown(meta, results, names))
    with open(os.path.join(out, 'results.json'), 'w') as f:
        f.write(report.results_json(meta, results))


def output_dirs(out, bags=None):
    """Makes the report's directory and the bags' (default OUT/bags) if missing; returns the bags'."""
    bags = bags or os.path.join(out, 'bags')
    os.makedirs(out, exist_ok=True)
    os.makedirs(bags, exist_ok=True)
    return bags


def main(argv=None):
    """The campaign command; exits with status 1 when a run was diagnosed wrongly. The
    scenario of --analyze-only is the one plan.json was made for."""
    from rason_campaign import bagread, runner  # ROS only here
    args = parse_args(sys.argv[1:] if argv is None else argv)
    stop_on_sigterm()
    bags = output_dirs(args.out, args.bags)
    plan_path = os.path.join(args.out, PLAN_FILE)
    if args.analyze_only or args.resume:
        if not os.path.exists(plan_path):
            sys.exit('campaign: no %s to go on with' % plan_path)
        with open(plan_path) as f:
            saved = json.load(f)
        meta, specs = saved['meta'], [plan.RunSpec.from_dict(d) for d in saved['runs']]
    else:
        try:
            faults = plan.parse_faults(args.faults)
            if args.scenario == 'fleet':
                specs = fleet_plan.make_fleet_plan(fleet_plan.parse_sizes(args.sizes),
                                                   args.runs, args.seed, args.rate)
            elif args.scenario == 'fault_tolerance':
                specs = plan.make_mission_plan(faults, args.runs, args.seed, args.fault_at,
                                               args.interaction, args.rate, args.images,
                                               args.third_marker)
            else:
                specs = plan.make_plan(faults, args.runs, args.seed, args.interaction,
                                       args.rate, args.images, jitter=not args.no_jitter,
                                       varied=args.varied, third_marker=args.third_marker)
        except plan.PlanError as e:
            sys.exit('campaign: %s' % e)
        meta = {'command': 'rosrun rason campaign ' + ' '.join(
                    shlex.quote(a) for a in (sys.argv[1:] if argv is None else argv)),
                'date': datetime.date.today().isoformat(), 'runs': args.runs,
                'seed': args.seed, 'rate': args.rate, 'interaction': args.interaction,
                'jitter': not args.no_jitter, 'timeout': args.timeout}
        if args.varied:
            meta['varied'] = True
        if args.third_marker:
            meta['third_marker'] = True
        if args.scenario != 'diagnosis':  # a diagnosis plan.json stays what it was
            del meta['jitter']            # the poses are spread by poses.spread_poses
            meta.update({'scenario': args.scenario, 'fault_at': args.fault_at})
        if args.scenario == 'fleet':
            meta['sizes'] = args.sizes
            del meta['interaction'], meta['fault_at']
        _write_plan(plan_path, meta, specs)
    if meta.get('scenario', 'diagnosis') == 'fault_tolerance':
        sys.exit(run_missions(args, meta, specs, bags, runner, bagread))
    if meta.get('scenario') == 'fleet':
        sys.exit(fleet_runs.run_fleet(args, meta, specs, bags, runner, bagread, run_all))
    t0 = time.monotonic()
    results = run_all(args, specs, bags, runner,
                      lambda _index, spec: progress_start(spec, len(specs)),
                      lambda spec, record: analyze(spec, record, bagread.read_events),
                      progress_end)
    wall = time.monotonic() - t0
    if not args.analyze_only:  # the report states how long the runs took (plan.json keeps it)
        meta.update({'wall': round(wall), 'jobs': args.jobs})
        _write_plan(plan_path, meta, specs)
    write_report(args.out, meta, results)
    s = stats.summary(results)
    print('campaign: %d correct, %d undiagnosed, %d wrong of %d runs in %.0f s; report %s'
          % (s['counts']['correct'], s['counts']['undiagnosed'], s['counts']['wrong'],
             s['runs'], wall, os.path.join(args.out, 'report.md')))
    sys.exit(0 if s['counts']['wrong'] == 0 else 1)


def stop_on_sigterm():
    """``kill`` (SIGTERM) stops a campaign as Ctrl-C does, also one started in the background
    (where SIGINT is ignored): the run under way is stopped and gets no record."""
    def interrupt(_signum, _frame):
        raise KeyboardInterrupt
    signal.signal(signal.SIGTERM, interrupt)


def _write_plan(path, meta, specs):
    """plan.json: the campaign's meta and its runs (what --analyze-only reads back)."""
    with open(path, 'w') as f:
        json.dump({'meta': meta, 'runs': [s.to_dict() for s in specs]}, f, indent=1)


def run_all(args, specs, bags, runner, start_line, analyze_run, end_line):
    """Runs each spec, --jobs at a time (or, with --analyze-only, loads its record), analyses
    it and prints its progress line as it ends; returns the results in the specs' order.

    :param start_line: (index from 1, spec) -> the text printed before the run
    :param analyze_run: (spec, record or None) -> the run's result
    :param end_line: result -> the text that ends the line"""
    reported = reported_runs(args.out) if args.resume else {}

    def run_one(numbered, slot):
        _index, spec = numbered
        kept = os.path.join(bags, spec.name + '.run.json') if args.analyze_only or args.resume else None
        if args.analyze_only or (kept and os.path.exists(kept)):  # --resume: made before
            record = runner.RunRecord.load(kept) if os.path.exists(kept) else None
        elif reported and spec.name in reported:  # --resume: reported, its bag elsewhere
            return reported[spec.name]
        else:
            record = runner.run(spec, bags, args.timeout, args.port + PORTS_PER_SLOT * slot)
        return analyze_run(spec, record)

    def print_line(_position, numbered, result):
        print(start_line(*numbered) + end_line(result), flush=True)

    jobs = 1 if args.analyze_only else args.jobs
    return slots.run_in_slots(list(enumerate(specs, 1)), jobs, run_one, print_line,
                              runner.stop_all)


def reported_runs(out):
    """{run name: result} of the runs that --out's results.json reports as made (a wall time
    recorded), so that --resume goes on without their bags, e.g. on another machine."""
    path = os.path.join(out, 'results.json')
    if not os.path.exists(path):
        return {}
    with open(path) as f:
        runs = json.load(f).get('runs', [])
    return {plan.RunSpec.from_dict(r).name: r for r in runs
            if isinstance(r, dict) and r.get('wall') is not None}


def run_missions(args, meta, specs, bags, runner, bagread):
    """The fault-tolerance campaign's runs (or, with --analyze-only, their bags) and
    report.

    :returns: the exit status: 1 when a run was diagnosed wrongly, else 0"""
    t0 = time.monotonic()
    results = run_all(args, specs, bags, runner,
                      lambda index, spec: mission_progress_start(index, spec, len(specs)),
                      lambda spec, record: analyze_mission(spec, record, bagread.read_events),
                      mission_progress_end)
    write_mission_report(args.out, meta, results)
    rows = mission_report.summary(results)
    wrong = sum(r['wrong'] for r in rows)
    met = all(g['met'] for g in mission_report.goals(results, rows))
    print('campaign: %d of %d runs completed, %d wrong diagnoses, in %.0f s; acceptance goals '
          '%s; report %s' % (sum(r['completed'] for r in rows), len(results), wrong,
                             time.monotonic() - t0, 'met' if met else 'not met',
                             os.path.join(args.out, 'report.md')))
    return 0 if wrong == 0 else 1
