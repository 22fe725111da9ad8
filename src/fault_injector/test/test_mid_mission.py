"""MidMissionFault: a fault injected fault_at seconds after the first motion command."""
import math

import pytest

from fault_injector import faults

STILL = ((0.0, 0.0, 0.0), (0.0, 0.0, 0.0))
FORWARD = ((0.2, 0.0, 0.0), (0.0, 0.0, 0.0))
TURN = ((0.0, 0.0, 0.0), (0.0, 0.0, -0.5))


def test_zero_and_nan_commands_do_not_start_the_mission():
    assert not faults.is_motion_command(*STILL)
    assert not faults.is_motion_command((math.nan, 0, 0), (0, 0, 0))
    assert faults.is_motion_command(*TURN)


def test_the_first_motion_command_starts_the_clock():
    pending = faults.MidMissionFault('odometry', 2.0)
    assert pending.on_command(*STILL, now=5.0) is None
    assert pending.due(100.0) is None          # no mission yet: never injected
    assert pending.on_command(*FORWARD, now=10.0) == 12.0
    assert pending.on_command(*TURN, now=11.0) is None   # the clock does not restart


def test_the_fault_is_due_once_at_its_time():
    pending = faults.MidMissionFault('both_actuators', 1.5)
    pending.on_command(*TURN, now=3.0)
    assert pending.due(4.49) is None
    assert pending.due(4.5) == faults.BOTH_ACTUATORS
    assert pending.due(9.0) is None


def test_the_clock_step_the_fault_is_due_at_counts_even_with_float_rounding():
    # CI: started at 3.31 s, fault_at 2: the timer woke at the clock's 5.31, which is less
    # than 3.31 + 2.0 in floats; the fault was never injected
    pending = faults.MidMissionFault('left_actuator', 2.0)
    assert pending.on_command(*FORWARD, now=3.31) == 3.31 + 2.0
    assert 5.31 < 3.31 + 2.0
    assert pending.due(5.30) is None
    assert pending.waiting(5.30) == pytest.approx(0.01)
    assert pending.waiting(5.31) is None
    assert pending.due(5.31) == faults.LEFT_ACTUATOR
    assert pending.waiting(5.31) is None and pending.waiting(4.0) is None  # injected


def test_nothing_to_wait_for_before_the_mission():
    assert faults.MidMissionFault('odometry', 2.0).waiting(1.0) is None


@pytest.mark.parametrize('fault, delay, error', [
    ('none', 1.0, faults.UnknownFaultError),
    ('cancel', 1.0, faults.UnknownFaultError),
    ('wheels', 1.0, faults.UnknownFaultError),
    ('odometry', 0.0, ValueError),
    ('odometry', -1.0, ValueError),
    ('odometry', math.inf, ValueError),
    ('odometry', math.nan, ValueError),
])
def test_bad_requests_are_refused(fault, delay, error):
    with pytest.raises(error):
        faults.MidMissionFault(fault, delay)
