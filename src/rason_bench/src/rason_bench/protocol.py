"""What the benchmark agent (agents/bench.asl) and the harness say to each other.

The harness starts a measurement with a control percept; the agent answers with
actions whose parameters carry the results (the harness is their decomposer and
acknowledges each with ``OK``). Action parameters arrive as text, numbers plainly.
"""
import math
from collections import namedtuple

#: ``cycle(Run, Iterations, Ms)``: the thesis loop of Listing 5.4 ran Iterations times in Ms.
Cycle = namedtuple('Cycle', 'run iterations ms')
#: ``rtt(Run, I, Ms)``: the I-th ``ping`` action took Ms from act to the intention resumed.
RoundTrip = namedtuple('RoundTrip', 'run index ms')
#: ``seen(Run, Seq, Ms)``: the percept stamp(Run, Seq, T) reached a plan Ms after T.
Seen = namedtuple('Seen', 'run seq ms')
#: ``took_back(Run, I, T)``: the agent took round I's motion back at T (``rason.time_ms``,
#: read right before ``.drop_intention``).
TookBack = namedtuple('TookBack', 'run index ms')

#: ``react(Run, Seq, Stamp)``: the agent's action for the percept trigger(Run, Seq, Stamp);
#: the harness times it on arrival (:func:`reaction`).
Reacted = namedtuple('Reacted', 'run seq stamp_ms')
#: Publish -> action arrival of one trigger, in ms (made by the harness from a Reacted).
Reaction = namedtuple('Reaction', 'run seq ms')
#: ``spinning(Run, N)``: the agent started N busy intentions.
Spinning = namedtuple('Spinning', 'run count')
#: ``spun(Run, I, K)``: busy intention I ended after K turns.
Spun = namedtuple('Spun', 'run index turns')
#: ``ticked(Run, Agent, Seq, Ms)``: the update tick(Run, Seq) reached Agent's plan at Ms
#: (the agent's rason.time_ms).
Ticked = namedtuple('Ticked', 'run agent seq ms')
#: ``marked(Run, K, Stamp)``: the agent's action for the flood mark flood_mark(Run, K, Stamp)
#: (agents/hostile.asl); the harness times it on arrival (:func:`mark_seen`).
Marked = namedtuple('Marked', 'run mark stamp_ms')
#: Publish of a flood mark -> the agent's action for it arriving, in ms (made by the harness).
MarkSeen = namedtuple('MarkSeen', 'run mark ms')
#: ``started(Run, Ms)``: the agent's first reasoning cycle ran at Ms (``rason.time_ms``;
#: agents/startup.asl).
Started = namedtuple('Started', 'run ms')

_REPORTS = {'cycle': (Cycle, (int, int, float)), 'rtt': (RoundTrip, (int, int, float)),
            'seen': (Seen, (int, int, float)), 'react': (Reacted, (int, int, float)),
            'spinning': (Spinning, (int, int)), 'spun': (Spun, (int, int, int)),
            'ticked': (Ticked, (int, str, int, float)), 'took_back': (TookBack, (int, int, float)),
            'marked': (Marked, (int, int, float)), 'started': (Started, (int, float))}

#: Source of the harness's control percepts.
CONTROL_SOURCE = 'bench_control'
#: Source of the latency stamps.
STAMP_SOURCE = 'bench_stamp'
#: Sources of the reaction triggers, taken in turn (:func:`trigger_source`).
TRIGGER_SOURCES = 10
#: Source of the rate-limit ticks.
TICK_SOURCE = 'bench_tick'


class BadReport(ValueError):
    """An action from the agent that is not a well-formed report."""


def parse_report(action, parameters):
    """A report action as one of the tuples above; None for actions that are not reports.

    :raises BadReport: a report with the wrong number or kind of parameters
    """
    kind = _REPORTS.get(action)
    if kind is None:
        return None
    cls, types = kind
    if len(parameters) != len(types):
        raise BadReport('%s needs %d parameters, got %r' % (action, len(types), list(parameters)))
    try:
        return cls(*[_int(p) if t is int else t(p) for t, p in zip(types, parameters)])
    except ValueError:
        raise BadReport('%s: parameters %r are not numbers' % (action, list(parameters)))


def _int(text):
    value = float(text)
    if not math.isfinite(value) or value != int(value):
        raise ValueError(text)
    return int(value)


def reaction(reacted, received_ms):
    """The Reaction of a Reacted that arrived at ``received_ms`` (same clock as its stamp)."""
    return Reaction(reacted.run, reacted.seq, received_ms - reacted.stamp_ms)


def mark_seen(marked, received_ms):
    """The MarkSeen of a Marked that arrived at ``received_ms`` (same clock as its stamp)."""
    return MarkSeen(marked.run, marked.mark, received_ms - marked.stamp_ms)


def go_cycle(agent, run, iterations):
    """Control percept: ``agent`` runs the loop ``iterations`` times and reports ``cycle``."""
    return 'go_cycle(%s,%d,%d)' % (agent, run, iterations)


def go_ping(agent, run, count):
    """Control percept: ``agent`` acts ``ping`` ``count`` times, reporting each round trip."""
    return 'go_ping(%s,%d,%d)' % (agent, run, count)


def go_started(agent, run):
    """Control percept: ``agent`` reports when its first reasoning cycle ran (``started``)."""
    return 'go_started(%s,%d)' % (agent, run)


def go_spin(agent, run, count):
    """Control percept: ``agent`` starts ``count`` busy intentions; they turn while it lasts
    (the next control percept replaces it) and then report ``spun``."""
    return 'go_spin(%s,%d,%d)' % (agent, run, count)


def stop_spin(agent, run):
    """Control percept replacing go_spin: the busy intentions end."""
    return 'stop_spin(%s,%d)' % (agent, run)


def trigger(run, seq, now_ms):
    """Reaction percept, published at ``now_ms``: the agent acts ``react`` for it at once."""
    return 'trigger(%d,%d,%.3f)' % (run, seq, now_ms)


def trigger_source(seq):
    """The source of trigger ``seq``: one of TRIGGER_SOURCES in turn, so that with per-source
    replacement a trigger is replaced only TRIGGER_SOURCES triggers later. A late agent then
    shows as a late reaction, not as a trigger it never perceived."""
    return 'bench_trigger_%d' % (seq % TRIGGER_SOURCES)


def tick(run, seq):
    """Rate-limit percept: the agents report each update that reaches them."""
    return 'tick(%d,%d)' % (run, seq)
def go_move(agent, run, index):
    """Control percept: ``agent`` starts round ``index``'s ``move(3)`` (agents/preempt.asl)."""
    return 'go_move(%s,%d,%d)' % (agent, run, index)


def take_back(agent, run, index):
    """Control percept: ``agent`` drops round ``index``'s motion and reports ``took_back``."""
    return 'take_back(%s,%d,%d)' % (agent, run, index)


def stamp(run, seq, now_ms):
    """Latency percept: published at ``now_ms`` on the monotonic clock."""
    return 'stamp(%d,%d,%.3f)' % (run, seq, now_ms)


#: The mark of a flood's very last message (the marks before it count from 1).
FINAL_MARK = 0


def flood_mark(run, mark, stamp_ms):
    """Flood percept: mark ``mark`` of run ``run``, first published at ``stamp_ms``; every
    message of the flood carries the current mark, so coalescing cannot hide a new one."""
    return 'flood_mark(%d,%d,%.3f)' % (run, mark, stamp_ms)


def burst(count, seq):
    """What the synthesizer-like node publishes: ``perception1(Seq)`` .. ``perceptionN(Seq)``,
    every literal new in every message, as a synthesizer's readings are."""
    return ['perception%d(%d)' % (k, seq) for k in range(1, count + 1)]
