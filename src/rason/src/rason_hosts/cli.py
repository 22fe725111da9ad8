"""rosrun rason hosts cleanup [--all] [--prefix P] | list: leftovers of the hosts harness;
rosrun rason hosts case-study [--fault F] [--loss P] [--delay-ms D] [--partition S] [--recovery]:
the case study with each robot on a host of its own (needs root)."""
import argparse
import re
import sys
import tempfile

from .hosts import DEFAULT_PREFIX, cleanup, list_namespaces


def main(argv=None):
    parser = argparse.ArgumentParser(prog='hosts', description=__doc__)
    sub = parser.add_subparsers(dest='command', required=True)
    clean = sub.add_parser('cleanup', help='remove the namespaces of runs whose process is gone')
    clean.add_argument('--all', action='store_true', help='also remove runs still alive')
    clean.add_argument('--prefix', default=DEFAULT_PREFIX)
    listing = sub.add_parser('list', help='the namespaces of the harness')
    listing.add_argument('--prefix', default=DEFAULT_PREFIX)
    play = sub.add_parser('case-study', help='Faulty and Helper on hosts of their own, over MQTT')
    play.add_argument('--fault', default='both_actuators')
    play.add_argument('--loss', type=float, default=0, help="%% of frames lost each way on each robot's link")
    play.add_argument('--delay-ms', type=int, default=0, help="ms added each way to each robot's connection")
    play.add_argument('--partition', type=float, default=0, help="s Helper's link is cut once its search began")
    play.add_argument('--recovery', action='store_true', help='the fault-tolerance mission')
    play.add_argument('--rate', type=float, default=0, help="the simulator's real-time factor (0: lockstep)")
    args = parser.parse_args(argv)
    if args.command == 'case-study':
        return _case_study(args)
    if args.command == 'list':
        for namespace in list_namespaces():
            if namespace.startswith(args.prefix + '-'):
                print(namespace)
        return 0
    removed = cleanup(args.prefix, all_runs=args.all)
    for namespace in removed:
        print('removed %s' % namespace)
    if not removed:
        print('nothing to remove')
    return 0


#: What an agent printed ([faulty] ... or [helper] ...), in a line of roslaunch's output.
AGENT_LINE = re.compile(r'\[(faulty|helper)\] .*')


def _case_study(args):
    from .case_study import HOST_NAMES, CaseStudyOnHosts
    from .hosts import Hosts

    def echo(source, text):
        said = AGENT_LINE.search(text)
        if said and source in ('faulty', 'helper'):
            print(said.group(0), flush=True)

    folder = tempfile.mkdtemp(prefix='rason_case_study_')
    print('logs in %s' % folder, flush=True)
    with Hosts(HOST_NAMES) as hosts:
        outcome = CaseStudyOnHosts(hosts, folder, fault=args.fault, recovery=args.recovery,
                                   loss=args.loss, delay_ms=args.delay_ms,
                                   partition=args.partition or None, rate=args.rate,
                                   echo=echo).play()
    print('diagnosis: %s (%s)' % outcome.diagnosis, flush=True)
    if outcome.mission:
        print('mission completed: %s by %s (recovery %s)' % outcome.mission, flush=True)
    return 0


if __name__ == '__main__':
    sys.exit(main())
