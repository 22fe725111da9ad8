"""The stand-in base's kinematics and the timing of a take-back (no master)."""
import math

import pytest

from rason_bench import preempt


def test_straight_line_along_the_heading():
    assert preempt.integrate((0.0, 0.0, 0.0), 0.2, 0.0, 0.02) == pytest.approx((0.004, 0.0, 0.0))
    x, y, yaw = preempt.integrate((1.0, 2.0, math.pi / 2), 0.5, 0.0, 2.0)
    assert (x, y, yaw) == pytest.approx((1.0, 3.0, math.pi / 2))


def test_turn_on_the_spot_changes_only_the_heading():
    assert preempt.integrate((1.0, -1.0, 0.0), 0.0, 0.5, 1.0) == pytest.approx((1.0, -1.0, 0.5))


def test_an_arc_ends_on_its_circle():
    # a quarter circle of radius 1 m to the left (counter-clockwise), from the origin facing +x
    x, y, yaw = preempt.integrate((0.0, 0.0, 0.0), 1.0, 1.0, math.pi / 2)
    assert (x, y, yaw) == pytest.approx((1.0, 1.0, math.pi / 2))


def test_many_small_steps_agree_with_one_big_one():
    pose = (0.3, 0.1, 0.2)
    for _ in range(50):
        pose = preempt.integrate(pose, 0.2, -0.4, 0.02)
    assert pose == pytest.approx(preempt.integrate((0.3, 0.1, 0.2), 0.2, -0.4, 1.0))


def test_no_time_no_motion():
    assert preempt.integrate((1.0, 2.0, 3.0), 0.2, 0.5, 0.0) == (1.0, 2.0, 3.0)
    assert preempt.integrate((1.0, 2.0, 3.0), 0.2, 0.5, -0.1) == (1.0, 2.0, 3.0)


def test_heading_wraps_into_minus_pi_pi():
    _, _, yaw = preempt.integrate((0.0, 0.0, 3.0), 0.0, 1.0, 1.0)
    assert yaw == pytest.approx(4.0 - 2 * math.pi)
    assert preempt.wrap(math.pi) == pytest.approx(math.pi)
    assert preempt.wrap(-math.pi) == pytest.approx(math.pi)


def test_yaw_quaternion_is_a_unit_rotation_about_z():
    x, y, z, w = preempt.yaw_quaternion(math.pi / 2)
    assert (x, y) == (0.0, 0.0)
    assert (z, w) == pytest.approx((math.sqrt(0.5), math.sqrt(0.5)))
    assert math.atan2(2 * w * z, 1 - 2 * z * z) == pytest.approx(math.pi / 2)


def test_only_the_all_zero_twist_is_the_stop():
    assert preempt.is_zero(0.0, 0.0, 0.0, 0.0, 0.0, 0.0)
    assert not preempt.is_zero(0.2, 0.0, 0.0, 0.0, 0.0, 0.0)
    assert not preempt.is_zero(0.0, 0.0, 0.0, 0.0, 0.0, -0.5)


def test_round_takes_the_first_zero_twist_after_the_motion_is_under_way():
    rnd = preempt.Round()
    rnd.twist(1.00, zero=True)      # a motion's first tick before odometry: not a stop
    assert (rnd.under_way, rnd.stopped) == (None, None)
    rnd.twist(1.02, zero=False)
    rnd.twist(1.04, zero=False)
    rnd.twist(1.05, zero=True)
    rnd.twist(1.06, zero=True)      # a later zero (the motion's end tick) changes nothing
    rnd.twist(1.08, zero=False)     # nor does the next motion
    assert (rnd.under_way, rnd.stopped) == (1.02, 1.05)


def test_round_latencies_from_the_take_back_timestamp():
    lat = preempt.round_latencies(took_back_ms=1000.0, stopped_s=1.0075, cancel_seen_s=1.0015)
    assert lat['stop_ms'] == pytest.approx(7.5)
    assert lat['cancel_ms'] == pytest.approx(1.5)
    assert lat['cancel_to_stop_ms'] == pytest.approx(6.0)


def test_round_latencies_without_a_cancel_heard():
    lat = preempt.round_latencies(took_back_ms=1000.0, stopped_s=1.010, cancel_seen_s=None)
    assert lat == {'stop_ms': pytest.approx(10.0), 'cancel_ms': None, 'cancel_to_stop_ms': None}


def test_a_motion_that_stopped_before_the_take_back_measures_nothing():
    rnd = preempt.Round()
    rnd.twist(1.0, zero=False)
    rnd.twist(1.5, zero=True)
    assert preempt.stopped_on_its_own(rnd, take_back_sent_s=2.0)
    assert not preempt.stopped_on_its_own(rnd, take_back_sent_s=1.2)
    assert not preempt.stopped_on_its_own(preempt.Round(), take_back_sent_s=2.0)
