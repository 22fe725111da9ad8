"""The start barrier's decisions, on a clock the test moves."""
from rason_bridge.start_barrier import StartBarrier, hold


class Clock(object):
    def __init__(self):
        self.now = 0.0

    def __call__(self):
        return self.now

    def pause(self, seconds):
        self.now += seconds


def test_nothing_to_wait_for_is_not_active_and_logs_nothing():
    lines = []
    hold(StartBarrier([], 0, 30), lambda: (set(), 0), lines.append, lines.append, None, lambda: True)
    assert lines == []


def test_missing_names_each_agent_and_the_robots_short():
    b = StartBarrier(['bidder_a', 'bidder_b'], 2, 30)
    assert b.missing({'bidder_a'}, 1) == ['agent bidder_b', '1 of 2 other robots']
    assert b.missing({'bidder_a', 'bidder_b', 'me'}, 2) == []


def test_waits_until_the_agents_arrive_then_lets_go():
    clock = Clock()
    arrivals = {1.0: 'bidder_a', 3.0: 'bidder_b'}
    b = StartBarrier(['bidder_a', 'bidder_b'], 0, 30)
    present = lambda: ({name for at, name in arrivals.items() if clock.now >= at}, 0)
    info, warn = [], []
    hold(b, present, info.append, warn.append, clock.pause, lambda: True, clock=clock)
    assert 3.0 <= clock.now < 3.0 + 0.051
    assert warn == []
    assert info[0] == 'holding the agents until agents bidder_a, bidder_b are present (at most 30 s, ~await_timeout)'
    assert info[1].startswith('agents bidder_a, bidder_b present after 3.0')


def test_the_timeout_starts_the_agents_anyway_saying_what_is_missing():
    clock = Clock()
    info, warn = [], []
    hold(StartBarrier(['bidder_c'], 1, 2.0), lambda: (set(), 0), info.append, warn.append, clock.pause,
         lambda: True, clock=clock)
    assert abs(clock.now - 2.0) < 1e-9
    assert warn == ['starting the agents without agent bidder_c, 1 of 1 other robots: not present after 2.0 s '
                    '(~await_timeout)']


def test_a_stopping_node_ends_the_wait_at_once():
    clock = Clock()
    missing, waited = StartBarrier(['x'], 0, 30).wait(lambda: (set(), 0), clock, clock.pause, alive=lambda: False)
    assert missing == ['agent x'] and waited == 0
