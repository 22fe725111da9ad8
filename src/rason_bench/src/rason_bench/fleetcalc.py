"""The fleet part's arithmetic (pure): reading what the processes print, tail latency with
lost messages, the search for the message rate where p99 passes its bound, departure
delays and false departures scaled to a common period."""
import math
import re

from rason_bench import stats

#: ``[alice] rtt 17 3.254``: one achieve round trip of the pinging agent (agents/fleet.asl), ms.
RTT = re.compile(r'\[(?P<agent>\w+)\] rtt (?P<seq>\d+) (?P<ms>[-0-9.Ee+]+)')
#: ``[watcher] absent sim7 1234.5`` / ``present``: the observer's presence beliefs, with its clock (ms).
PRESENCE = re.compile(r'\[(?P<agent>\w+)\] (?P<what>present|absent) (?P<robot>\w+) (?P<ms>[-0-9.Ee+]+)')
#: ``killed 7 1234.5``: SimulatedFleet ended robot 7's connection at that time (ms).
KILLED = re.compile(r'^killed (?P<index>\d+) (?P<ms>[-0-9.Ee+]+)$')
#: ``load RUN RATE SENT SEND_SECONDS ms ms ...``: one load run of SimulatedFleet.
LOAD = re.compile(r'^load (?P<run>\d+) (?P<rate>[0-9.Ee+]+) (?P<sent>\d+) (?P<seconds>[0-9.]+)(?P<ms>( [-0-9.]+)*)$')


def round_trips(lines, agent, warmup, count):
    """The round trips (ms) of ``agent`` among ``lines``, in order of their sequence number,
    leaving out the first ``warmup``; at most ``count``."""
    found = {}
    for line in lines:
        m = RTT.search(line)
        if m and m.group('agent') == agent:
            found[int(m.group('seq'))] = float(m.group('ms'))
    ordered = [found[k] for k in sorted(found) if k >= warmup]
    return ordered[:count]


def load_run(line):
    """A SimulatedFleet ``load`` line as a dict (rate asked, sent, the rate achieved, answer
    times in ms), or None if it is not one."""
    m = LOAD.match(line.strip())
    if not m:
        return None
    sent, seconds = int(m.group('sent')), float(m.group('seconds'))
    ms = [float(x) for x in m.group('ms').split()]
    return {'run': int(m.group('run')), 'rate': float(m.group('rate')), 'sent': sent, 'answered': len(ms),
            'send_seconds': seconds, 'achieved_rate': sent / seconds if seconds > 0 else None, 'ms': ms}


def tail_ms(answered_ms, sent, p):
    """The p-th percentile of the latencies of ``sent`` messages of which ``answered_ms`` were
    answered: an unanswered one counts as slower than any answered, so the result is
    infinite when the percentile falls among them.

    :raises ValueError: nothing sent, or more answers than messages
    """
    if sent <= 0 or len(answered_ms) > sent:
        raise ValueError('%d answers of %d messages' % (len(answered_ms), sent))
    rank = (sent - 1) * p / 100.0
    if math.ceil(rank) >= len(answered_ms):
        return math.inf
    ordered = sorted(answered_ms)
    low = int(math.floor(rank))
    return ordered[low] + (ordered[min(low + 1, len(ordered) - 1)] - ordered[low]) * (rank - low)


class RateSearch(object):
    """Steps the offered rate up (each step ``factor`` times the last, from ``start``) until a
    step's p99 passes ``bound_ms`` or ``limit`` is passed, then halves the interval between
    the last rate within the bound and the first beyond it ``refinements`` times.

    Feed each step's p99 to :meth:`record`; :meth:`next_rate` is the rate to try next, or None
    when done. :attr:`highest_within` / :attr:`lowest_beyond`: the answer.
    """

    def __init__(self, start=500.0, factor=2.0, limit=16000.0, bound_ms=100.0, refinements=2):
        self.bound_ms, self.factor, self.limit, self.refinements = bound_ms, factor, limit, refinements
        self.steps = []  # (rate, p99)
        self.highest_within = None
        self.lowest_beyond = None
        self._next = float(start)

    def record(self, rate, p99_ms):
        self.steps.append((rate, p99_ms))
        if p99_ms <= self.bound_ms:
            if self.highest_within is None or rate > self.highest_within:
                self.highest_within = rate
        elif self.lowest_beyond is None or rate < self.lowest_beyond:
            self.lowest_beyond = rate
        self._next = self._choose()

    def _choose(self):
        if self.lowest_beyond is None:
            rate = self.steps[-1][0] * self.factor
            return rate if rate <= self.limit else None
        if self.highest_within is None:  # beyond the bound at the first rate: nothing to refine
            return None
        first_beyond = next(i for i, (_, p) in enumerate(self.steps) if p > self.bound_ms)
        if len(self.steps) - 1 - first_beyond >= self.refinements:
            return None
        middle = round((self.highest_within + self.lowest_beyond) / 2.0)
        return middle if self.highest_within < middle < self.lowest_beyond else None

    def next_rate(self):
        return self._next


def departure_delays(killed, absent):
    """{robot index: ms from its kill to the observer's departure notice} for each killed robot
    whose departure was noticed after its kill (the first such notice).

    :param killed: {index: ms of the kill}
    :param absent: [(robot index, ms of the notice)] in any order
    """
    out = {}
    for index, t_kill in killed.items():
        later = [t for i, t in absent if i == index and t >= t_kill]
        if later:
            out[index] = min(later) - t_kill
    return out


def absent_now(lines):
    """The robots whose last presence line among ``lines`` says absent."""
    last = {}
    for line in lines:
        m = PRESENCE.search(line)
        if m:
            last[m.group('robot')] = m.group('what')
    return {robot for robot, what in last.items() if what == 'absent'}


def per_period(count, seconds, period_s=600.0):
    """count events in ``seconds``, scaled to ``period_s`` (10 minutes)."""
    if seconds <= 0:
        raise ValueError('a window of %r s' % (seconds,))
    return count * period_s / seconds


def summary(samples):
    """:func:`stats.summarize` of samples (ms)."""
    return stats.summarize(samples)
