"""Where a seen robot is now: its newest located point moved on by its measured velocity."""
import pytest

from robot_guide.track import Track


def test_nothing_before_the_first_point():
    assert Track().at(10.0) is None


def test_a_single_point_stays_where_it_is():
    t = Track()
    t.add(10.0, 1.0, 2.0)
    assert t.at(10.3) == (1.0, 2.0) and t.velocity == (0.0, 0.0)


def test_a_moving_robot_is_followed_over_the_cameras_delay():
    t = Track(baseline=0.3, horizon=0.5)
    for k in range(8):                        # 0.2 m/s along +y, frames at 10 Hz
        t.add(10.0 + 0.1 * k, 1.0, 0.02 * k)
    assert t.velocity == pytest.approx((0.0, 0.2))
    assert t.at(10.9) == pytest.approx((1.0, 0.14 + 0.04))   # newest 10.7, 0.2 s later
    assert t.at(12.0) == pytest.approx((1.0, 0.14 + 0.1))    # at most `horizon` ahead
    assert t.at(10.5) == pytest.approx((1.0, 0.14))          # never back in time


def test_the_velocity_is_measured_over_the_baseline_not_between_neighbours():
    t = Track(baseline=0.3)
    noise = [0.0, 0.004, -0.004, 0.004, -0.004, 0.004, 0.0]  # 4 mm of noise, standing still
    for k, n in enumerate(noise):
        t.add(10.0 + 0.1 * k, 1.0 + n, 0.0)
    assert abs(t.velocity[0]) < 0.03              # between neighbours it would read 0.08 m/s


def test_too_short_a_history_measures_no_speed():
    t = Track(baseline=0.3)
    t.add(10.0, 1.0, 0.0)
    t.add(10.1, 1.1, 0.0)
    assert t.velocity == (0.0, 0.0)


def test_a_jump_no_robot_makes_restarts_the_track():
    t = Track(baseline=0.3, max_speed=1.0)
    for k in range(5):
        t.add(10.0 + 0.1 * k, 0.0, 0.02 * k)
    t.add(10.5, 3.0, 0.0)                         # 3 m in 0.3 s: a teleport
    assert t.velocity == (0.0, 0.0) and t.at(11.0) == (3.0, 0.0)
    t.add(10.6, 3.0, 0.0)
    assert t.velocity == (0.0, 0.0)


def test_old_and_repeated_frames_are_ignored():
    t = Track()
    t.add(10.0, 1.0, 0.0)
    t.add(10.0, 5.0, 0.0)
    t.add(9.0, 5.0, 0.0)
    assert t.at(10.0) == (1.0, 0.0)


def test_points_older_than_keep_are_forgotten():
    t = Track(baseline=0.3, keep=1.0)
    t.add(10.0, 0.0, 0.0)
    t.add(12.0, 1.0, 0.0)                         # the only other point is 2 s old: forgotten
    assert t.velocity == (0.0, 0.0)
