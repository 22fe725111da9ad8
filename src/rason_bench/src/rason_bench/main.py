"""``make bench`` / ``rosrun rason_bench run_bench``: runs the benchmarks on a master of
their own and writes ``report.md``, ``results.json`` and PNG plots.

Options: ``--seconds`` (length of one measured run, default 1), ``--quick`` (a subset of
cells, fewer samples, for a smoke run), ``--only`` (startup, cycle, latency, cpu, reaction,
scale, preemption, hostile, fleet, behaviour, budget, fleet_sim; repeatable), ``--take-backs`` (rounds of the preemption part), ``--out``
(directory).
"""
import argparse
import datetime
import json
import os
import platform
import subprocess
import sys
import time

from rason_bench import plots, report, thesis

#: The parts of a run, in the order they run (behaviour, budget and fleet_sim last: they start the simulator).
PARTS = ('startup', 'cycle', 'latency', 'cpu', 'reaction', 'scale', 'preemption', 'hostile', 'fleet', 'behaviour',
         'budget', 'fleet_sim')
#: Starts of a one-agent rason_mas the startup part times (normal, --quick).
STARTS, STARTS_QUICK = 5, 3
TAKE_BACKS, TAKE_BACKS_QUICK = 200, 50
#: motion_decomp's ~rate in the preemption part: the 50 Hz control period of the goal.
CONTROL_RATE_HZ = 50.0
#: The hostile part's flood (issue 13's): seconds (--quick: FLOOD_SECONDS_QUICK), Hz,
#: literals per message, and when after it the node's RSS is read (s).
FLOOD_SECONDS, FLOOD_SECONDS_QUICK, FLOOD_RATE_HZ, FLOOD_LITERALS, FLOOD_AFTER_S = 20.0, 5.0, 1000.0, 50, 10.0
#: The fleet part (issue 30), normal and --quick: round trips after a warm-up, seconds per step
#: of the message rate, kills one at a time and at once among FLEET_ROBOTS, and the window of
#: each loss level (s) in which false departures are counted.
FLEET = {'warmup': 200, 'round_trips': 1000, 'rate_seconds': 2.0, 'singles': 10, 'batch': 10, 'loss_window_s': 120.0}
FLEET_QUICK = {'warmup': 100, 'round_trips': 300, 'rate_seconds': 1.0, 'singles': 5, 'batch': 5, 'loss_window_s': 30.0}
FLEET_ROBOTS, FLEET_LOSSES = 100, (10, 20)


def _parse(argv):
    ap = argparse.ArgumentParser(prog='run_bench', description=__doc__.split('\n\n')[0])
    ap.add_argument('--seconds', type=float, default=1.0, help='length of one measured run (s)')
    ap.add_argument('--quick', action='store_true', help='perceptions {1, 10} x {1, 50} Hz, fewer samples')
    ap.add_argument('--only', action='append', choices=PARTS,
                    help='run only these parts (repeatable)')
    ap.add_argument('--take-backs', type=int, default=None,
                    help='take-backs measured by the preemption part (default %d, %d with --quick)'
                    % (TAKE_BACKS, TAKE_BACKS_QUICK))
    ap.add_argument('--out', default='results/bench', help='output directory')
    return ap.parse_args(argv)


def machine_facts():
    """CPU count and model, load average, whether the simulator runs, versions."""
    model = ''
    try:
        with open('/proc/cpuinfo') as f:
            model = next((l.split(':', 1)[1].strip() for l in f if l.startswith('model name')), '')
    except OSError:
        pass
    sim = subprocess.run(['pgrep', '-f', 'rason_sim_node'], stdout=subprocess.DEVNULL).returncode == 0
    java = subprocess.run(['java', '-version'], stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          universal_newlines=True).stdout.splitlines()
    return {'cpus': os.cpu_count(), 'cpu_model': model, 'load_at_start': list(os.getloadavg()),
            'simulator_running': sim, 'python': platform.python_version(), 'java': java[0] if java else '',
            'date': datetime.datetime.now().strftime('%Y-%m-%d %H:%M')}


def main(argv=None):
    args = _parse(sys.argv[1:] if argv is None else argv)
    parts = [p for p in PARTS if p in (args.only or PARTS)]
    out_dir = os.path.abspath(args.out)
    os.makedirs(out_dir, exist_ok=True)
    perceptions = (1, 10) if args.quick else thesis.PERCEPTIONS
    rates = (1, 50) if args.quick else thesis.RATES_HZ
    pings, stamps = (100, 50) if args.quick else (1000, 300)
    wakeups, sim_window = (3, 5.0) if args.quick else (5, 10.0)
    take_backs = args.take_backs or (TAKE_BACKS_QUICK if args.quick else TAKE_BACKS)
    results = {'machine': machine_facts(),
               'params': {'seconds': args.seconds, 'perceptions': list(perceptions), 'rates_hz': list(rates),
                          'pings': pings, 'stamps': stamps, 'stamp_period_s': 0.02, 'quick': args.quick,
                          'cpu_window_s': 5 * args.seconds, 'triggers': stamps,
                          'busy_intentions': report.BUSY_INTENTIONS, 'wakeups': wakeups, 'wakeup_gap_s': 2.0,
                          'sim_window_s': sim_window, 'rate_limit_seconds': 3.0, 'rate_limit_sent_hz': 50.0,
                          'take_backs': take_backs, 'control_rate_hz': CONTROL_RATE_HZ,
                          'starts': STARTS_QUICK if args.quick else STARTS,
                          'flood_seconds': FLOOD_SECONDS_QUICK if args.quick else FLOOD_SECONDS,
                          'flood_rate_hz': FLOOD_RATE_HZ, 'flood_literals': FLOOD_LITERALS,
                          'flood_after_s': FLOOD_AFTER_S, 'parts': parts,
                          'fleet': dict(FLEET_QUICK if args.quick else FLEET, robots=FLEET_ROBOTS,
                                        losses=list(FLEET_LOSSES))}}

    def log(line):
        print(line, flush=True)

    log('load average at start: %s%s' % (results['machine']['load_at_start'],
                                         ' (the simulator is running)' if results['machine']['simulator_running'] else ''))
    from rason_bench.procs import Processes
    procs = Processes(os.path.join(out_dir, 'logs'))
    os.environ['ROS_MASTER_URI'] = procs.master_uri
    procs.start_master()
    started = time.monotonic()
    failed = []
    try:
        import rason_rospy
        import rospy
        from rason_bench import behaviour, experiments, fleet, fleet_sim, hostile, robot_budget, startup
        from rason_bench.harness import Harness
        rason_rospy.init_node('rason_bench', disable_signals=True)
        harness = Harness()
        p = results['params']

        def scale():
            iterations = results['cycle']['per_source']['iterations'] if 'per_source' in results.get('cycle', {}) else 20000
            return experiments.scale(procs, harness, (1, 10, 100), args.seconds, iterations, log)
        steps = {
            'startup': [('startup', 'start-up: a one-agent rason_mas to its first reasoning cycle',
                         lambda: startup.measure(procs, harness, p['starts'], log))],
            'cycle': [('cycle', None, lambda: experiments.cycle_tables(
                procs, harness, ('accumulate', 'per_source'), perceptions, rates, args.seconds, log))],
            'latency': [('latency', 'latencies', lambda: experiments.latencies(procs, harness, pings, stamps, 0.02, log))],
            'cpu': [('cpu', 'node CPU time per perception message', lambda: experiments.node_cpu_per_message(
                procs, harness, p['cpu_window_s'], log))],
            'reaction': [('reaction', 'reaction: perception -> action', lambda: experiments.reaction(
                procs, harness, p['triggers'], 0.02, p['busy_intentions'], log))],
            'scale': [('scale', 'scale', scale)],
            'preemption': [('preemption', 'preemption (motion_decomp at %g Hz)' % CONTROL_RATE_HZ,
                            lambda: experiments.preemption(procs, harness, p['take_backs'], CONTROL_RATE_HZ, log))],
            'hostile': [
                ('hostile.inputs', 'hostile input: the agent answers after each', lambda: hostile.reaction_after_inputs(
                    procs, harness, log)),
                ('hostile.flood', 'hostile input: a perception flood', lambda: hostile.flood(
                    procs, harness, p['flood_seconds'], p['flood_rate_hz'], p['flood_literals'], p['flood_after_s'],
                    log))],
            'fleet': fleet.steps(procs, p['fleet'], os.path.join(out_dir, 'logs'), log) if 'fleet' in parts else [],
            'behaviour': [
                ('behaviour.wakeup', 'behaviour: idle wake-up', lambda: behaviour.wakeup(
                    procs, harness, wakeups, p['wakeup_gap_s'], log)),
                ('behaviour.rate_limit', 'behaviour: perception rate limit', lambda: behaviour.rate_limit(
                    procs, harness, p['rate_limit_seconds'], p['rate_limit_sent_hz'], log)),
                ('behaviour.sim', 'behaviour: simulator rates (two_robots.launch)', lambda: behaviour.sim_rates(
                    procs, sim_window, log))],
            'budget': [('budget', 'robot budget: the case study, each robot in a CPU cgroup (rate 1)',
                        lambda: robot_budget.measure(args.quick, log))],
            'fleet_sim': [('fleet_sim', 'the simulator with a fleet: N = %s robots, lockstep on (rate 0)'
                           % ', '.join(str(n) for n in fleet_sim.SIZES),
                           lambda: fleet_sim.measure(procs, args.quick, log))]}
        for part in parts:
            for key, title, measure in steps[part]:
                if title:
                    log(title)
                t0 = time.monotonic()
                try:
                    value = measure()
                except Exception as e:  # the other parts still run and are written
                    failed.append(key)
                    results.setdefault('errors', {})[key] = '%s: %s' % (type(e).__name__, e)
                    log('  FAILED: %s: %s' % (type(e).__name__, e))
                    continue
                finally:
                    results.setdefault('durations_s', {})[key] = round(time.monotonic() - t0, 1)
                section, _, sub = key.partition('.')
                if sub:
                    results.setdefault(section, {})[sub] = value
                else:
                    results[section] = value
    finally:
        procs.stop_master()
    results['duration_s'] = round(time.monotonic() - started, 1)
    write(results, out_dir)
    for goal, measured, met in report.goals(results):
        log('%-70s %-40s %s' % (goal, measured, 'skipped' if met is None else 'met' if met else 'NOT MET'))
    log('wrote %s/report.md (%.0f s)%s' % (out_dir, results['duration_s'],
                                            '; FAILED: ' + ', '.join(failed) if failed else ''))
    return 1 if failed else 0


def write(results, out_dir):
    results['goals'] = [{'goal': goal, 'measured': measured, 'met': met}
                        for goal, measured, met in report.goals(results)]
    with open(os.path.join(out_dir, 'results.json'), 'w') as f:
        json.dump(results, f, indent=1, sort_keys=True)
    if 'cycle' in results:
        plots.cycle_plot(results['cycle'], os.path.join(out_dir, 'cycle_time.png'))
    if 'latency' in results:
        plots.latency_plot(results['latency'], os.path.join(out_dir, 'latency.png'))
    if 'scale' in results:
        plots.scale_plot(results['scale'], os.path.join(out_dir, 'scale.png'))
    if results.get('budget', {}).get('runs'):
        plots.budget_plot(results['budget'], os.path.join(out_dir, 'budget.png'))
    if 'reaction' in results:
        plots.reaction_plot(results['reaction'], os.path.join(out_dir, 'reaction.png'))
    with open(os.path.join(out_dir, 'report.md'), 'w') as f:
        f.write(report.markdown(results))
