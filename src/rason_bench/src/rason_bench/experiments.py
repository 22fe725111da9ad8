"""The benchmarks of ``make bench`` on the agents' node, each against its own rason_mas process.

1. :func:`cycle_tables`: thesis Tables 5.1/5.2, the Listing 5.4 loop under bursts from
   ``bench_synth``, per perception manager, with baselines (no traffic) in the same JVM.
2. :func:`latencies`: action round trip and perception -> belief event, idle and under a burst.
3. :func:`node_cpu_per_message`: the node's CPU time per perception message of a burst.
4. :func:`reaction`: perception -> the agent's action, idle and under load (a burst and
   busy intentions).
5. :func:`scale`: 1, 10, 100 agents in one process hearing 10 perceptions at 10 Hz.
6. :func:`preemption`: an agent takes its ``move`` back; time to the zero twist of the real
   ``motion_decomp`` node on ``cmd_vel`` (a stand-in base, ``bench_base``, gives it odometry).

The simulator's rates, wake-up and the rate limit are in :mod:`rason_bench.behaviour`.
"""
import contextlib
import os
import random
import time

import psutil
import rospy
from rason_msgs.msg import Action

from rason_bench import preempt, protocol, stats

AGENTS_DIR = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', 'agents')
BURST_SOURCE = 'bench_synth_burst'


def agents_file(name):
    return os.path.normpath(os.path.join(AGENTS_DIR, name))


class Mas(object):
    """One rason_mas process running a benchmark project, and its CPU and memory use."""

    def __init__(self, procs, harness, mas2j, perception_manager='per_source', **params):
        self.procs = procs
        self.harness = harness
        if rospy.has_param('/rason_mas/agents'):  # left by the previous run's node
            rospy.delete_param('/rason_mas/agents')
        self.proc = procs.rosrun('rason_mas', 'rason_bridge', 'rason_mas', agents_file(mas2j),
                                 perception_manager=perception_manager, **params)
        self.ps = psutil.Process(self.proc.pid)

    def __enter__(self):
        try:
            self.agents = self._agent_names(60.0)
            for name in self.agents:
                self.harness.handshake(name, 60.0)
        except Exception:
            self.procs.stop(self.proc)
            raise
        return self

    def __exit__(self, *exc):
        self.procs.stop(self.proc)

    def _agent_names(self, timeout):
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            if rospy.has_param('/rason_mas/agents'):
                return list(rospy.get_param('/rason_mas/agents'))
            time.sleep(0.1)
        raise RuntimeError('rason_mas did not list its agents')

    def cpu_seconds(self):
        t = self.ps.cpu_times()
        return t.user + t.system

    def rss_mb(self):
        return self.ps.memory_info().rss / 2.0 ** 20


class Burst(object):
    """A ``bench_synth`` node publishing ``count`` perceptions at ``rate`` Hz while the block runs."""

    def __init__(self, procs, harness, count, rate, settle=0.5):
        self.procs, self.harness, self.count, self.rate, self.settle = procs, harness, count, rate, settle
        self.proc = None

    def __enter__(self):
        self.proc = self.procs.rosrun('bench_synth', 'rason_bench', 'bench_synth', count=self.count,
                                      rate=float(self.rate), source=BURST_SOURCE)
        try:
            self.harness.wait_heard(BURST_SOURCE, count=2 if self.rate >= 2 else 1, timeout=30.0)
        except Exception:
            self.procs.stop(self.proc)
            raise
        time.sleep(self.settle)  # the agents' node hears it too, and the burst is under way
        return self

    def __exit__(self, *exc):
        self.procs.stop(self.proc)


def measured_cycle(mas, agent, iterations):
    """One Listing 5.4 run: ms per iteration, and the node's CPU use (% of one core) meanwhile."""
    cpu0, t0 = mas.cpu_seconds(), time.monotonic()
    c = mas.harness.cycle(agent, iterations, timeout=max(120.0, iterations * 0.05))
    cpu = 100.0 * (mas.cpu_seconds() - cpu0) / (time.monotonic() - t0)
    return {'ms': c.ms / c.iterations, 'cpu_percent': cpu}


def calibrate(mas, agent, seconds, log, min_seconds=10.0, max_seconds=60.0):
    """Warm the JIT up (runs of about a second for at least ``min_seconds``, then until two in
    a row agree within 5 %, at most ``max_seconds``), then the iteration count that makes one
    run last about ``seconds``."""
    n, previous, per_iteration = 2000, None, None
    start = time.monotonic()
    while time.monotonic() < start + max_seconds:
        per_iteration = mas.harness.cycle(agent, n, timeout=120.0).ms / n
        if previous is not None and abs(per_iteration - previous) <= 0.05 * previous \
                and time.monotonic() > start + min_seconds:
            break
        previous = per_iteration
        n = max(2000, int(1000.0 / per_iteration))
    iterations = max(2000, int(seconds * 1000.0 / per_iteration))
    log('  warm: %.4f ms per iteration -> %d iterations per run' % (per_iteration, iterations))
    return iterations


def cycle_tables(procs, harness, modes, perceptions, rates, seconds, log, repeats=3):
    """Per mode, one cell per perceptions x rate. A cell is ``repeats`` runs under the burst
    (their median) bracketed by a baseline run before and after it (no traffic, same agent,
    same JVM; their mean), so that drifts of a shared machine cancel and one slow run (GC,
    another process) does not decide the cell."""
    out = {}
    for mode in modes:
        log('cycle time, perception_manager=%s' % mode)
        with Mas(procs, harness, 'bench.mas2j', mode) as mas:
            agent = mas.agents[0]
            iterations = calibrate(mas, agent, seconds, log)
            cells = []
            for p in perceptions:
                for r in rates:
                    before = measured_cycle(mas, agent, iterations)
                    with Burst(procs, harness, p, r):
                        runs = [measured_cycle(mas, agent, iterations) for _ in range(repeats)]
                    after = measured_cycle(mas, agent, iterations)
                    cell = stats.median_run(runs)
                    cell.update(perceptions=p, rate_hz=r, runs_ms=[x['ms'] for x in runs],
                                baseline_ms=(before['ms'] + after['ms']) / 2.0,
                                baseline_cpu_percent=(before['cpu_percent'] + after['cpu_percent']) / 2.0)
                    cells.append(cell)
                    log('  %2d perceptions x %2g Hz: %.4f ms (baseline %.4f ms, %.2fx), node CPU %.0f%%'
                        % (p, r, cell['ms'], cell['baseline_ms'], cell['ms'] / cell['baseline_ms'],
                           cell['cpu_percent']))
        out[mode] = {'iterations': iterations, 'repeats': repeats, 'cells': cells}
    return out


def latencies(procs, harness, pings, stamps, stamp_period, log):
    """Action round trips and perception -> belief event times (ms), with the agent idle and
    while a 10 x 50 Hz burst runs."""
    out = {}
    with Mas(procs, harness, 'bench.mas2j') as mas:
        agent = mas.agents[0]
        harness.pings(agent, 50, timeout=60.0)  # warm up
        harness.stamps(20, stamp_period, timeout=30.0)
        for load in ('idle', 'burst'):
            with Burst(procs, harness, 10, 50) if load == 'burst' else contextlib.nullcontext():
                rtt = harness.pings(agent, pings, timeout=60.0 + pings * 0.1)
                seen = harness.stamps(stamps, stamp_period, timeout=30.0)
            out[load] = {'action_round_trip_ms': stats.summarize(rtt),
                         'perception_to_belief_ms': stats.summarize(seen), 'stamps_sent': stamps,
                         'action_round_trip_samples': [round(x, 3) for x in rtt],
                         'perception_to_belief_samples': [round(x, 3) for x in seen]}
            log('  %s: action round trip p50 %.2f p99 %.2f ms; perception -> belief p50 %.2f p99 %.2f ms'
                ' (%d of %d stamps seen)' % (load, out[load]['action_round_trip_ms']['p50'],
                                             out[load]['action_round_trip_ms']['p99'],
                                             out[load]['perception_to_belief_ms']['p50'],
                                             out[load]['perception_to_belief_ms']['p99'], len(seen), stamps))
    return out


#: Burst before the CPU windows: the JVM's C2 compiler is still compiling the perception path's
#: large methods (the parser, Jason's belief update and deliberation) 15-25 s into a burst, at
#: about a third of a core; a node that runs for hours pays that once.
CPU_WARM_S = 30.0


def node_cpu_per_message(procs, harness, window, log, count=10, rate=50, windows=3, warm=CPU_WARM_S):
    """CPU time (user + sys) of the rason_mas process per perception message of a ``count``
    literals x ``rate`` Hz burst, less its idle CPU use: the median of ``windows`` windows of
    ``window`` s, for the Listing 5.4 agent (a plan with a .print per literal), for the same
    plans without the .print (what the printed lines cost is the difference) and for an
    agent without perception plans (the bridge and the belief updates only). The messages are
    those the harness heard from the burst meanwhile (the node subscribes to the same topic)."""
    out = {}
    for label, mas2j in (('listing_5_4', 'bench.mas2j'), ('no_print', 'silent.mas2j'), ('no_plans', 'quiet.mas2j')):
        with Mas(procs, harness, mas2j) as mas:
            with Burst(procs, harness, count, rate):  # the JIT compiles the perception path (CPU_WARM_S)
                time.sleep(warm)
            time.sleep(1.0)
            idle = [_cpu_window(mas, harness, window)]
            with Burst(procs, harness, count, rate):
                runs = [_cpu_window(mas, harness, window) for _ in range(windows)]
            time.sleep(1.0)
            idle.append(_cpu_window(mas, harness, window))
        idle_per_s = sum(r['cpu_s'] for r in idle) / sum(r['wall_s'] for r in idle)
        for r in runs:
            r['us_per_message'] = stats.cpu_per_message_us(r['cpu_s'], r['wall_s'], idle_per_s, r['messages'])
        measured = [r['us_per_message'] for r in runs if r['us_per_message'] is not None]
        row = {'literals_per_message': count, 'rate_hz': rate, 'window_s': window,
               'idle_cpu_percent': 100.0 * idle_per_s, 'runs': runs,
               'us_per_message': stats.median(measured) if measured else None,
               'cpu_percent': 100.0 * sum(r['cpu_s'] for r in runs) / sum(r['wall_s'] for r in runs)}
        out[label] = row
        log('  %s: %s µs CPU per message (%d literals x %g Hz; node CPU %.0f%%, idle %.1f%%)'
            % (label, '%.0f' % row['us_per_message'] if measured else 'no messages: no', count, rate,
               row['cpu_percent'], row['idle_cpu_percent']))
    return out


def _cpu_window(mas, harness, seconds):
    """CPU seconds of the node, wall seconds, and burst messages heard over ``seconds``."""
    cpu0, heard0, t0 = mas.cpu_seconds(), harness.heard(BURST_SOURCE), time.monotonic()
    time.sleep(seconds)
    cpu1, heard1, t1 = mas.cpu_seconds(), harness.heard(BURST_SOURCE), time.monotonic()
    return {'cpu_s': cpu1 - cpu0, 'wall_s': t1 - t0, 'messages': heard1 - heard0}


def reaction(procs, harness, count, period, spinners, log):
    """Perception -> action: the harness publishes trigger(Run, Seq, Stamp), the agent's plan
    acts react(Run, Seq, Stamp) at once, the harness times its arrival (ms). Idle, and under
    load: a 10 x 50 Hz burst and ``spinners`` busy intentions in the same agent."""
    out = {}
    with Mas(procs, harness, 'bench.mas2j') as mas:
        agent = mas.agents[0]
        harness.triggers(20, period, timeout=30.0)  # warm up
        timeout = 60.0 + count * period
        out['idle'] = _reaction_row(harness.triggers(count, period, timeout), count)
        with Burst(procs, harness, 10, 50):
            cpu0, t0 = mas.cpu_seconds(), time.monotonic()
            run = harness.spin(agent, spinners)
            samples = harness.triggers(count, period, timeout)
            turns = harness.stop_spin(agent, run, spinners, timeout=60.0)
            wall = time.monotonic() - t0
            cpu = 100.0 * (mas.cpu_seconds() - cpu0) / wall
        out['load'] = _reaction_row(samples, count)
        out['load'].update(busy_intentions=spinners, burst='10 x 50 Hz', cpu_percent=cpu,
                           busy_turns_per_s=sum(turns) / wall, busy_intentions_reported=len(turns))
    for load in ('idle', 'load'):
        s = out[load]['reaction_ms']
        log('  %s: reaction p50 %.2f p99 %.2f ms (%d of %d triggers)'
            % (load, s.get('p50', float('nan')), s.get('p99', float('nan')), s['n'], count))
    log('  busy intentions: %d, %.0f turns/s in all; node CPU %.0f%%'
        % (spinners, out['load']['busy_turns_per_s'], out['load']['cpu_percent']))
    return out


def _reaction_row(samples, sent):
    return {'reaction_ms': stats.summarize(samples), 'triggers_sent': sent,
            'reaction_samples': [round(x, 3) for x in samples]}


def scale(procs, harness, counts, seconds, iterations, log):
    """Per agent count: CPU and memory of the node while every agent hears 10 perceptions at
    10 Hz (and, before, with no traffic), and the Listing 5.4 time of one agent meanwhile."""
    projects = {1: 'bench.mas2j', 10: 'bench10.mas2j', 100: 'bench100.mas2j'}
    out = []
    for n in counts:
        with Mas(procs, harness, projects[n]) as mas:
            agent = sorted(mas.agents)[0]
            row = {'agents': n, 'rss_mb_start': mas.rss_mb()}
            calibrate(mas, agent, 0.1, lambda _line: None)  # warm up only
            row['baseline_ms'] = measured_cycle(mas, agent, iterations)['ms']
            row['idle_cpu_percent'] = _cpu_over(mas, seconds)
            with Burst(procs, harness, 10, 10, settle=1.0):
                row['cpu_percent'] = _cpu_over(mas, seconds)
                row['ms'] = measured_cycle(mas, agent, iterations)['ms']
                row['rss_mb'] = mas.rss_mb()
        log('  %3d agents: node CPU %.0f%% (idle %.0f%%), RSS %.0f MB, cycle %.4f ms (baseline %.4f)'
            % (n, row['cpu_percent'], row['idle_cpu_percent'], row['rss_mb'], row['ms'], row['baseline_ms']))
        out.append(row)
    return out


def _cpu_over(mas, seconds):
    cpu0, t0 = mas.cpu_seconds(), time.monotonic()
    time.sleep(seconds)
    return 100.0 * (mas.cpu_seconds() - cpu0) / (time.monotonic() - t0)


def preemption(procs, harness, rounds, control_rate, log, warmup=5, max_delay=0.1, seed=1):
    """``rounds`` take-backs (after ``warmup`` unrecorded ones) by the agent of
    ``preempt.mas2j``, with ``motion_decomp`` at ``control_rate`` Hz and ``bench_base`` at 50 Hz.

    A round: the agent starts ``move(3)``; once a non-zero twist is heard on ``cmd_vel``
    and a further random 0..``max_delay`` s have passed (so take-backs fall anywhere in a
    control period), the agent is asked to take it back; the round ends when the zero twist,
    the ``.cancel`` on ``jason/action`` and the agent's ``took_back(T)`` have all been heard.
    Returns the summaries (ms) and samples of take-back -> zero twist, take-back -> cancel
    heard, cancel -> zero twist.
    """
    from rason_bench.harness import MotionWatch
    rng = random.Random(seed)
    base = procs.rosrun('bench_base', 'rason_bench', 'bench_base', rate=50.0)
    decomp = procs.rosrun('motion_decomp', 'motion_decomp', 'motion_decomp_node', rate=float(control_rate))
    watch = MotionWatch()
    samples = {'stop_ms': [], 'cancel_ms': [], 'cancel_to_stop_ms': []}
    ended_early = 0
    try:
        watch.wait_publisher(60.0)
        with Mas(procs, harness, 'preempt.mas2j') as mas:
            agent = mas.agents[0]
            started = time.monotonic()
            for i in range(warmup + rounds):
                run = harness.next_run()
                rnd = watch.start_round()
                since = time.monotonic()
                harness.control(protocol.go_move(agent, run, i))
                _, move_id = harness.noted_action(agent, 'move', since, 30.0)
                watch.wait(lambda r: r.under_way is not None, 30.0, 'motion on cmd_vel')
                time.sleep(rng.uniform(0.0, max_delay))
                sent = time.monotonic()
                harness.control(protocol.take_back(agent, run, i))
                took_back = harness.reports(protocol.TookBack, run, 1, 30.0)[0]
                cancel_seen, _ = harness.noted_action(agent, Action.CANCEL, since, 30.0, action_id=move_id)
                watch.wait(lambda r: r.stopped is not None, 30.0, 'zero twist on cmd_vel')
                if preempt.stopped_on_its_own(rnd, sent):
                    ended_early += 1
                    log('  round %d: the motion stopped before the take-back; not counted' % i)
                    continue
                if i < warmup:
                    continue
                for key, value in preempt.round_latencies(took_back.ms, rnd.stopped, cancel_seen).items():
                    samples[key].append(value)
            seconds = time.monotonic() - started
    finally:
        watch.close()
        procs.stop(decomp)
        procs.stop(base)
    out = {key: stats.summarize(values) for key, values in samples.items()}
    out.update({'take_backs': rounds, 'warmup': warmup, 'ended_early': ended_early,
                'control_rate_hz': control_rate, 'base_rate_hz': 50.0, 'max_delay_s': max_delay,
                'seconds': round(seconds, 1),
                'samples': {key: [round(x, 3) for x in values] for key, values in samples.items()}})
    log('  %d take-backs in %.0f s: take-back -> zero twist p50 %.2f p99 %.2f ms; take-back -> cancel'
        ' heard p50 %.2f p99 %.2f ms' % (len(samples['stop_ms']), seconds, out['stop_ms'].get('p50', 0),
                                         out['stop_ms'].get('p99', 0), out['cancel_ms'].get('p50', 0),
                                         out['cancel_ms'].get('p99', 0)))
    return out
