"""A fault-tolerance run judged from hand-built events: what the agents said (rason/mission,
rason/diagnosis) checked against the simulator's true poses."""
import math

import pytest

from rason_campaign.mission import judge_mission

# Faulty starts at the origin facing +y: its goal is (0, 1), not (1, 0).
START = (0.0, 0.0, math.pi / 2)


def action(t, name, robot='faulty', agent=None):
    return (t, 'action', {'robot': robot, 'agent': agent or robot, 'action': name,
                          'parameters': []})


def message(t, sender, receiver, performative, content):
    return (t, 'message', {'sender': sender, 'receiver': receiver,
                           'performative': performative, 'content': content})


def diagnosis(t, component, evidence=''):
    return (t, 'diagnosis', {'agent': 'faulty', 'component': component, 'evidence': evidence})


def mission(t, completed, by, recovery, component):
    return (t, 'mission', {'agent': 'faulty', 'completed': completed, 'by': by,
                           'recovery': recovery, 'diagnosis': component})


def pose(t, robot, x, y, yaw=0.0):
    return (t, 'pose', {'robot': robot, 'x': x, 'y': y, 'yaw': yaw})


def faulty_drives(to_goal=(0.02, 0.95), back=(0.05, 0.03)):
    """Faulty still until t = 5 (its first move), at to_goal at t = 30, back at t = 50."""
    return [pose(0.0, 'faulty', 0.4, 0.0, 0.0),   # before it settled: not the start
            pose(4.0, 'faulty', *START), pose(5.0, 'faulty', *START),
            action(5.0, 'move'),
            pose(20.0, 'faulty', 0.01, 0.6, math.pi / 2),
            pose(30.0, 'faulty', to_goal[0], to_goal[1], math.pi / 2),
            pose(40.0, 'faulty', 0.03, 0.5, -math.pi / 2),
            pose(50.0, 'faulty', back[0], back[1], -math.pi / 2)]


def asked_for_help(t=8.0):
    return [message(t, 'faulty', '', 'achieve', 'helpme'),
            message(t + 6, 'helper', 'faulty', 'tell', 'found(faulty)')]


def test_completed_by_faulty_with_compensate():
    events = faulty_drives() + asked_for_help() + [
        diagnosis(18.0, 'left_actuator'), mission(52.0, 'true', 'faulty', 'compensate',
                                                  'left_actuator'),
        mission(53.0, 'true', 'faulty', 'compensate', 'left_actuator'),   # a repeat
        pose(60.0, 'faulty', 0.0, 1.0, 0.0)]   # after the end: does not count
    out = judge_mission('left_actuator', 'recovery', events)
    assert out.completed and out.claimed
    assert (out.by, out.recovery, out.diagnosis, out.diagnosis_outcome) == (
        ['faulty'], 'compensate', 'left_actuator', 'correct')
    assert out.goal == pytest.approx((0.0, 1.0), abs=1e-6)
    assert (out.start, out.end, out.time) == (5.0, 52.0, 47.0)
    assert out.goal_error == pytest.approx(math.hypot(0.02, 0.05), abs=1e-4)
    assert out.start_error == pytest.approx(math.hypot(0.05, 0.03), abs=1e-4)
    assert out.reason == 'completed by faulty (recovery compensate)'


def test_completed_by_the_helper_with_delegate_judged_on_the_helpers_true_pose():
    events = [pose(0.0, 'faulty', *START), action(5.0, 'move'),
              pose(30.0, 'faulty', 0.0, 0.0, math.pi / 2),        # Faulty never moves
              action(20.0, 'goto', robot='helper', agent='h1'),
              pose(0.0, 'helper', -1.5, 0.0), pose(40.0, 'helper', -0.4, 1.2),
              pose(60.0, 'helper', 0.05, 1.08), pose(65.0, 'helper', 0.3, 1.1)] + \
        asked_for_help() + [diagnosis(18.0, 'both_actuators'),
                            mission(70.0, 'true', 'h1', 'delegate', 'both_actuators')]
    out = judge_mission('both_actuators', 'recovery', events)
    assert out.completed and out.by == ['h1'] and out.recovery == 'delegate'
    assert out.goal_error == pytest.approx(math.hypot(0.05, 0.08), abs=1e-4)
    assert out.start_error is None          # Faulty did not do it: its start is not checked
    assert out.time == 65.0


def test_mission_not_completed_by_the_agents():
    events = faulty_drives(to_goal=(0.0, 0.3)) + asked_for_help() + [
        diagnosis(18.0, 'odometry'), mission(40.0, 'false', '', 'guided', 'odometry')]
    out = judge_mission('odometry', 'recovery', events)
    assert not out.completed and not out.claimed
    assert out.reason == 'mission not completed (diagnosis odometry, recovery guided)'
    assert out.diagnosis_outcome == 'correct'
    assert out.time is None and out.goal_error is None
    assert out.end == 40.0 and out.recovery == 'guided'


def test_goal_error_too_large_is_not_completed():
    events = faulty_drives(to_goal=(0.0, 0.8)) + [
        diagnosis(51.0, 'none'), mission(52.0, 'true', 'faulty', 'none', 'none')]
    out = judge_mission('none', 'recovery', events)
    assert out.claimed and not out.completed
    assert out.goal_error == pytest.approx(0.2, abs=1e-4)
    assert out.reason == 'goal missed by 0.200 m (> 0.15 m)'
    assert out.time is None


def test_faulty_not_back_at_its_start_is_not_completed():
    events = faulty_drives(back=(0.0, 0.2)) + [
        diagnosis(51.0, 'none'), mission(52.0, 'true', 'faulty', 'none', 'none')]
    out = judge_mission('none', 'recovery', events)
    assert out.claimed and not out.completed
    assert out.start_error == pytest.approx(0.2, abs=1e-4)
    assert out.reason == 'Faulty ended 0.200 m from its start (> 0.15 m)'


def test_baseline_under_a_fault_stops_after_the_diagnosis():
    events = faulty_drives(to_goal=(0.0, 0.1), back=(0.0, 0.1)) + asked_for_help() + [
        diagnosis(18.0, 'right_actuator')]
    out = judge_mission('right_actuator', 'baseline', events)
    assert not out.completed and not out.claimed
    assert out.diagnosis_outcome == 'correct'
    assert out.reason == 'stopped after the diagnosis right_actuator (thesis behaviour)'


def test_baseline_without_a_fault_completes_its_mission_at_its_diagnosis():
    events = faulty_drives() + [diagnosis(51.0, 'none', 'destination reached')]
    out = judge_mission('none', 'baseline', events)
    assert out.completed and out.by == ['faulty'] and out.recovery == 'none'
    assert (out.end, out.time) == (51.0, 46.0)
    assert out.diagnosis_outcome == 'correct'


def test_baseline_false_positive_is_a_wrong_diagnosis_and_not_completed():
    events = faulty_drives() + asked_for_help() + [diagnosis(25.0, 'none', 'false positive')]
    out = judge_mission('left_actuator', 'baseline', events)
    assert not out.completed and out.diagnosis_outcome == 'wrong'
    assert out.reason == 'stopped after the diagnosis none (thesis behaviour)'


def test_recovery_after_a_false_positive_completes_but_the_diagnosis_is_wrong():
    events = faulty_drives() + asked_for_help() + [
        diagnosis(25.0, 'none'), mission(52.0, 'true', 'faulty', 'none', 'none')]
    out = judge_mission('left_actuator', 'recovery', events)
    assert out.completed and out.diagnosis_outcome == 'wrong'


def test_no_true_poses_recorded():
    events = [action(5.0, 'move'), diagnosis(18.0, 'none'),
              mission(52.0, 'true', 'faulty', 'none', 'none')]
    out = judge_mission('none', 'recovery', events)
    assert out.claimed and not out.completed and out.goal is None
    assert out.reason == 'no true pose of faulty recorded'


def test_a_run_that_went_wrong_says_why():
    out = judge_mission('odometry', 'recovery', [], 'timed out after 420 s')
    assert not out.completed and out.diagnosis_outcome == 'undiagnosed'
    assert out.reason == 'timed out after 420 s; no rason/mission status recorded'
    out = judge_mission('odometry', 'baseline', [], 'roslaunch exited with code 1')
    assert out.reason == 'roslaunch exited with code 1; no diagnosis recorded'


def test_a_launch_that_hung_after_a_completed_mission_still_completed_it():
    events = faulty_drives() + [diagnosis(51.0, 'none'),
                                mission(52.0, 'true', 'faulty', 'none', 'none')]
    out = judge_mission('none', 'recovery', events, 'timed out after 420 s')
    assert out.completed
    assert out.reason == 'timed out after 420 s; completed by faulty (recovery none)'


def test_order_of_the_events_does_not_matter():
    events = faulty_drives() + asked_for_help() + [
        diagnosis(18.0, 'left_actuator'),
        mission(52.0, 'true', 'faulty', 'compensate', 'left_actuator')]
    a = judge_mission('left_actuator', 'recovery', events).to_dict()
    assert judge_mission('left_actuator', 'recovery', list(reversed(events))).to_dict() == a
