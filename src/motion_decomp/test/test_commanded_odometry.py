"""Unit tests of motion_decomp.commanded_odometry: dead reckoning of the commanded twists."""
import math

import pytest

from motion_decomp.commanded_odometry import COMMAND_TIMEOUT, CommandedOdometry, integrate


def test_it_starts_at_the_zero_pose_and_stands_still_without_commands():
    odo = CommandedOdometry()
    assert odo.advance(5.0) == (0.0, 0.0, 0.0)
    assert odo.advance(100.0) == (0.0, 0.0, 0.0)
    assert odo.twist(100.0) == (0.0, 0.0)


def test_a_straight_command_repeated_at_the_control_rate_integrates_the_distance():
    odo = CommandedOdometry()
    t = 10.0
    for _ in range(250):                  # 5 s at 50 Hz, 0.2 m/s
        odo.command(0.2, 0.0, t)
        t += 0.02
    odo.command(0.0, 0.0, t)
    assert odo.advance(t + 3.0) == pytest.approx((1.0, 0.0, 0.0))
    assert odo.twist(t + 3.0) == (0.0, 0.0)


def test_turning_and_arcs_are_integrated_exactly():
    odo = CommandedOdometry(command_timeout=10.0)
    odo.command(0.0, math.pi / 2, 0.0)          # a quarter turn on the spot in 1 s
    odo.command(0.5, 0.0, 1.0)                  # 0.5 m along +y
    odo.command(math.pi / 4, math.pi / 2, 2.0)  # a half circle of radius 0.5, to the left
    odo.command(0.0, 0.0, 4.0)
    x, y, yaw = odo.advance(4.0)
    assert (x, y) == pytest.approx((-1.0, 0.5), abs=1e-9)
    assert math.cos(yaw) == pytest.approx(0.0, abs=1e-9) and math.sin(yaw) == pytest.approx(-1.0)


def test_integrate_matches_small_steps():
    pose = (0.3, -0.2, 2.0)
    fine = pose
    for _ in range(1000):
        fine = integrate(fine, 0.2, -0.7, 0.003)
    assert integrate(pose, 0.2, -0.7, 3.0) == pytest.approx(fine, abs=1e-9)


def test_a_command_holds_until_the_base_timeout_only():
    odo = CommandedOdometry()
    odo.command(0.2, 0.0, 0.0)
    assert odo.twist(0.5) == (0.2, 0.0)
    assert odo.advance(0.3)[0] == pytest.approx(0.06)
    # no newer command: the base stops after COMMAND_TIMEOUT, and so does the integration
    assert odo.advance(10.0)[0] == pytest.approx(0.2 * COMMAND_TIMEOUT)
    assert odo.twist(10.0) == (0.0, 0.0)


def test_time_going_back_integrates_nothing_and_goes_on_from_there():
    odo = CommandedOdometry()
    odo.command(0.2, 0.0, 100.0)
    odo.command(0.2, 0.0, 100.5)
    assert odo.advance(100.5)[0] == pytest.approx(0.1)
    assert odo.advance(1.0)[0] == pytest.approx(0.1)       # a restarted simulation
    odo.command(0.1, 0.0, 1.0)
    assert odo.advance(1.5)[0] == pytest.approx(0.15)


def test_a_bad_timeout_is_refused():
    for bad in (0.0, -1.0, float('nan')):
        with pytest.raises(ValueError):
            CommandedOdometry(bad)
