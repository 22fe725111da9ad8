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
