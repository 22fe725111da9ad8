"""rosrun rason hosts cleanup [--all] [--prefix P] | list: leftovers of the hosts harness;
rosrun rason hosts case-study [--fault F] [--loss P] [--delay-ms D] [--partition S] [--recovery]:
the case study with each robot on a host of its own (needs root);
rosrun rason hosts campaign --runs N --out DIR [--recovery]: many such runs, the link drawn,
each beside the same run on a clean link (link_campaign)."""
import argparse
import json
import os
import re
import shutil
import signal
import sys
import tempfile
import time

from .hosts import DEFAULT_PREFIX, HostsError, cleanup, list_namespaces
from . import link_campaign


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
    campaign = sub.add_parser('campaign', help='the case study across hosts, many runs, the link as a factor')
    campaign.add_argument('--runs', type=int, default=10,
                          help='drawn scenarios; each runs on its link and on a clean one')
    campaign.add_argument('--seed', type=int, default=1)
    campaign.add_argument('--faults', default='all', help='all, or a comma list of ' + ','.join(link_campaign.FAULTS))
    campaign.add_argument('--recovery', action='store_true', help='the fault-tolerance mission, judged by true poses')
    campaign.add_argument('--rate', type=float, default=1, help="the simulator's real-time factor (0: lockstep)")
    campaign.add_argument('--timeout', type=float, default=240, help='wall s a run may take to its diagnosis')
    campaign.add_argument('--out', required=True, help='folder for report.md, results.json and the runs\' logs')
    campaign.add_argument('--resume', action='store_true',
                          help='go on with the campaign in OUT (same plan): play only the scenarios not yet played on '
                               'both links')
    campaign.add_argument('--analyze-only', action='store_true',
                          help="make report.md again from OUT/results.json (e.g. of a campaign stopped early)")
    args = parser.parse_args(argv)
    if args.command == 'case-study':
        return _case_study(args)
    if args.command == 'campaign':
        return _campaign(args, argv)
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


def _campaign(args, argv_seen=None):
    from .case_study import HOST_NAMES, CaseStudyOnHosts
    from .hosts import Hosts

    faults = link_campaign.FAULTS if args.faults == 'all' else tuple(args.faults.split(','))
    unknown = sorted(set(faults) - set(link_campaign.FAULTS))
    if unknown:
        print('campaign: unknown fault(s) %s; known: %s' % (', '.join(unknown), ', '.join(link_campaign.FAULTS)),
              file=sys.stderr)
        return 2
    # SIGTERM ends the campaign as Ctrl-C does: through the with-blocks that remove each run's hosts
    signal.signal(signal.SIGTERM, lambda *_: sys.exit(143))
    args.out = os.path.abspath(args.out)
    if args.analyze_only:
        with open(os.path.join(args.out, 'results.json')) as f:
            records = json.load(f)
        return _campaign_report(records, args.out)
    os.makedirs(args.out, exist_ok=True)
    plan = link_campaign.draw_plan(args.runs, args.seed, faults, args.recovery)
    command = 'rosrun rason hosts ' + ' '.join(sys.argv[1:] if argv_seen is None else argv_seen)
    now = time.strftime('%Y-%m-%d %H:%M', time.gmtime())
    records, to_play = [], plan
    if args.resume:
        with open(os.path.join(args.out, 'campaign.json')) as f:
            made = json.load(f)
        with open(os.path.join(args.out, 'results.json')) as f:
            records, to_play = link_campaign.remaining(plan, json.load(f))
        made.setdefault('resumed', []).append({'at': now, 'command': command, 'from_run': to_play[0]['run']
                                               if to_play else None})
    else:
        made = {'command': command, 'started': now, 'rate': args.rate, 'seed': args.seed, 'cores': os.cpu_count()}
    with open(os.path.join(args.out, 'campaign.json'), 'w') as f:
        json.dump(made, f, indent=1)
    for scenario in to_play:
        for link, played in (('drawn', scenario), ('clean', link_campaign.on_clean_link(scenario))):
            folder = os.path.join(args.out, 'runs', '%03d-%s' % (scenario['run'], link))
            shutil.rmtree(folder, ignore_errors=True)     # what a stopped campaign left of the run
            os.makedirs(folder)
            record = {'scenario': played, 'link': link}
            with Hosts(HOST_NAMES) as hosts:
                partition = played['partition'] or {}
                run = CaseStudyOnHosts(hosts, folder, fault=played['fault'], recovery=played['recovery'],
                                       loss=played['loss'], delay_ms=played['delay_ms'],
                                       partition=partition.get('seconds'), partition_after=partition.get('after', 0),
                                       rate=args.rate, seed=played['seed'], timeout=args.timeout)
                record.update(play_and_judge(run, played))
            records.append(record)
            link_campaign.save(records, os.path.join(args.out, 'results.json'))
            print('[%d/%d %s] %s on %s: %s%s' % (
                scenario['run'], len(plan), link, played['fault'], link_campaign.link_label(played),
                record['verdict']['outcome'],
                ' in %.1f s' % record['diagnosis_s'] if record.get('diagnosis_s') else ''), flush=True)
    return _campaign_report(records, args.out)


def play_and_judge(run, played):
    """Plays run (a CaseStudyOnHosts of scenario played); its verdict and, once Faulty gave its
    diagnosis, the wall seconds to it. A run that fails after the diagnosis (the mission never
    ended) keeps the diagnosis, with the failure as the reason."""
    diagnosis = failure = mission = closest = back = None
    try:
        outcome = run.play()
        diagnosis, mission = outcome.diagnosis, outcome.mission
        closest, back = outcome.mission_judged()
    except HostsError as e:
        diagnosis = run.diagnosis
        failure = str(e).splitlines()[0].split('; last lines')[0]
    played_out = {'verdict': link_campaign.judge(played, diagnosis, failure, mission, closest, back)}
    if 'diagnosis' in run.marks:
        played_out['diagnosis_s'] = run.marks['diagnosis'] - run.marks['launched']
    return played_out


FIGURE = 'links.png'


def _campaign_report(records, out):
    """report.md of out from records, with how the campaign was made (out/campaign.json)."""
    with open(os.path.join(out, 'campaign.json')) as f:
        made = json.load(f)
    scenarios = len({r['scenario']['run'] for r in records})
    title = 'The case study across hosts: %d scenarios (seed %d), each on its drawn link and on a clean one' % (
        scenarios, made['seed'])
    how = ('Made by `%s` from %s UTC (%d cores, shared), the simulator at real-time factor %g; times are wall '
           'seconds from the robots\' launch to Faulty\'s diagnosis. Each run\'s logs: `runs/`, not committed.'
           % (made['command'], made['started'], made['cores'], made['rate']))
    for resumed in made.get('resumed', ()):
        how += ' Resumed from run %s at %s UTC (`%s`).' % (resumed['from_run'], resumed['at'], resumed['command'])
    from .link_figures import links_figure
    links_figure(records, os.path.join(out, FIGURE))
    with open(os.path.join(out, 'report.md'), 'w') as f:
        f.write(link_campaign.report(records, title, how, figure=FIGURE))
    print('report: %s' % os.path.join(out, 'report.md'), flush=True)
    return 1 if any(r['verdict']['outcome'] == 'wrong' for r in records) else 0


if __name__ == '__main__':
    sys.exit(main())
