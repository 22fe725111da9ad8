"""``rosrun rason budget``: run a command with each robot's processes held to a CPU quota
and measured; and ``rosrun rason in_budget ROBOT COMMAND...``, the launch prefix that puts a
node in its robot's group.

  budget detect                      which cgroup hierarchy a budget would use
  budget run --cores 0.5 --robot faulty --robot helper [--json F] -- roslaunch rason faulty_helper.launch budget:=true
  budget cleanup [--all]             remove the groups crashed runs left
"""
import argparse
import json
import os
import signal
import subprocess
import sys

from rason_budget import cgroups
from rason_budget.meter import Meter


def _parse(argv):
    ap = argparse.ArgumentParser(prog='budget', description=__doc__.split('\n\n')[0])
    sub = ap.add_subparsers(dest='command', required=True)
    sub.add_parser('detect', help='say which cgroup hierarchy is used, or why none can be')
    clean = sub.add_parser('cleanup', help="remove the groups of crashed runs")
    clean.add_argument('--all', action='store_true', help="every run's groups, live ones too")
    run = sub.add_parser('run', help='run a command with RASON_BUDGET_RUN set; measure each robot')
    run.add_argument('--cores', type=float, default=None, help='quota of each robot (default: none, only measure)')
    run.add_argument('--robot', action='append', required=True, help='a robot (repeatable)')
    run.add_argument('--interval', type=float, default=0.5, help='seconds between looks (default 0.5)')
    run.add_argument('--json', help='write the measurements here')
    run.add_argument('argv', nargs=argparse.REMAINDER, help='-- the command')
    return ap.parse_args(argv)


def format_summary(summary):
    """Lines for a person: per robot CPU and RSS, then per process."""
    lines = []
    for robot, r in sorted(summary['robots'].items()):
        quota = 'no quota' if r['quota_cores'] is None else 'quota %.2f core' % r['quota_cores']
        lines.append('%s (%s): CPU mean %.3f core, p95 %.3f, %.1f s over %.0f s; RSS peak %.0f MB; throttled %s'
                     % (robot, quota, r['cpu_mean_cores'], r['cpu_p95_cores'], r['cpu_s'], r['seconds'],
                        r['rss_total_peak_mb'], r['throttling']))
        lines += ['  %-24s %7.2f s CPU  %6.3f core  RSS peak %6.1f MB' % (p['name'], p['cpu_s'], p['cpu_mean_cores'],
                                                                      p['rss_peak_mb']) for p in r['processes']]
    if 'outside' in summary:
        lines.append('outside the budget: %.1f s CPU' % summary['outside']['cpu_s'])
        lines += ['  %-24s %7.2f s CPU  RSS peak %6.1f MB' % (p['name'], p['cpu_s'], p['rss_peak_mb'])
                  for p in summary['outside']['processes']]
    return lines


def run(args):
    argv = args.argv[1:] if args.argv[:1] == ['--'] else args.argv
    if not argv:
        raise cgroups.BudgetError('no command given (budget run ... -- COMMAND)')
    with cgroups.Budget({robot: args.cores for robot in args.robot}) as budget:
        proc = None
        meter = Meter(budget, args.interval, root_pid=lambda: proc.pid if proc else None)
        with meter:
            proc = subprocess.Popen(argv, env=dict(os.environ, **budget.env))
            try:
                code = proc.wait()
            except KeyboardInterrupt:  # the command got the Ctrl-C too; let it end
                code = proc.wait()
    summary = meter.summary()
    print('\n'.join(format_summary(summary)))
    if args.json:
        with open(args.json, 'w') as f:
            json.dump(summary, f, indent=1, sort_keys=True)
    return code


def main(argv=None):
    args = _parse(sys.argv[1:] if argv is None else argv)
    try:
        if args.command == 'detect':
            print(cgroups.detect())
            return 0
        if args.command == 'cleanup':
            for name in cgroups.cleanup(all_runs=args.all):
                print('removed %s' % name)
            return 0
        return run(args)
    except cgroups.BudgetError as e:
        print('budget: %s' % e, file=sys.stderr)
        return 2


def in_budget_main(argv=None):
    """``in_budget ROBOT COMMAND...``: join ROBOT's group of the run in RASON_BUDGET_RUN,
    then exec COMMAND (so the node's PID, signals and exit code are its own)."""
    argv = sys.argv[1:] if argv is None else argv
    if len(argv) < 2:
        print('usage: in_budget ROBOT COMMAND [ARG...]', file=sys.stderr)
        return 2
    try:
        cgroups.join_by_name(argv[0], os.getpid())
    except (cgroups.BudgetError, OSError) as e:
        print('in_budget: %s' % e, file=sys.stderr)
        return 2
    signal.signal(signal.SIGPIPE, signal.SIG_DFL)  # Python ignores it; exec would pass that on
    os.execvp(argv[1], argv[1:])
