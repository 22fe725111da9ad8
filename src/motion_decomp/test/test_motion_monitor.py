"""Unit tests of motion_decomp.monitor on synthetic odometry (no ROS master needed)."""
import math
import random

import pytest

from motion_decomp import monitor as m
from rason_msgs.msg import Event

DT = 0.05  # 20 Hz, the node's default control rate


def unicycle(pose, v, w, dt=DT):
    """The test's own kinematic robot: pose after driving (v, w) for dt."""
    x, y, yaw = pose
    mid = yaw + 0.5 * w * dt
    yaw = math.atan2(math.sin(yaw + w * dt), math.cos(yaw + w * dt))
    return (x + v * math.cos(mid) * dt, y + v * math.sin(mid) * dt, yaw)


def drive(mon, pose, t=0.0, plant=None, noise=None, limit=200.0):
    """Feed ``mon`` the odometry of a robot that executes its commands.

    :param plant: ``plant(v, w) -> (v, w)`` what the robot really does (faults)
    :param noise: ``noise(pose) -> pose`` what odometry reports
    :returns: (result, end time, true end pose, list of reported poses)
    """
    seen = [pose]
    result = mon.update(pose, t)
    t_end = t + limit
    while result is None and t < t_end:
        v, w = mon.command()
        if plant is not None:
            v, w = plant(v, w)
        pose = unicycle(pose, v, w)
        t += DT
        observed = noise(pose) if noise is not None else pose
        seen.append(observed)
        result = mon.update(observed, t)
    return result, t, pose, seen


def monitor(action, param, pose=(0.0, 0.0, 0.0), t=0.0, **options):
    return m.MotionMonitor(m.parse_motion(action, [param]), pose, t, **options)


# ---------------------------------------------------------------- parameters

@pytest.mark.parametrize('action, params, amount', [
    ('move', ['1'], 1.0),
    ('move', ['-0.3'], -0.3),
    ('move', ['1.0E-4'], 1e-4),
    ('move', ['+2'], 2.0),
    ('turn', ['90'], 90.0),
    ('turn', ['-45.5'], -45.5),
    ('turn', ['.5'], 0.5),
])
def test_parse_motion_accepts_numbers_as_jason_prints_them(action, params, amount):
    assert m.parse_motion(action, params) == m.Motion(action, amount)


@pytest.mark.parametrize('action, params', [
    ('move', ['abc']),
    ('move', []),
    ('move', ['1', '2']),
    ('move', ['']),
    ('move', ['nan']),
    ('move', ['NaN']),
    ('turn', ['inf']),
    ('turn', ['-Infinity']),
    ('turn', ['1e999']),       # parses to inf
    ('move', ['1_0']),         # float() would take it
    ('move', [' 1']),
    ('turn', ['"90"']),
    ('turn', ['ninety']),
])
def test_parse_motion_rejects_bad_parameters(action, params):
    with pytest.raises(m.BadParameters):
        m.parse_motion(action, params)


def test_parse_motion_rejects_other_actions_without_calling_them_bad_parameters():
    with pytest.raises(m.UnknownAction):
        m.parse_motion('grab', ['1'])
    assert not m.is_motion('grab')
    assert m.is_motion('move') and m.is_motion('turn')


# ---------------------------------------------------------------- commands and signs

def test_command_signs_move_forward_and_backward():
    assert monitor('move', '1').command() == (0.2, 0.0)
    assert monitor('move', '-1').command() == (-0.2, 0.0)


def test_command_signs_positive_turn_is_clockwise():
    # Documented convention: turn(+deg) turns RIGHT, i.e. negative angular z.
    assert monitor('turn', '90').command() == (0.0, -0.5)
    assert monitor('turn', '-90').command() == (0.0, 0.5)


def test_command_uses_configured_speeds():
    assert monitor('move', '-1', linear_speed=0.3).command() == (-0.3, 0.0)
    assert monitor('turn', '90', angular_speed=1.2).command() == (0.0, -1.2)


def test_a_turn_slows_down_over_its_last_degrees_so_a_late_odometry_overshoots_little():
    import motion_model
    lag = 10  # control cycles (0.2 s at 50 Hz) between a command and the wheels
    for degrees in (10, -10, 90):
        run = motion_model.drive(monitor('turn', str(degrees)), (0.0, 0.0, 0.0), lag=lag)
        assert run.result == Event.OK
        # the commands still on their way when the turn ended turn the robot too
        in_flight = sum(w for _, w in run.commands[-lag:]) * motion_model.DT
        turned = math.degrees(-(run.pose[2] + in_flight))
        overshoot = abs(turned) - abs(degrees)
        assert 0 <= overshoot < 3.0, (degrees, overshoot)  # at full speed to the end: 6
        assert run.time < abs(math.radians(degrees)) / 0.5 + 1.0  # not much slower
    mon = monitor('turn', '90')
    assert mon.command() == (0.0, -0.5)  # full speed far from the end
    mon.update((0.0, 0.0, -math.radians(88)), 1.0)
    assert -0.5 < mon.command()[1] < 0  # slower near it
    mon.update((0.0, 0.0, -math.radians(89.9)), 1.1)
    assert mon.command() == (0.0, -0.1)  # never below the floor


def test_no_command_without_odometry_and_after_the_end():
    mon = m.MotionMonitor(m.Motion('move', 1.0), None, 0.0)
    assert mon.command() == (0.0, 0.0)
    assert mon.update((0.0, 0.0, 0.0), 0.05) is None
    assert mon.command() == (0.2, 0.0)
    assert mon.update((1.0, 0.0, 0.0), 0.1) == Event.OK
    assert mon.command() == (0.0, 0.0)
    assert mon.update((1.0, 0.0, 0.0), 0.15) == Event.OK   # stays ended


# ---------------------------------------------------------------- move

def test_move_forward_reaches_the_goal_along_the_heading():
    start = (3.0, -1.0, 2.5)
    mon = monitor('move', '1', start)
    result, t, (x, y, _), _ = drive(mon, start)
    assert result == Event.OK
    assert 1.0 <= math.hypot(x - 3.0, y + 1.0) < 1.0 + 0.2 * DT + 1e-9
    assert t == pytest.approx(1.0 / 0.2, abs=2 * DT)
    # went where the robot was facing
    assert (x - 3.0) * math.cos(2.5) + (y + 1.0) * math.sin(2.5) > 0.99


def test_move_backward_reaches_the_goal_behind_the_robot():
    start = (0.0, 0.0, -1.0)
    mon = monitor('move', '-0.5', start)
    result, _, (x, y, _), _ = drive(mon, start)
    assert result == Event.OK
    assert x * math.cos(-1.0) + y * math.sin(-1.0) == pytest.approx(-0.5, abs=0.011)


def test_move_does_not_end_before_the_distance():
    mon = monitor('move', '1')
    assert mon.update((0.5, 0.0, 0.0), 0.1) is None
    assert mon.update((0.999, 0.0, 0.0), 0.2) is None
    assert mon.update((1.0, 0.0, 0.0), 0.3) == Event.OK


def test_move_of_zero_is_ok_at_once_even_without_odometry():
    mon = m.MotionMonitor(m.Motion('move', 0.0), None, 0.0)
    assert mon.update(None, 0.0) == Event.OK


# ---------------------------------------------------------------- no_progress and timeout

def test_stuck_odometry_is_no_progress_after_one_second_not_before():
    mon = monitor('move', '1', (1.0, 2.0, 0.3), t=10.0)
    stuck = (1.0, 2.0, 0.3)
    for t in (10.05, 10.5, 10.95, 11.0):
        assert mon.update(stuck, t) is None, t
    assert mon.update(stuck, 11.05) == Event.NO_PROGRESS


def test_robot_that_stops_halfway_is_no_progress_one_second_later():
    stop_at = 0.4

    def blocked(v, w):
        return (v, w) if current[0][0] < stop_at else (0.0, 0.0)

    current = [(0.0, 0.0, 0.0)]

    def noise(pose):
        current[0] = pose
        return pose

    mon = monitor('move', '1')
    result, t, pose, _ = drive(mon, (0.0, 0.0, 0.0), plant=blocked, noise=noise)
    assert result == Event.NO_PROGRESS
    blocked_at = stop_at / 0.2
    assert blocked_at + 1.0 < t <= blocked_at + 1.0 + 2 * DT
    assert pose[0] == pytest.approx(stop_at, abs=0.011)


def test_jitter_below_the_thresholds_is_still_no_progress():
    mon = monitor('turn', '90')
    t = 0.0
    result = None
    while result is None and t < 5:
        t += DT
        # 0.5 mm and 0.05 degree of jitter: below 1 mm / 0.1 degree
        jitter = 0.0005 if int(t / DT) % 2 else 0.0
        result = mon.update((jitter, 0.0, math.radians(jitter * 100)), t)
    assert result == Event.NO_PROGRESS
    assert 1.0 < t <= 1.0 + 2 * DT


def test_slow_but_steady_progress_is_not_no_progress():
    # 2 mm every 0.6 s: each pose alone differs by < 1 mm from the last, but it adds up
    mon = monitor('move', '0.1', no_progress_time=1.0)
    t, x = 0.0, 0.0
    result = None
    while result is None and t < 60:
        t += DT
        x += 0.002 * DT / 0.6
        result = mon.update((x, 0.0, 0.0), t)
    assert result == Event.OK


def test_no_odometry_at_all_is_no_progress_after_one_second():
    mon = m.MotionMonitor(m.parse_motion('turn', ['45']), None, 5.0)
    assert mon.update(None, 5.5) is None
    assert mon.update(None, 6.0) is None
    assert mon.command() == (0.0, 0.0)   # never drives blind
    assert mon.update(None, 6.05) == Event.NO_PROGRESS


def test_late_first_odometry_gives_the_robot_a_full_second():
    # Driving only starts with the first pose, so the no-progress clock restarts there.
    mon = m.MotionMonitor(m.parse_motion('move', ['1']), None, 0.0)
    assert mon.update(None, 0.9) is None
    assert mon.update((0.0, 0.0, 0.0), 0.95) is None
    assert mon.update((0.0, 0.0, 0.0), 1.9) is None
    assert mon.update((0.0, 0.0, 0.0), 2.0) == Event.NO_PROGRESS


def test_no_progress_time_is_a_parameter():
    mon = monitor('move', '1', no_progress_time=2.5)
    assert mon.update((0.0, 0.0, 0.0), 2.5) is None
    assert mon.update((0.0, 0.0, 0.0), 2.55) == Event.NO_PROGRESS


def test_non_finite_pose_is_ignored():
    mon = monitor('move', '1')
    assert mon.update((float('nan'), 0.0, 0.0), 0.3) is None
    assert mon.update((0.5, 0.0, float('inf')), 0.6) is None
    assert mon.travelled == 0.0
    assert mon.update((0.1, 0.0, 0.0), 0.9) is None
    assert mon.travelled == pytest.approx(0.1)


def test_timeout_ends_a_motion_that_never_arrives():
    # turning the wrong way forever: progress, but never the goal
    mon = monitor('turn', '30', max_duration=3.0)
    result, t, _, _ = drive(mon, (0.0, 0.0, 0.0), plant=lambda v, w: (v, -w))
    assert result == Event.TIMEOUT
    assert t == pytest.approx(3.0, abs=DT + 1e-9)


# ---------------------------------------------------------------- bad_move

@pytest.mark.parametrize('side', [1.0, -1.0], ids=['left_fault', 'right_fault'])
@pytest.mark.parametrize('metres', ['1', '-1'])
def test_curved_path_of_an_actuator_fault_is_bad_move(side, metres):
    # One wheel failing: half the linear speed, and the robot turns (w = +-v).
    def fault(v, w):
        return 0.5 * v, side * abs(0.5 * v)

    mon = monitor('move', metres, (2.0, 1.0, 0.7))
    result, _, pose, _ = drive(mon, (2.0, 1.0, 0.7), plant=fault)
    assert result == Event.BAD_MOVE
    gone = math.hypot(pose[0] - 2.0, pose[1] - 1.0)
    # caught well before the goal, but only after the measuring distance
    assert 0.05 <= gone < 0.5


def test_small_noise_on_a_straight_path_is_no_false_bad_move():
    for seed in range(20):
        rnd = random.Random(seed)

        def noise(pose):
            x, y, yaw = pose
            return (x + rnd.gauss(0, 0.002), y + rnd.gauss(0, 0.002),
                    yaw + rnd.gauss(0, math.radians(0.3)))

        for metres in ('1', '-0.6'):
            mon = monitor('move', metres, (0.0, 0.0, 1.0))
            result, _, _, _ = drive(mon, (0.0, 0.0, 1.0), noise=noise)
            assert result == Event.OK, (seed, metres)


def test_direction_is_not_judged_before_the_measuring_distance():
    mon = monitor('move', '1')
    assert mon.update((0.0, 0.04, 0.0), 0.1) is None        # sideways, but too short to tell
    assert mon.update((0.0, 0.06, 0.0), 0.2) == Event.BAD_MOVE  # now it counts


def test_bad_move_threshold_is_the_cosine():
    # cos(8 degrees) = 0.9903 passes, cos(8.2 degrees) = 0.9898 fails
    ok = monitor('move', '1')
    a = math.radians(8.0)
    assert ok.update((0.3 * math.cos(a), 0.3 * math.sin(a), 0.0), 1.0) is None
    bad = monitor('move', '1')
    a = math.radians(8.2)
    assert bad.update((0.3 * math.cos(a), -0.3 * math.sin(a), 0.0), 1.0) == Event.BAD_MOVE


def test_moving_forward_when_backward_was_asked_is_bad_move():
    mon = monitor('move', '-1')
    assert mon.update((0.1, 0.0, 0.0), 0.5) == Event.BAD_MOVE


# ---------------------------------------------------------------- turn

@pytest.mark.parametrize('degrees, start_yaw', [
    ('90', -3.0),    # clockwise across -pi -> +pi
    ('-90', 3.0),    # counter-clockwise across +pi -> -pi
    ('90', 0.0),
    ('-90', 0.0),
    ('360', 2.0),
    ('-360', -2.0),
    ('720', 0.0),
])
def test_turn_reaches_the_angle_across_the_yaw_wrap(degrees, start_yaw):
    start = (1.0, 1.0, start_yaw)
    mon = monitor('turn', degrees, start)
    result, t, (_, _, yaw), seen = drive(mon, start)
    assert result == Event.OK
    want = math.radians(float(degrees))
    # at 0.5 rad/s, slower over the last 7 degrees (about 0.4 s more)
    assert abs(want) / 0.5 <= t <= abs(want) / 0.5 + 0.5
    # positive degrees are clockwise: the yaw went down by the angle
    assert m.wrap_angle(yaw - (start_yaw - want)) == pytest.approx(0.0, abs=0.5 * DT + 1e-9)
    assert -mon.turned == pytest.approx(want, abs=0.5 * DT + 1e-9)


def test_turn_360_does_not_end_at_half_way_or_when_the_yaw_is_back_near_start():
    mon = monitor('turn', '360')
    assert mon.update((0.0, 0.0, -math.pi / 2), 3.0) is None
    assert mon.update((0.0, 0.0, -math.pi + 0.01), 6.0) is None
    assert mon.update((0.0, 0.0, math.pi / 2), 9.0) is None
    assert mon.update((0.0, 0.0, 0.01), 12.0) is None
    assert mon.update((0.0, 0.0, 0.0), 12.1) == Event.OK


def test_turn_the_wrong_way_does_not_count():
    mon = monitor('turn', '90')        # clockwise wanted
    assert mon.update((0.0, 0.0, 1.0), 1.0) is None
    assert mon.update((0.0, 0.0, 1.6), 2.0) is None   # 90 degrees, but counter-clockwise


# ---------------------------------------------------------------- helpers

def test_yaw_from_quaternion_and_wrap():
    for yaw in (0.0, 0.5, -2.0, 3.1):
        assert m.yaw_from_quaternion(0.0, 0.0, math.sin(yaw / 2), math.cos(yaw / 2)) == pytest.approx(yaw)
    assert m.wrap_angle(3 * math.pi / 2) == pytest.approx(-math.pi / 2)
    assert m.wrap_angle(-3 * math.pi / 2) == pytest.approx(math.pi / 2)


@pytest.mark.parametrize('options', [
    dict(linear_speed=0.0), dict(angular_speed=-1.0), dict(no_progress_time=float('nan')),
    dict(max_duration=0), dict(bad_move_min_cos=1.5), dict(bad_move_min_distance=-1), dict(speed=1),
])
def test_bad_options_are_rejected(options):
    with pytest.raises(ValueError):
        m.MotionScheduler(**options)


# ---------------------------------------------------------------- one motion at a time

def test_scheduler_runs_motions_one_at_a_time_in_fifo_order():
    s = m.MotionScheduler()
    assert s.submit('r1', 1, 'move', ['0.2']) is None
    assert s.submit('r1', 2, 'turn', ['90']) is None
    assert s.pending == 2
    pose, t = (0.0, 0.0, 0.0), 0.0
    feedbacks, commands = [], []
    while len(feedbacks) < 2 and t < 20:
        cmd, fb = s.step(pose, t)
        commands.append(cmd)
        if fb is not None:
            feedbacks.append((fb, pose))
            assert cmd == (0.0, 0.0)      # every end stops the robot
        elif cmd is not None:
            pose = unicycle(pose, *cmd)
        t += DT
    assert [fb for fb, _ in feedbacks] == [m.Feedback('r1', 1, Event.OK), m.Feedback('r1', 2, Event.OK)]
    # the turn only started after the move: while moving, never an angular command
    first_end = commands.index((0.0, 0.0))
    assert all(c[1] == 0.0 for c in commands[:first_end])
    assert all(c[0] == 0.0 for c in commands[first_end:])
    assert feedbacks[1][1][2] == pytest.approx(-math.pi / 2, abs=0.03)
    assert s.step(pose, t) == (None, None)   # idle: publish nothing


def test_scheduler_starts_the_next_motion_from_where_the_robot_is():
    s = m.MotionScheduler()
    s.submit('r1', 1, 'move', ['0.2'])
    s.submit('r1', 2, 'move', ['0.2'])
    pose, t, done = (0.0, 0.0, 0.0), 0.0, []
    while len(done) < 2 and t < 20:
        cmd, fb = s.step(pose, t)
        if fb is not None:
            done.append(pose[0])
        elif cmd is not None:
            pose = unicycle(pose, *cmd)
        t += DT
    assert done[0] == pytest.approx(0.2, abs=0.011)
    assert done[1] == pytest.approx(0.4, abs=0.022)


def test_scheduler_fails_bad_parameters_at_once_and_ignores_nothing_else():
    s = m.MotionScheduler()
    s.submit('a', 1, 'move', ['1'])
    assert s.submit('b', 7, 'move', ['abc']) == m.Feedback('b', 7, Event.BAD_PARAMETERS)
    assert s.submit('b', 8, 'turn', []) == m.Feedback('b', 8, Event.BAD_PARAMETERS)
    assert s.pending == 1
    with pytest.raises(m.UnknownAction):
        s.submit('b', 9, 'say', ['hello'])


def test_scheduler_cancel_all_reports_running_and_queued():
    s = m.MotionScheduler()
    s.submit('a', 1, 'move', ['1'])
    s.submit('a', 2, 'turn', ['10'])
    s.step((0.0, 0.0, 0.0), 0.0)
    assert s.cancel_all() == [m.Feedback('a', 1, Event.SHUTDOWN), m.Feedback('a', 2, Event.SHUTDOWN)]
    assert s.step((0.0, 0.0, 0.0), 1.0) == (None, None)


def test_scheduler_cancel_of_a_queued_motion_removes_it_and_keeps_the_order():
    s = m.MotionScheduler()
    for action_id, action in ((1, 'move'), (2, 'turn'), (3, 'move')):
        s.submit('a', action_id, action, ['0.1'])
    cmd, _ = s.step((0.0, 0.0, 0.0), 0.0)          # 1 runs
    assert cmd == (0.2, 0.0)
    assert s.cancel('a', 2) == (None, [m.Feedback('a', 2, Event.CANCELLED)])
    assert s.pending == 1
    # the running motion goes on undisturbed, then 3 (not 2) runs
    pose, t, ended = (0.0, 0.0, 0.0), 0.0, []
    while len(ended) < 2 and t < 10:
        t += DT
        pose = unicycle(pose, *cmd) if cmd else pose
        cmd, fb = s.step(pose, t)
        if fb is not None:
            ended.append(fb)
    assert ended == [m.Feedback('a', 1, Event.OK), m.Feedback('a', 3, Event.OK)]
    assert pose[0] == pytest.approx(0.2, abs=0.022)


def test_scheduler_cancel_of_the_running_motion_stops_now_and_starts_the_next_at_the_next_step():
    s = m.MotionScheduler()
    s.submit('a', 1, 'move', ['1'])
    s.submit('a', 2, 'turn', ['90'])
    assert s.step((0.0, 0.0, 0.0), 0.0) == ((0.2, 0.0), None)
    assert s.step((0.01, 0.0, 0.0), DT) == ((0.2, 0.0), None)
    command, feedbacks = s.cancel('a', 1)
    assert command == (0.0, 0.0)
    assert feedbacks == [m.Feedback('a', 1, Event.CANCELLED)]
    assert s.current is None and s.pending == 1
    # next step: the turn starts from where the move stopped, with no end of its own
    cmd, fb = s.step((0.01, 0.0, 0.0), 2 * DT)
    assert fb is None and cmd == (0.0, -0.5)
    assert s.current[1].start_pose == (0.01, 0.0, 0.0)


def test_scheduler_cancel_zero_takes_back_every_motion_of_the_agent_only():
    s = m.MotionScheduler()
    s.submit('a', 1, 'move', ['1'])
    s.submit('b', 1, 'move', ['1'])
    s.submit('a', 2, 'turn', ['90'])
    s.step((0.0, 0.0, 0.0), 0.0)
    command, feedbacks = s.cancel('a', 0)
    assert command == (0.0, 0.0)
    assert feedbacks == [m.Feedback('a', 1, Event.CANCELLED), m.Feedback('a', 2, Event.CANCELLED)]
    cmd, fb = s.step((0.0, 0.0, 0.0), DT)
    assert fb is None and cmd == (0.2, 0.0)        # b's move runs now
    assert s.current[0].agent == 'b' and s.pending == 0


def test_scheduler_cancel_of_an_unknown_or_finished_motion_changes_nothing():
    s = m.MotionScheduler()
    s.submit('a', 1, 'move', ['0'])
    assert s.step((0.0, 0.0, 0.0), 0.0) == ((0.0, 0.0), m.Feedback('a', 1, Event.OK))
    s.submit('a', 2, 'move', ['1'])
    s.step((0.0, 0.0, 0.0), DT)
    assert s.cancel('a', 1) == (None, [])      # finished
    assert s.cancel('a', 9) == (None, [])      # unknown
    assert s.cancel('b', 0) == (None, [])      # another agent
    assert s.cancel('b', 2) == (None, [])      # same id, another agent
    assert s.step((0.0, 0.0, 0.0), 2 * DT) == ((0.2, 0.0), None)


def test_scheduler_no_odometry_fails_no_progress_and_never_drives():
    s = m.MotionScheduler(no_progress_time=1.0)
    s.submit('a', 3, 'move', ['1'])
    t, cmds = 0.0, []
    while t < 2.0:
        cmd, fb = s.step(None, t)
        cmds.append(cmd)
        if fb is not None:
            break
        t += DT
    assert fb == m.Feedback('a', 3, Event.NO_PROGRESS)
    assert 1.0 < t <= 1.0 + 2 * DT
    assert set(cmds) == {(0.0, 0.0)}


# ---------------------------------------------------------------- node message conversion

def test_node_conversions():
    from nav_msgs.msg import Odometry
    from motion_decomp import node

    odom = Odometry()
    odom.pose.pose.position.x = 1.5
    odom.pose.pose.position.y = -2.0
    odom.pose.pose.orientation.z = math.sin(0.25)
    odom.pose.pose.orientation.w = math.cos(0.25)
    assert node.pose_from_odometry(odom) == pytest.approx((1.5, -2.0, 0.5))
    odom.pose.pose.position.y = float('nan')
    assert node.pose_from_odometry(odom) is None

    ev = node.feedback_event(m.Feedback('bob', 42, Event.BAD_MOVE))
    assert (ev.agent, ev.event_type, list(ev.parameters)) == ('bob', Event.ACTION_FEEDBACK, [Event.BAD_MOVE, '42'])
    tw = node.twist(0.0, -0.5)
    assert (tw.linear.x, tw.angular.z) == (0.0, -0.5)
    assert node.agent_filter('a, b c') == {'a', 'b', 'c'}
    assert node.agent_filter(['x']) == {'x'} and node.agent_filter([]) == set()
