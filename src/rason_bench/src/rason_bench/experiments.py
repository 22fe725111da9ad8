"""The benchmarks of ``make bench``, each against its own rason_mas process.

1. :func:`cycle_tables`: thesis Tables 5.1/5.2, the Listing 5.4 loop under bursts from
   ``bench_synth``, per perception manager, with baselines (no traffic) in the same JVM.
2. :func:`latencies`: action round trip and perception -> belief event, idle and under a burst.
3. :func:`scale`: 1, 10, 100 agents in one process hearing 10 perceptions at 10 Hz.
4. :func:`preemption`: an agent takes its ``move`` back; time to the zero twist of the real
   ``motion_decomp`` node on ``cmd_vel`` (a stand-in base, ``bench_base``, gives it odometry).
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

    def __init__(self, procs, harness, mas2j, perception_manager='per_source'):
        self.procs = procs
        self.harness = harness
        if rospy.has_param('/rason_mas/agents'):  # left by the previous run's node
            rospy.delete_param('/rason_mas/agents')
        self.proc = procs.rosrun('rason_mas', 'rason_bridge', 'rason_mas', agents_file(mas2j),
                                 perception_manager=perception_manager)
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
                    cell = median_run(runs)
                    cell.update(perceptions=p, rate_hz=r, runs_ms=[x['ms'] for x in runs],
                                baseline_ms=(before['ms'] + after['ms']) / 2.0,
                                baseline_cpu_percent=(before['cpu_percent'] + after['cpu_percent']) / 2.0)
                    cells.append(cell)
                    log('  %2d perceptions x %2g Hz: %.4f ms (baseline %.4f ms, %.2fx), node CPU %.0f%%'
                        % (p, r, cell['ms'], cell['baseline_ms'], cell['ms'] / cell['baseline_ms'],
                           cell['cpu_percent']))
        out[mode] = {'iterations': iterations, 'repeats': repeats, 'cells': cells}
    return out


def median_run(runs):
    """The run with the median time (an odd count gives a run that happened)."""
    ordered = sorted(runs, key=lambda x: x['ms'])
    return dict(ordered[len(ordered) // 2])


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
