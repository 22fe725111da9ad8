"""Simulated time standing still is said, and its moving again (rason_bridge.clock_watch)."""
from rason_bridge.clock_watch import ClockWatch


class Wall(object):
    def __init__(self):
        self.now = 100.0

    def __call__(self):
        return self.now


def test_a_clock_that_keeps_moving_says_nothing():
    wall = Wall()
    watch = ClockWatch(stall=5, clock=wall)
    for step in range(1, 100):
        wall.now += 0.5
        watch.heard(step * 10**8)
        assert watch.due() is None


def test_a_clock_never_heard_is_said_after_the_stall():
    wall = Wall()
    watch = ClockWatch(stall=5, clock=wall)
    wall.now += 4.9
    assert watch.due() is None
    wall.now += 0.2
    line = watch.due()
    assert line.startswith('/clock has not moved for 5 s (no /clock heard since the start)')
    assert 'paused, or gone?' in line


def test_a_clock_standing_still_is_said_once_then_reminded_and_its_return_said():
    wall = Wall()
    watch = ClockWatch(stall=5, repeat=60, clock=wall)
    watch.heard(12_500_000_000)
    wall.now += 6
    assert watch.due().startswith('/clock has not moved for 6 s (simulated time stands at 12.500 s)')
    wall.now += 30
    assert watch.due() is None                       # said; not again before the reminder
    watch.heard(12_500_000_000)                      # the same time again is no step
    wall.now += 31
    assert watch.due().startswith('/clock has not moved for 67 s')
    watch.heard(12_600_000_000)
    assert watch.due() == "/clock moves again: the agents' waits and timeouts go on"
    assert watch.due() is None


def test_a_clock_that_went_back_moves_on_from_there():
    wall = Wall()
    watch = ClockWatch(stall=5, clock=wall)
    watch.heard(50 * 10**9)
    wall.now += 4
    watch.heard(1 * 10**9)                           # a simulator restarted
    for step in range(2, 20):
        wall.now += 1
        watch.heard(step * 10**9)
        assert watch.due() is None
    wall.now += 5
    assert 'stands at 19.000 s' in watch.due()
