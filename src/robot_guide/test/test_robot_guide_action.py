"""guide(Name, Seconds): its arguments, and when a run ends."""
import math

import pytest
from rason_msgs.msg import Event

from robot_guide.guide import BadGuide, GuideRun, parse_arguments


@pytest.mark.parametrize('parameters, want', [
    (['faulty', '5'], ('faulty', 5.0)), (['faulty', '2.5'], ('faulty', 2.5)),
    ([' robot_2 ', '0.01'], ('robot_2', 0.01)), (['faulty', '1e3'], ('faulty', 1000.0)),
])
def test_good_arguments(parameters, want):
    assert parse_arguments(parameters) == want


@pytest.mark.parametrize('parameters, why', [
    (['faulty'], '2 arguments'), (['faulty', '5', '1'], '2 arguments'), ([], '2 arguments'),
    (['Faulty', '5'], 'atom'), (['pos(1,2)', '5'], 'atom'), (['"a b"', '5'], 'atom'),
    (['', '5'], 'atom'), (['faulty', '0'], 'positive'), (['faulty', '-1'], 'positive'),
    (['faulty', 'inf'], 'positive'), (['faulty', '1e999'], 'positive'),
    (['faulty', 'nan'], 'positive'), (['faulty', 'five'], 'positive'), (['faulty', ''], 'positive'),
])
def test_bad_arguments_say_why(parameters, why):
    with pytest.raises(BadGuide, match=why):
        parse_arguments(parameters)


def run(start=100.0, seconds=5.0, lost_after=2.0):
    return GuideRun('faulty', seconds, start, lost_after, deadband=3.0, gain=2.0, max_speed=0.4)


def no_camera(x, y):
    return None


def test_it_ends_ok_once_the_time_is_over():
    r = run()
    for now in (100.0, 101.5, 103.0, 104.5):
        r.frame(now, 1.0, (2.0, 0.0), now - 0.1)
        assert r.outcome(now) is None
    assert r.outcome(104.99) is None
    assert r.outcome(105.0) == Event.OK


def test_a_robot_never_seen_is_lost_after_lost_after():
    r = run()
    for now in (100.5, 101.0, 101.9):
        r.frame(now, None, None, now - 0.1)
        assert r.command(now, no_camera) == 0.0
        assert r.outcome(now) is None
    assert r.outcome(102.0) == Event.LOST


def test_lost_counts_from_the_last_sighting():
    r = run()
    r.frame(101.5, 0.0, None, 101.4)
    r.frame(102.0, None, None, 101.9)
    assert r.outcome(103.4) is None
    assert r.outcome(103.5) == Event.LOST


def test_the_time_being_over_wins_over_lost():
    assert run(seconds=1.0, lost_after=1.0).outcome(101.0) == Event.OK


def test_it_aims_at_the_located_point_as_the_camera_sees_it_now():
    r = run()
    assert r.command(100.0, lambda x, y: 10.0) == 0.0    # nothing located yet
    r.frame(100.1, 10.0, (2.0, -0.35), 100.0)
    asked = []
    bearing = {(2.0, -0.35): 10.0}

    def camera(x, y):
        asked.append((x, y))
        return bearing[(x, y)]

    assert r.command(100.15, camera) == pytest.approx(-2.0 * math.radians(10.0))
    bearing[(2.0, -0.35)] = 0.5                          # the base turned toward it
    assert r.command(100.2, camera) == 0.0
    assert asked == [(2.0, -0.35)] * 2


def test_it_aims_where_a_moving_robot_is_now():
    r = run()
    for k in range(5):                                   # 0.2 m/s along +y
        r.frame(100.1 + 0.1 * k, 0.0, (2.0, 0.02 * k), 100.0 + 0.1 * k)
    asked = []
    r.command(100.6, lambda x, y: asked.append((x, y)) or 0.0)
    assert asked == [pytest.approx((2.0, 0.08 + 0.2 * 0.2))]   # 0.2 s after the newest frame


def test_a_frame_without_the_robot_keeps_the_aim_at_its_track():
    r = run()
    r.frame(100.1, 10.0, (2.0, -0.35), 100.0)
    r.frame(100.2, None, None, 100.1)
    assert r.command(100.25, lambda x, y: 10.0) == pytest.approx(-2.0 * math.radians(10.0))
    assert r.command(100.3, no_camera) == 0.0            # no camera pose: no turn


def test_a_frame_that_could_not_locate_it_aims_at_its_angle_until_the_next_frame():
    r = run()
    r.frame(100.1, 10.0, (2.0, -0.35), 100.0)
    r.frame(100.2, -20.0, None, 100.1)                   # seen, not located (no transform)
    assert r.command(100.25, lambda x, y: 10.0) == 0.4
    r.frame(100.3, None, None, 100.2)                    # that angle is stale now: the track
    assert r.command(100.35, lambda x, y: 10.0) == pytest.approx(-2.0 * math.radians(10.0))


def test_a_clock_that_goes_back_does_not_unsee():
    r = run()
    r.frame(103.0, 0.0, None, 102.9)
    r.frame(102.0, 0.0, None, 101.9)
    assert r.outcome(104.9) is None
