"""Unit tests of fault_injector.faults (thesis §6.3, Eq. 6.2 and 6.3); no ROS master."""
import math

import pytest

from fault_injector import faults

ZERO = (0.0, 0.0, 0.0)
NAN = float('nan')


# --- Eq. 6.2 / 6.3: one actuator ------------------------------------------

@pytest.mark.parametrize('fault, x_lin, yaw_in, expected_yaw', [
    # Eq. 6.2, first case: angular.z = x_lin
    (faults.LEFT_ACTUATOR, 0.8, 0.0, 0.8),     # left, forward
    (faults.RIGHT_ACTUATOR, -0.6, 0.0, -0.6),  # right, backward
    # Eq. 6.2, second case: angular.z = -x_lin
    (faults.RIGHT_ACTUATOR, 0.8, 0.0, -0.8),   # right, forward
    (faults.LEFT_ACTUATOR, -0.6, 0.0, 0.6),    # left, backward
    # the commanded yaw rate is replaced, not added to
    (faults.LEFT_ACTUATOR, 0.5, -0.3, 0.5),
    (faults.RIGHT_ACTUATOR, 0.5, 0.3, -0.5),
    (faults.LEFT_ACTUATOR, -0.5, 0.7, 0.5),
    (faults.RIGHT_ACTUATOR, -0.5, -0.7, -0.5),
])
def test_single_actuator_moving(fault, x_lin, yaw_in, expected_yaw):
    linear, angular = faults.transform_twist(fault, (x_lin, 0.0, 0.0), (0.0, 0.0, yaw_in))
    assert angular == (0.0, 0.0, expected_yaw)
    assert linear == (x_lin / 2.0, 0.0, 0.0)  # Eq. 6.3


def test_single_actuator_halves_linear_exactly():
    assert faults.transform_twist(faults.LEFT_ACTUATOR, (0.8, 0, 0), ZERO)[0][0] == 0.4
    assert faults.transform_twist(faults.RIGHT_ACTUATOR, (-1.0, 0, 0), ZERO)[0][0] == -0.5


def test_left_fault_turns_left_when_moving_forward():
    _, angular = faults.transform_twist(faults.LEFT_ACTUATOR, (0.3, 0, 0), ZERO)
    assert angular[2] > 0
    _, angular = faults.transform_twist(faults.RIGHT_ACTUATOR, (0.3, 0, 0), ZERO)
    assert angular[2] < 0


@pytest.mark.parametrize('fault', [faults.LEFT_ACTUATOR, faults.RIGHT_ACTUATOR])
def test_single_actuator_keeps_unused_components(fault):
    linear, angular = faults.transform_twist(fault, (1.0, 0.1, 0.2), (0.3, 0.4, 0.0))
    assert linear[1:] == (0.1, 0.2)
    assert angular[:2] == (0.3, 0.4)


@pytest.mark.parametrize('fault', [faults.LEFT_ACTUATOR, faults.RIGHT_ACTUATOR])
def test_single_actuator_zero_twist_stays_zero(fault):
    assert faults.transform_twist(fault, ZERO, ZERO) == (ZERO, ZERO)


@pytest.mark.parametrize('fault', [faults.LEFT_ACTUATOR, faults.RIGHT_ACTUATOR])
@pytest.mark.parametrize('yaw', [0.5, -0.5])
def test_single_actuator_turn_on_spot_unchanged(fault, yaw):
    # x_lin == 0: neither case of Eq. 6.2 applies, angular.z is kept
    assert faults.transform_twist(fault, ZERO, (0.0, 0.0, yaw)) == (ZERO, (0.0, 0.0, yaw))


# --- the other faults --------------------------------------------------------

@pytest.mark.parametrize('linear, angular', [
    ((0.8, 0.0, 0.0), (0.0, 0.0, 0.0)),     # forward
    ((-0.6, 0.0, 0.0), (0.0, 0.0, 0.2)),    # backward
    (ZERO, ZERO),                           # zero
    (ZERO, (0.0, 0.0, 1.0)),                # turning only
    ((1.0, 2.0, 3.0), (4.0, 5.0, 6.0)),     # every component set
])
def test_both_actuators_zeroes_everything(linear, angular):
    assert faults.transform_twist(faults.BOTH_ACTUATORS, linear, angular) == (ZERO, ZERO)


@pytest.mark.parametrize('fault', [faults.NONE, faults.ODOMETRY])
@pytest.mark.parametrize('linear, angular', [
    ((0.8, 0.0, 0.0), (0.0, 0.0, 0.1)),
    ((-0.6, 0.0, 0.0), (0.0, 0.0, -0.2)),
    (ZERO, ZERO),
    (ZERO, (0.0, 0.0, 1.0)),
    ((1.0, 2.0, 3.0), (4.0, 5.0, 6.0)),
])
def test_pass_through_faults_leave_twist(fault, linear, angular):
    assert faults.transform_twist(fault, linear, angular) == (linear, angular)


def test_transform_returns_float_tuples():
    linear, angular = faults.transform_twist(faults.LEFT_ACTUATOR, [1, 0, 0], [0, 0, 0])
    assert isinstance(linear, tuple) and isinstance(angular, tuple)
    assert all(isinstance(v, float) for v in linear + angular)


# --- validation --------------------------------------------------------------

@pytest.mark.parametrize('request_, expected', [
    ('left_actuator', faults.LEFT_ACTUATOR),
    ('right_actuator', faults.RIGHT_ACTUATOR),
    ('both_actuators', faults.BOTH_ACTUATORS),
    ('odometry', faults.ODOMETRY),
    ('cancel', faults.NONE),
    ('none', faults.NONE),
    ('  Left_Actuator\n', faults.LEFT_ACTUATOR),
])
def test_parse_fault_valid(request_, expected):
    assert faults.parse_fault(request_) == expected


@pytest.mark.parametrize('request_', ['', 'left', 'actuator', 'left actuator', 'both', 'odom', 'cancel!'])
def test_parse_fault_unknown(request_):
    with pytest.raises(faults.UnknownFaultError):
        faults.parse_fault(request_)


# --- FaultState: the service's behaviour -------------------------------------

def test_state_starts_pass_through():
    state = faults.FaultState()
    assert state.fault == faults.NONE
    assert state.twist((1.0, 0, 0), (0, 0, 0.5)) == ((1.0, 0.0, 0.0), (0.0, 0.0, 0.5))


@pytest.mark.parametrize('fault', faults.FAULTS)
def test_state_request_success_names_fault(fault):
    state = faults.FaultState()
    ok, message = state.request(fault)
    assert ok
    assert state.fault == fault
    assert fault in message


def test_state_request_applies_fault_to_twist():
    state = faults.FaultState()
    state.request('right_actuator')
    assert state.twist((0.8, 0, 0), ZERO) == ((0.4, 0.0, 0.0), (0.0, 0.0, -0.8))
    state.request('both_actuators')
    assert state.twist((0.8, 0, 0), (0, 0, 1)) == (ZERO, ZERO)


@pytest.mark.parametrize('cancel', ['cancel', 'none'])
def test_state_cancel_back_to_pass_through(cancel):
    state = faults.FaultState()
    state.request('left_actuator')
    ok, message = state.request(cancel)
    assert ok
    assert state.fault == faults.NONE
    assert 'no active fault' in message
    assert state.twist((0.8, 0, 0), ZERO) == ((0.8, 0.0, 0.0), ZERO)


def test_state_unknown_fault_rejected_and_state_unchanged():
    state = faults.FaultState()
    state.request('left_actuator')
    ok, message = state.request('right_wheel')
    assert not ok
    assert state.fault == faults.LEFT_ACTUATOR
    assert 'unknown' in message and 'right_wheel' in message
    for name in faults.VALID_REQUESTS:
        assert name in message
    assert 'left_actuator' in message.split('unchanged')[1]
    # and the active fault still acts
    assert state.twist((0.8, 0, 0), ZERO) == ((0.4, 0.0, 0.0), (0.0, 0.0, 0.8))


def test_state_unknown_fault_keeps_frozen_odometry():
    state = faults.FaultState()
    state.odom('a')
    state.request('odometry')
    state.request('bogus')
    assert state.odom('b') == 'a'


def test_state_initial_fault():
    assert faults.FaultState('both_actuators').fault == faults.BOTH_ACTUATORS
    with pytest.raises(faults.UnknownFaultError):
        faults.FaultState('nope')


# --- odometry freezing --------------------------------------------------------

def test_odometry_pass_through_without_fault():
    state = faults.FaultState()
    assert [state.odom(v) for v in ('a', 'b', 'c')] == ['a', 'b', 'c']


def test_odometry_frozen_at_last_value_before_fault():
    state = faults.FaultState()
    state.odom('a')
    state.odom('b')
    state.request('odometry')
    assert [state.odom(v) for v in ('c', 'd')] == ['b', 'b']


def test_odometry_fault_before_first_message_freezes_first_one():
    state = faults.FaultState()
    state.request('odometry')
    assert state.odometry.frozen is None  # nothing to publish yet
    assert [state.odom(v) for v in ('a', 'b', 'c')] == ['a', 'a', 'a']


def test_odometry_cancel_resumes_with_latest():
    state = faults.FaultState()
    state.odom('a')
    state.request('odometry')
    state.odom('b')
    state.request('cancel')
    assert state.odom('c') == 'c'
    assert state.odometry.frozen is None


def test_odometry_repeated_request_keeps_original_value():
    state = faults.FaultState()
    state.odom('a')
    state.request('odometry')
    state.odom('b')
    state.request('odometry')
    assert state.odom('c') == 'a'


def test_odometry_released_by_another_fault():
    state = faults.FaultState()
    state.odom('a')
    state.request('odometry')
    state.request('left_actuator')
    assert state.odom('b') == 'b'


def test_odometry_freezer_direct():
    freezer = faults.OdometryFreezer()
    assert not freezer.active and freezer.last is None
    freezer.filter(1)
    freezer.freeze()
    assert freezer.active and freezer.frozen == 1
    assert freezer.filter(2) == 1 and freezer.last == 2
    freezer.release()
    assert not freezer.active and freezer.filter(3) == 3


def test_actuator_faults_do_not_touch_odometry():
    for fault in (faults.LEFT_ACTUATOR, faults.RIGHT_ACTUATOR, faults.BOTH_ACTUATORS):
        state = faults.FaultState(fault)
        assert [state.odom(v) for v in ('a', 'b')] == ['a', 'b']


# --- NaN -------------------------------------------------------------------------

def test_has_nan():
    assert faults.has_nan((0.0, NAN))
    assert not faults.has_nan((0.0, 1.0, float('inf')))
    assert not faults.has_nan(())


def test_nan_odometry_passes_through_without_fault():
    state = faults.FaultState()
    odom = (NAN, 0.0, 0.0)
    assert state.odom(odom) is odom


def test_nan_odometry_can_be_frozen():
    state = faults.FaultState()
    odom = (NAN, 0.0)
    state.odom(odom)
    state.request('odometry')
    assert state.odom((1.0, 2.0)) is odom


def test_nan_twist_pass_through():
    linear, angular = faults.transform_twist(faults.NONE, (NAN, 0, 0), (0, 0, NAN))
    assert math.isnan(linear[0]) and math.isnan(angular[2])


@pytest.mark.parametrize('fault', [faults.LEFT_ACTUATOR, faults.RIGHT_ACTUATOR])
def test_nan_linear_single_actuator_does_not_raise(fault):
    linear, angular = faults.transform_twist(fault, (NAN, 0, 0), (0, 0, 0.5))
    assert math.isnan(linear[0])
    assert angular == (0.0, 0.0, 0.5)  # NaN is neither > 0 nor < 0


def test_nan_angular_single_actuator_replaced():
    _, angular = faults.transform_twist(faults.LEFT_ACTUATOR, (0.4, 0, 0), (0, 0, NAN))
    assert angular[2] == 0.4


def test_nan_twist_both_actuators_zero():
    assert faults.transform_twist(faults.BOTH_ACTUATORS, (NAN,) * 3, (NAN,) * 3) == (ZERO, ZERO)


@pytest.mark.parametrize('severity', [0.25, 0.5, 0.9])
@pytest.mark.parametrize('fault', [faults.LEFT_ACTUATOR, faults.RIGHT_ACTUATOR])
def test_a_weaker_actuator_fault_blends_the_command_with_the_thesis_fault(fault, severity):
    commanded = ((0.4, 0.0, 0.0), (0.0, 0.0, 0.1))
    full = faults.transform_twist(fault, *commanded)
    linear, angular = faults.transform_twist(fault, *commanded, severity=severity)
    assert linear[0] == pytest.approx((1 - severity) * 0.4 + severity * full[0][0])
    assert angular[2] == pytest.approx((1 - severity) * 0.1 + severity * full[1][2])
    # weaker than the thesis's fault, still turning the same way
    assert abs(angular[2] - 0.1) < abs(full[1][2] - 0.1)
    assert (angular[2] - 0.1) * (full[1][2] - 0.1) > 0


def test_severity_one_is_the_thesis_fault_and_other_faults_ignore_it():
    commanded = ((0.4, 0.0, 0.0), (0.0, 0.0, 0.1))
    assert faults.transform_twist(faults.LEFT_ACTUATOR, *commanded, severity=1.0) == \
        faults.transform_twist(faults.LEFT_ACTUATOR, *commanded)
    assert faults.transform_twist(faults.BOTH_ACTUATORS, *commanded, severity=0.3) == (ZERO, ZERO)
    assert faults.transform_twist(faults.NONE, *commanded, severity=0.3) == commanded


@pytest.mark.parametrize('bad', [0, -0.5, 1.5, float('nan'), 'strong', None])
def test_severity_outside_zero_one_is_refused(bad):
    with pytest.raises(ValueError, match='severity'):
        faults.FaultState(faults.LEFT_ACTUATOR, severity=bad)


def test_fault_state_applies_its_severity():
    state = faults.FaultState(faults.RIGHT_ACTUATOR, severity='0.5')
    assert state.severity == 0.5
    assert state.twist((0.4, 0, 0), ZERO) == faults.transform_twist(
        faults.RIGHT_ACTUATOR, (0.4, 0, 0), ZERO, severity=0.5)
