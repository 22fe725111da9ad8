"""What the benchmark agent (agents/bench.asl) and the harness say to each other.

The harness starts a measurement with a control percept; the agent answers with
actions whose parameters carry the results (the harness is their decomposer and
acknowledges each with ``OK``). Action parameters arrive as text, numbers plainly.
"""
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

_REPORTS = {'cycle': (Cycle, (int, int, float)), 'rtt': (RoundTrip, (int, int, float)),
            'seen': (Seen, (int, int, float)), 'took_back': (TookBack, (int, int, float))}

#: Source of the harness's control percepts.
CONTROL_SOURCE = 'bench_control'
#: Source of the latency stamps.
STAMP_SOURCE = 'bench_stamp'


class BadReport(ValueError):
    """An action from the agent that is not a well-formed report."""


def parse_report(action, parameters):
    """A report action as a Cycle, RoundTrip, Seen or TookBack; None for actions that are not reports.

    :raises BadReport: a report with the wrong number or kind of parameters
    """
    kind = _REPORTS.get(action)
    if kind is None:
        return None
    cls, types = kind
    if len(parameters) != len(types):
        raise BadReport('%s needs %d parameters, got %r' % (action, len(types), list(parameters)))
    try:
        return cls(*[t(float(p)) if t is int else t(p) for t, p in zip(types, parameters)])
    except ValueError:
        raise BadReport('%s: parameters %r are not numbers' % (action, list(parameters)))


def go_cycle(agent, run, iterations):
    """Control percept: ``agent`` runs the loop ``iterations`` times and reports ``cycle``."""
    return 'go_cycle(%s,%d,%d)' % (agent, run, iterations)


def go_ping(agent, run, count):
    """Control percept: ``agent`` acts ``ping`` ``count`` times, reporting each round trip."""
    return 'go_ping(%s,%d,%d)' % (agent, run, count)


def go_move(agent, run, index):
    """Control percept: ``agent`` starts round ``index``'s ``move(3)`` (agents/preempt.asl)."""
    return 'go_move(%s,%d,%d)' % (agent, run, index)


def take_back(agent, run, index):
    """Control percept: ``agent`` drops round ``index``'s motion and reports ``took_back``."""
    return 'take_back(%s,%d,%d)' % (agent, run, index)


def stamp(run, seq, now_ms):
    """Latency percept: published at ``now_ms`` on the monotonic clock."""
    return 'stamp(%d,%d,%.3f)' % (run, seq, now_ms)


def burst(count, seq):
    """What the synthesizer-like node publishes: ``perception1(Seq)`` .. ``perceptionN(Seq)``,
    every literal new in every message, as a synthesizer's readings are."""
    return ['perception%d(%d)' % (k, seq) for k in range(1, count + 1)]
