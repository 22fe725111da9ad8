"""The centring turn: REP 103 against vision_synth's clockwise angle, dead band, gain, limit."""
import math

import pytest

from robot_guide.centring import SETTLE, Centring, centring_speed


@pytest.mark.parametrize('angle', [0.0, 2.9, -2.9, 3.0, -3.0])
def test_nothing_inside_the_dead_band(angle):
    assert centring_speed(angle, 3.0, 2.0, 0.4) == 0.0


def test_a_robot_on_the_right_turns_clockwise_which_is_negative():
    assert centring_speed(5.0, 3.0, 2.0, 0.4) == pytest.approx(-2.0 * math.radians(5.0))
    assert centring_speed(-5.0, 3.0, 2.0, 0.4) == pytest.approx(2.0 * math.radians(5.0))


def test_proportional_to_the_whole_angle_outside_the_dead_band():
    small, large = centring_speed(4.0, 3.0, 1.0, 0.4), centring_speed(8.0, 3.0, 1.0, 0.4)
    assert large == pytest.approx(2 * small) and small == pytest.approx(-math.radians(4.0))


@pytest.mark.parametrize('angle, want', [(20.0, -0.4), (-25.0, 0.4), (28.5, -0.4)])
def test_limited_to_the_angular_speed(angle, want):
    assert centring_speed(angle, 3.0, 2.0, 0.4) == want


def test_no_dead_band_turns_for_any_angle():
    assert centring_speed(0.5, 0.0, 2.0, 0.4) == pytest.approx(-2.0 * math.radians(0.5))


def test_an_angle_that_is_not_a_number_turns_nothing():
    assert centring_speed(float('nan'), 3.0, 2.0, 0.4) == 0.0


def test_once_turning_it_goes_on_until_well_inside_the_dead_band():
    c = Centring(3.0, 2.0, 0.4)
    assert c.speed(2.5) == 0.0 and not c.turning          # never started: dead band
    assert c.speed(4.0) < 0.0 and c.turning
    assert c.speed(2.5) == pytest.approx(-2.0 * math.radians(2.5))   # still turning
    assert c.speed(3.0 * SETTLE + 0.01) < 0.0
    assert c.speed(3.0 * SETTLE) == 0.0 and not c.turning
    assert c.speed(2.5) == 0.0                              # stopped: the dead band again


def test_nothing_to_aim_at_stops_the_turn():
    c = Centring(3.0, 2.0, 0.4)
    assert c.speed(10.0) < 0.0
    assert c.speed(None) == 0.0 and not c.turning
    assert c.speed(2.0) == 0.0
    assert c.speed(float('nan')) == 0.0
