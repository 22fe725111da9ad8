"""``--only hostile``: the agents' node under hostile input (issue 13).

1. :func:`reaction_after_inputs`: twice, each hostile input of :mod:`rason_tools.hostile` (deep
   and huge terms, too many literals, non-finite numbers, reserved annotations, malformed text,
   bad events, 200 agent names of 1 MB, 300 source names), then at once trigger percepts
   on the same topic behind it: perception -> the agent's action, in ms (the agent still
   answers); the node's RSS before and after each input.
2. :func:`flood`: ``bench_synth`` floods one source (``rate`` Hz x ``count`` literals for
   ``seconds``), every message carrying the current flood mark (a new one each second) and the
   last one a final mark; the agent acts on each new mark it perceives, so the harness times
   publish -> action for the marks during the flood and for the newest perception at its end.
   The node's RSS before, at its peak and ``after`` s after the flood. The harness stops
   reading jason/perception meanwhile (a rospy process at 1000 x 50 literals a second, or
   with 1 MB literals, would time the agent less well).
"""
import threading
import time

from rason_msgs.msg import Event, Perception

from rason_bench import protocol, stats
from rason_bench.experiments import Burst, Mas
from rason_tools import hostile as inputs

FLOOD_SOURCE = 'bench_flood'
#: Triggers after each hostile input (perception -> action), one every TRIGGER_PERIOD s.
TRIGGERS_PER_INPUT = 5
TRIGGER_PERIOD = 0.02
#: Before measuring, the inputs part warms the node up with WARM_S s of a burst of the flood's
#: shape at WARM_RATE_HZ (the JIT compiles the perception path, the libraries' pages are read
#: in: a cold node's first growth is not what hostile input leaves behind), then waits SETTLE_S s.
WARM_S, WARM_RATE_HZ, SETTLE_S = 5.0, 50, 3.0
#: The flood part's warm-up is a short flood of the same kind (FLOOD_WARM_S s): the node has
#: met a flood before, and given back what it grew when it ended (rason_bridge.jvm), when
#: its RSS before is read SETTLE_S s later. (After a slower warm-up the heap it grew stays
#: until G1's 30 s idle collection, which young collections keep putting off.)
FLOOD_WARM_S = 5.0
#: perception_ttl of the inputs part's node: the trigger sources, heard before, must still be
#: known after 300 new source names (a new source is refused while max_sources others
#: were heard within the TTL), even when sending a case takes a few seconds.
INPUTS_PERCEPTION_TTL = 10.0


class RssSampler(object):
    """Samples a process's RSS (MB) every ``period`` s in a thread while the block runs."""

    def __init__(self, mas, period=0.1):
        self.mas, self.period = mas, period
        self.samples = []  # (time.monotonic, MB)
        self._stop = threading.Event()
        self._thread = threading.Thread(target=self._run, daemon=True)

    def _run(self):
        while not self._stop.is_set():
            try:
                self.samples.append((time.monotonic(), self.mas.rss_mb()))
            except Exception:  # the process ended: nothing more to sample
                return
            self._stop.wait(self.period)

    def __enter__(self):
        self._thread.start()
        return self

    def __exit__(self, *exc):
        self._stop.set()
        self._thread.join(5.0)

    def peak(self):
        return max(mb for _, mb in self.samples) if self.samples else None


def _triggers(harness):
    return harness.triggers(TRIGGERS_PER_INPUT, TRIGGER_PERIOD, timeout=30.0)


def reaction_after_inputs(procs, harness, log, seed=13, rounds=2):
    """``rounds`` times every hostile input in turn; per input and round: perception ->
    action (ms) of the triggers right behind it, how long sending it took, and the node's RSS
    before and after. (The first round also shows what the JIT costs the first time a node
    meets messages of these sizes; the second, what the input itself costs.)"""
    out = {'seed': seed, 'triggers_per_input': TRIGGERS_PER_INPUT, 'perception_ttl_s': INPUTS_PERCEPTION_TTL,
           'rounds': []}
    with Mas(procs, harness, 'hostile.mas2j', perception_ttl=INPUTS_PERCEPTION_TTL) as mas:
        agent = mas.agents[0]
        _warm_up(procs, harness)
        out['rss_mb_start'] = mas.rss_mb()
        harness.hear(False)
        try:
            _rounds(harness, mas, agent, seed, rounds, out, log)
        finally:
            harness.hear(True)
        out['rss_mb_end'] = mas.rss_mb()
    return out


def _rounds(harness, mas, agent, seed, rounds, out, log):
    """Every input in turn, ``rounds`` times, into out['rounds']."""
    for r in range(rounds):
        done = {}
        for case in inputs.cases(seed):
            rss0 = mas.rss_mb()
            t0 = time.monotonic()
            _send(harness, case, agent)
            sent_s = time.monotonic() - t0
            samples = _triggers(harness)
            row = {'reaction_ms': stats.summarize(samples), 'send_s': round(sent_s, 2),
                   'rss_mb_before': rss0, 'rss_mb_after': mas.rss_mb(),
                   'reaction_samples': [round(x, 3) for x in samples]}
            done[case.name] = row
            log('  round %d, %-17s sent in %5.2f s, then perception -> action max %6.1f ms (%d of %d); '
                'RSS %.0f -> %.0f MB' % (r + 1, case.name, sent_s, row['reaction_ms'].get('max', float('nan')),
                                        row['reaction_ms']['n'], TRIGGERS_PER_INPUT, rss0, row['rss_mb_after']))
        out['rounds'].append(done)


def _send(harness, case, agent):
    for source, literals in case.perceptions:
        harness.publish_perception(Perception(source=source, perception=literals))
    for name, event_type, parameters in case.events:
        harness.publish_event(Event(agent=agent if name is None else name, event_type=event_type,
                                    parameters=parameters))


def _warm_up(procs, harness, literals=50, rate=WARM_RATE_HZ, seconds=WARM_S):
    with Burst(procs, harness, literals, rate):
        time.sleep(seconds)
    harness.triggers(20, TRIGGER_PERIOD, timeout=30.0)
    time.sleep(SETTLE_S)


def _published(param, timeout=10.0):
    """The count bench_synth leaves on its ~published when its flood is over; None if it did not."""
    import rospy
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        if rospy.has_param(param):
            value = rospy.get_param(param)
            rospy.delete_param(param)
            return value
        time.sleep(0.1)
    return None


def flood(procs, harness, seconds, rate, count, after, log, mark_period=1.0):
    """A ``seconds`` flood of ``rate`` Hz x ``count`` literals from one source: publish ->
    action (ms) of the newest perception (the flood's last message) and of the marks during
    it; the node's RSS before, at its peak and ``after`` s after the flood; its CPU time."""
    out = {'seconds': seconds, 'rate_hz': rate, 'literals': count, 'mark_period_s': mark_period,
           'after_s': after}
    with Mas(procs, harness, 'hostile.mas2j') as mas:
        _warm_up(procs, harness, count, rate, FLOOD_WARM_S)
        out['rss_mb_before'] = mas.rss_mb()
        cpu0 = mas.cpu_seconds()
        run = harness.next_run()
        harness.hear(False)
        with RssSampler(mas) as rss:
            t0 = time.monotonic()
            synth = procs.rosrun('bench_flood', 'rason_bench', 'bench_synth', count=count, rate=float(rate),
                                 source=FLOOD_SOURCE, duration=float(seconds), mark_period=float(mark_period),
                                 run=run)
            try:
                marks = harness.reports(protocol.MarkSeen, run, 10 ** 6, timeout=seconds + 120.0,
                                        done=lambda r: r.mark == protocol.FINAL_MARK)
                out['flood_wall_s'] = round(time.monotonic() - t0, 2)
                out['messages_published'] = _published('/bench_flood/published')
            finally:
                procs.stop(synth)
                harness.hear(True)
            out['cpu_s'] = mas.cpu_seconds() - cpu0
            time.sleep(after)
        out['rss_mb_peak'] = rss.peak()
        out['rss_mb_after'] = mas.rss_mb()
        out['rss_samples'] = [(round(t - t0, 1), round(mb, 1)) for t, mb in rss.samples[::5]]
        final = [m.ms for m in marks if m.mark == protocol.FINAL_MARK]
        during = [m.ms for m in marks if m.mark != protocol.FINAL_MARK]
        out['newest_ms'] = final[0] if final else None
        out['marks_ms'] = stats.summarize(during)
        out['marks_samples'] = [(m.mark, round(m.ms, 2)) for m in marks]
        out['reaction_after_ms'] = stats.summarize(_triggers(harness))
    log('  %g s x %g Hz x %d literals (%s messages published): newest perception -> action %s ms; '
        'marks during it p50 %s, max %s ms'
        % (seconds, rate, count, out['messages_published'],
           '%.1f' % out['newest_ms'] if out['newest_ms'] is not None else '-',
           '%.1f' % out['marks_ms']['p50'] if out['marks_ms']['n'] else '-',
           '%.1f' % out['marks_ms']['max'] if out['marks_ms']['n'] else '-'))
    log('  RSS before %.0f MB, peak %.0f MB, %g s after %.0f MB; node CPU %.1f s'
        % (out['rss_mb_before'], out['rss_mb_peak'] or 0, after, out['rss_mb_after'], out['cpu_s']))
    return out
