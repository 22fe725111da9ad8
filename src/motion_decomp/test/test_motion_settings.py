"""Unit tests of the scheduler's goto, compensate and pose_source (issue 15) on the tests'
kinematic model (no ROS): parsing, the FIFO order of settings, compensated goto and move
under the one-wheel faults, the guided pose source."""
import math

import pytest

from motion_decomp import monitor as m
from motion_decomp.arc import ArcSteering
from motion_decomp.goto import DirectSteering
from motion_decomp.commanded_odometry import integrate
from motion_decomp.pose_source import CommandedTrail, StampedPose, carried_forward, fresh_pose, stamped_pose
from motion_model import DT, healthy, one_wheel_fault, step
from rason_msgs.msg import Event


class Robot(object):
    """A MotionScheduler driving the model: odometry is the true pose unless ``odom`` says
    otherwise; ``guided`` gives the guided pose fed at each step."""

    def __init__(self, scheduler=None, pose=(0.0, 0.0, 0.0), plant=healthy, odom=None, guided=None):
        self.s = scheduler or m.MotionScheduler()
        self.pose, self.plant, self.odom, self.guided = tuple(pose), plant, odom, guided
        self.t = 0.0
        self.commands = []       # (time, command) of every non-idle step
        self.feedbacks = []      # (feedback, time, true pose)
        self._id = 0

    def submit(self, action, *parameters):
        self._id += 1
        answer = self.s.submit('a', self._id, action, [str(p) for p in parameters])
        return self._id if answer is None else answer

    def run(self, limit=120.0):
        """Step until nothing is running or queued; returns the feedbacks."""
        end = self.t + limit
        while self.t < end:
            odom = self.odom(self.pose, self.t) if self.odom else self.pose
            guided = self.guided(self.pose, self.t) if self.guided else None
            command, feedback = self.s.step(odom, self.t, guided)
            if feedback is not None:
                self.feedbacks.append((feedback, self.t, self.pose))
            if command is not None:
                self.commands.append((self.t, command))
                self.pose = step(self.pose, *self.plant(*command))
            elif self.s.current is None and not self.s.pending:
                return [f for f, _, _ in self.feedbacks]
            self.t += DT
        raise AssertionError('still busy after %.0f s' % limit)

    def at(self, action_id):
        """(time, true pose) when ``action_id`` was answered."""
        return next((t, p) for f, t, p in self.feedbacks if f.action_id == action_id)


class GuidedFeed(object):
    """Someone else's view of the robot: the true pose ``latency`` s late, every ``period`` s."""

    def __init__(self, latency=0.2, period=0.1, offset=(0.0, 0.0)):
        self.latency, self.period, self.offset = latency, period, offset
        self._history = []
        self._last = None

    def __call__(self, pose, now):
        self._history.append((now, pose))
        if self._last is None or now - self._last.stamp - self.latency >= self.period - 1e-9:
            seen_at = now - self.latency
            old = [p for t, p in self._history if t <= seen_at + 1e-9]
            if old:
                x, y, yaw = old[-1]
                self._last = StampedPose((x + self.offset[0], y + self.offset[1], yaw), seen_at)
        return self._last


def distance(pose, point):
    return math.hypot(point[0] - pose[0], point[1] - pose[1])


def ok(*ids):
    return [m.Feedback('a', i, Event.OK) for i in ids]


# ---------------------------------------------------------------- parsing

@pytest.mark.parametrize('action, params, parsed', [
    ('goto', ['1', '-0.5'], m.Goto(1.0, -0.5)),
    ('goto', ['0', '1.0E-4'], m.Goto(0.0, 1e-4)),
    ('compensate', ['left', '2'], m.Compensation('left', 2.0)),
    ('compensate', ['right', '1.6'], m.Compensation('right', 1.6)),
    ('compensate', ['none', '0'], m.Compensation('none', 0.0)),
    ('compensate', ['left', '20'], m.Compensation('left', 20.0)),
    ('pose_source', ['odom'], m.PoseSourceSetting('odom')),
    ('pose_source', ['guided'], m.PoseSourceSetting('guided')),
    ('pose_source', ['guided', '/r1/located/r4'], m.PoseSourceSetting('guided', '/r1/located/r4')),
    ('pose_source', ['guided', 'located/faulty'], m.PoseSourceSetting('guided', 'located/faulty')),
])
def test_the_new_actions_parse(action, params, parsed):
    assert m.parse_motion(action, params) == parsed
    assert m.parse_motion(action, params).kind == action


@pytest.mark.parametrize('action, params', [
    ('goto', ['1']), ('goto', ['1', '2', '3']), ('goto', []), ('goto', ['1', 'abc']),
    ('goto', ['nan', '0']), ('goto', ['0', 'inf']), ('goto', ['1e999', '0']), ('goto', ['x', 'y']),
    ('compensate', ['left']), ('compensate', ['left', '2', '3']), ('compensate', ['up', '2']),
    ('compensate', ['Left', '2']), ('compensate', ['"left"', '2']), ('compensate', ['left', '-1']),
    ('compensate', ['left', 'nan']), ('compensate', ['left', 'inf']), ('compensate', ['left', '20.5']),
    ('compensate', ['2', 'left']),
    ('pose_source', ['gps']), ('pose_source', ['']), ('pose_source', ['odom', 'guided']),
    ('pose_source', []), ('pose_source', ['"guided"']),
    ('pose_source', ['odom', '/r1/located/r4']), ('pose_source', ['guided', '']),
    ('pose_source', ['guided', '~located']), ('pose_source', ['guided', '/r1//r4']),
    ('pose_source', ['guided', '/r1/located/']), ('pose_source', ['guided', '/r1/located r4']),
    ('pose_source', ['guided', '/r1', 'x']),
])
def test_bad_parameters_of_the_new_actions_fail_at_once(action, params):
    with pytest.raises(m.BadParameters):
        m.parse_motion(action, params)
    s = m.MotionScheduler()
    assert s.submit('a', 3, action, params) == m.Feedback('a', 3, Event.BAD_PARAMETERS)
    assert s.pending == 0
    assert s.compensation == m.NO_COMPENSATION and s.pose_source == 'odom'


def test_the_new_options_are_checked():
    for options in (dict(goto_tolerance=0), dict(segment_length=-1), dict(guided_linear_speed=float('nan')),
                    dict(guided_angular_speed=0), dict(guided_max_age=float('inf'))):
        with pytest.raises(ValueError):
            m.MotionScheduler(**options)


# ---------------------------------------------------------------- goto

@pytest.mark.parametrize('start, point', [((0, 0, 0), (1.0, -0.5)), ((1, 1, 2.0), (0.2, 0.3)),
                                          ((0, 0, 0), (-0.7, 0.0))])
def test_goto_drives_to_the_point_and_answers_ok(start, point):
    robot = Robot(pose=start)
    action_id = robot.submit('goto', *point)
    assert robot.run() == ok(action_id)
    assert distance(robot.pose, point) <= 0.05


def test_goto_tolerance_is_a_parameter():
    robot = Robot(m.MotionScheduler(goto_tolerance=0.2))
    action_id = robot.submit('goto', 1, 0)
    assert robot.run() == ok(action_id)
    assert 0.1 - 0.01 <= distance(robot.pose, (1, 0)) <= 0.2    # aims at half the tolerance


def test_goto_already_there_is_ok_at_once():
    robot = Robot(pose=(0.5, 0.5, 1.0))
    action_id = robot.submit('goto', 0.51, 0.5)
    assert robot.run() == ok(action_id)
    assert robot.at(action_id)[0] == 0.0


def test_goto_on_a_stuck_base_is_no_progress_and_without_odometry_too():
    robot = Robot(plant=lambda v, w: (0.0, 0.0))
    action_id = robot.submit('goto', 1, 0)
    assert robot.run() == [m.Feedback('a', action_id, Event.NO_PROGRESS)]
    assert 1.0 < robot.t <= 1.0 + 2 * DT
    blind = Robot(odom=lambda pose, t: None)
    action_id = blind.submit('goto', 1, 0)
    assert blind.run() == [m.Feedback('a', action_id, Event.NO_PROGRESS)]
    assert {c for _, c in blind.commands} == {(0.0, 0.0)}      # never drives blind


def test_goto_that_never_arrives_is_timeout():
    robot = Robot(m.MotionScheduler(max_duration=3.0))
    action_id = robot.submit('goto', 10, 0)
    assert robot.run() == [m.Feedback('a', action_id, Event.TIMEOUT)]
    assert robot.t == pytest.approx(3.0, abs=DT + 1e-9)


def test_goto_is_cancelled_and_shut_down_like_a_move():
    s = m.MotionScheduler()
    s.submit('a', 1, 'goto', ['1', '1'])
    s.submit('a', 2, 'goto', ['2', '2'])
    s.step((0.0, 0.0, 0.0), 0.0)
    assert s.cancel('a', 1) == ((0.0, 0.0), [m.Feedback('a', 1, Event.CANCELLED)])
    s.step((0.0, 0.0, 0.0), DT)
    assert isinstance(s.current[1], m.GotoMotion)
    assert s.cancel_all() == [m.Feedback('a', 2, Event.SHUTDOWN)]


# ---------------------------------------------------------------- compensate: when it applies

def test_compensate_waits_in_the_fifo_and_answers_ok_when_it_takes_effect():
    robot = Robot()
    move = robot.submit('move', 0.2)
    setting = robot.submit('compensate', 'left', 2)
    after = robot.submit('goto', 0.5, 0.0)
    assert robot.s.compensation == m.NO_COMPENSATION     # queued, not in effect
    command, feedback = robot.s.step(robot.pose, 0.0)
    assert feedback is None and isinstance(robot.s.current[1], m.MotionMonitor)
    assert robot.run() == ok(move, setting, after)
    assert robot.at(move)[0] < robot.at(setting)[0] < robot.at(after)[0]
    assert robot.s.compensation == m.Compensation('left', 2.0)


def test_a_setting_takes_its_own_step_and_commands_nothing():
    s = m.MotionScheduler()
    s.submit('a', 1, 'compensate', ['right', '1.5'])
    s.submit('a', 2, 'pose_source', ['guided'])
    assert s.step(None, 0.0) == (None, m.Feedback('a', 1, Event.OK))
    assert s.compensation.curvature == -1.5 and s.pose_source == 'odom'
    assert s.step(None, DT) == (None, m.Feedback('a', 2, Event.OK))
    assert s.pose_source == 'guided'
    assert s.step(None, 2 * DT) == (None, None)


def test_a_queued_setting_can_be_cancelled_and_then_never_applies():
    s = m.MotionScheduler()
    s.submit('a', 1, 'move', ['1'])
    s.submit('a', 2, 'compensate', ['left', '2'])
    s.step((0.0, 0.0, 0.0), 0.0)
    assert s.cancel('a', 2) == (None, [m.Feedback('a', 2, Event.CANCELLED)])
    s.cancel('a', 1)
    assert s.step((0.0, 0.0, 0.0), DT) == (None, None)
    assert s.compensation == m.NO_COMPENSATION


@pytest.mark.parametrize('setting', [('left', 0), ('right', 0), ('none', 0), ('none', 2)])
def test_without_a_curvature_driving_is_plain(setting):
    robot = Robot(plant=one_wheel_fault('left'))
    robot.submit('compensate', 'left', 2)
    robot.submit('compensate', *setting)          # back to normal
    move = robot.submit('move', 1)
    goto = robot.submit('goto', 1, 1)
    feedbacks = robot.run()
    assert feedbacks[2] == m.Feedback('a', move, Event.BAD_MOVE)   # as without compensate
    assert robot.s.compensation.curvature == 0
    assert feedbacks[3].action_id == goto
    # the plain move commanded straight driving
    assert all(c == (0.2, 0.0) for t, c in robot.commands if t < robot.at(move)[0])


# ---------------------------------------------------------------- compensated goto and move

@pytest.mark.parametrize('side', ['left', 'right'])
@pytest.mark.parametrize('gain', ['2', '1.6', '2.4'])
@pytest.mark.parametrize('start', [(0.0, 0.0, 0.0), (0.3, -0.2, 2.5), (-1.0, 0.5, -1.2)])
def test_compensated_goto_reaches_the_point_under_the_fault(side, gain, start):
    robot = Robot(pose=start, plant=one_wheel_fault(side))
    robot.submit('compensate', side, gain)
    action_id = robot.submit('goto', 0.8, -0.4)
    assert robot.run()[-1] == m.Feedback('a', action_id, Event.OK)
    assert distance(robot.pose, (0.8, -0.4)) <= 0.05
    assert isinstance(robot.s.compensation, m.Compensation)


@pytest.mark.parametrize('side', ['left', 'right'])
@pytest.mark.parametrize('metres', [1.0, -0.5])
def test_compensated_move_reaches_the_point_ahead_or_behind_without_bad_move(side, metres):
    start = (0.2, 0.1, 0.7)
    robot = Robot(pose=start, plant=one_wheel_fault(side))
    robot.submit('compensate', side, 2)
    move = robot.submit('move', metres)
    assert robot.run()[-1] == m.Feedback('a', move, Event.OK)
    point = (start[0] + metres * math.cos(0.7), start[1] + metres * math.sin(0.7))
    assert distance(robot.pose, point) <= 0.05


def test_the_compensated_move_is_measured_from_where_it_starts():
    robot = Robot(plant=one_wheel_fault('left'))
    robot.submit('compensate', 'left', 2)
    robot.submit('turn', -90)                      # now facing +y
    robot.submit('move', 0.6)
    robot.submit('move', 0.4)
    assert robot.run() == ok(1, 2, 3, 4)
    _, after_turn = robot.at(2)
    assert after_turn[2] == pytest.approx(math.pi / 2, abs=0.03)
    _, second = robot.at(3)
    assert distance(second, (0.6 * math.cos(after_turn[2]), 0.6 * math.sin(after_turn[2]))) <= 0.05
    # the second move goes 0.4 m along the heading the first one ended with (its last arc's)
    x, y, yaw = second
    assert distance(robot.pose, (x + 0.4 * math.cos(yaw), y + 0.4 * math.sin(yaw))) <= 0.05


def test_uncompensated_move_under_the_fault_is_bad_move():
    robot = Robot(plant=one_wheel_fault('left'))
    move = robot.submit('move', 1)
    assert robot.run() == [m.Feedback('a', move, Event.BAD_MOVE)]


def test_turn_is_unchanged_while_compensating():
    robot = Robot(pose=(0.0, 0.0, 1.0), plant=one_wheel_fault('left'))
    robot.submit('compensate', 'left', 2)
    turn = robot.submit('turn', 90)
    assert robot.run() == ok(1, turn)
    # turning on the spot as without the setting: 0.5 rad/s, slower over the last degrees
    assert robot.commands[0][1] == (0.0, -0.5)
    assert all(v == 0.0 and -0.5 <= w <= -0.1 for _, (v, w) in robot.commands[:-1])
    assert robot.pose[2] == pytest.approx(1.0 - math.pi / 2, abs=0.03)


def test_the_runner_follows_the_setting():
    s = m.MotionScheduler(segment_length=0.5)
    s.submit('a', 1, 'compensate', ['right', '2'])
    s.submit('a', 2, 'goto', ['3', '0'])
    s.step((0.0, 0.0, 0.0), 0.0)
    s.step((0.0, 0.0, 0.0), DT)
    steering = s.current[1].controller.steering
    assert isinstance(steering, ArcSteering)
    assert steering.curvature == -2.0 and steering.segment_length == 0.5
    plain = m.MotionScheduler()
    plain.submit('a', 1, 'goto', ['3', '0'])
    plain.step((0.0, 0.0, 0.0), 0.0)
    assert isinstance(plain.current[1].controller.steering, DirectSteering)


# ---------------------------------------------------------------- pose_source

def test_guided_poses_are_fresh_for_max_age_either_way():
    stamped = StampedPose((1.0, 2.0, 0.5), 10.0)
    assert fresh_pose(stamped, 10.5, 0.5) == (1.0, 2.0, 0.5)
    assert fresh_pose(stamped, 10.51, 0.5) is None
    assert fresh_pose(stamped, 9.5, 0.5) == (1.0, 2.0, 0.5)
    assert fresh_pose(stamped, 9.49, 0.5) is None        # stamped ahead: another clock
    assert fresh_pose(None, 10.0, 0.5) is None


def test_the_trail_gives_the_newest_commanded_pose_at_or_before_a_time():
    trail = CommandedTrail(span=1.0)
    assert trail.at(5.0) is None
    for i in range(300):
        trail.record(i * 0.02, (i * 0.002, 0.0, 0.0))
    assert trail.at(5.0) == (0.5, 0.0, 0.0)
    assert trail.at(5.009) == (0.5, 0.0, 0.0)
    assert trail.at(100.0) == (0.598, 0.0, 0.0)
    assert trail.at(3.0) is None                 # older than the span: dropped
    assert len(trail._times) <= 2 * 51
    trail.record(1.0, (9.0, 9.0, 0.0))           # time went back: a new trail
    assert trail.at(5.0) == (9.0, 9.0, 0.0) and trail.at(0.99) is None


def test_a_guided_pose_is_carried_forward_by_what_the_robot_commanded_since_its_stamp():
    trail = CommandedTrail(span=5.0)
    trail.record(10.0, (2.0, 3.0, math.pi))      # the commanded frame is not the guide's
    trail.record(10.5, (1.7, 3.0, math.pi))      # 0.3 m forward
    trail.record(11.0, (1.7, 3.0, math.pi / 2))  # then a quarter turn to the right
    seen = StampedPose((1.0, 0.0, math.pi / 2), 10.0)
    now = carried_forward(seen, trail, 11.0)
    assert now.stamp == 10.0                     # its freshness is still when it was seen
    assert now.pose == pytest.approx((1.0, 0.3, 0.0))
    assert carried_forward(StampedPose((1.0, 0.0, 0.0), 9.0), trail, 11.0).pose == (1.0, 0.0, 0.0)
    assert carried_forward(None, trail, 11.0) is None


def _guided_goto(latency, carry):
    """(result, true pose at the end, largest distance between the pose driven on and the
    true pose) of a guided goto, the feed ``latency`` s late; as motion_decomp's node does,
    the feed is carried forward along the trail of the commanded odometry when ``carry``."""
    scheduler = m.MotionScheduler(guided_max_age=1.0)
    feed, trail = GuidedFeed(latency=latency), CommandedTrail(span=2.0)
    scheduler.submit('a', 1, 'pose_source', ['guided'])
    scheduler.submit('a', 2, 'goto', ['1.0', '0.5'])
    pose = commanded = (0.0, 0.0, 0.0)
    error, t = 0.0, 0.0
    while t < 60.0:
        trail.record(t, commanded)
        guided = carried_forward(feed(pose, t), trail, t) if carry else feed(pose, t)
        if guided is not None and scheduler.current is not None:
            error = max(error, distance(guided.pose, pose))
        command, feedback = scheduler.step(None, t, guided)
        if feedback is not None and feedback.action_id == 2:
            return feedback.result, pose, error
        if command is not None:
            pose = step(pose, *healthy(*command))
            commanded = integrate(commanded, command[0], command[1], DT)
        t += DT
    raise AssertionError('still driving after 60 s')


def test_a_guided_pose_late_by_two_robots_links_is_driven_on_as_if_on_time():
    # 0.6 s late: a camera frame, then the seeing robot's and this robot's links to a broker
    result, pose, error = _guided_goto(latency=0.6, carry=True)
    assert result == Event.OK
    assert distance(pose, (1.0, 0.5)) <= 0.05 + 0.005
    assert error <= 0.005
    _, _, uncarried_error = _guided_goto(latency=0.6, carry=False)
    assert uncarried_error >= 0.1 * 0.6 * 0.9      # the guided speed times the latency


def test_a_zero_stamp_counts_as_received_and_a_non_finite_pose_as_none():
    assert stamped_pose((1.0, 2.0, 0.5), 0.0, 42.0) == StampedPose((1.0, 2.0, 0.5), 42.0)
    assert stamped_pose((1.0, 2.0, 0.5), 41.9, 42.0) == StampedPose((1.0, 2.0, 0.5), 41.9)
    assert stamped_pose((float('nan'), 2.0, 0.5), 41.9, 42.0) is None
    assert stamped_pose((1.0, 2.0, float('inf')), 41.9, 42.0) is None


def test_pose_source_waits_in_the_fifo_then_the_guided_pose_drives():
    # odometry drifts (it says the robot is 1 m from where it is); the guided pose is right
    feed = GuidedFeed()
    robot = Robot(odom=lambda pose, t: (pose[0] + 1.0, pose[1], pose[2]), guided=feed)
    before = robot.submit('move', 0.3)
    setting = robot.submit('pose_source', 'guided')
    after = robot.submit('goto', 1.0, 0.5)
    assert robot.run() == ok(before, setting, after)
    assert robot.at(before)[0] < robot.at(setting)[0]
    assert distance(robot.pose, (1.0, 0.5)) <= 0.05 + 0.1 * 0.2   # + the 0.2 s latency at 0.1 m/s


def test_while_guided_the_guided_speeds_are_commanded():
    robot = Robot(guided=GuidedFeed())
    robot.submit('pose_source', 'guided')
    move = robot.submit('move', 0.3)
    turn = robot.submit('turn', -45)
    assert robot.run() == ok(1, move, turn)
    t_move, t_turn = robot.at(move)[0], robot.at(turn)[0]
    # (zero, not blind, until the first guided pose arrives, and at each end)
    assert {c for t, c in robot.commands if t < t_move and c != (0, 0)} == {(0.1, 0.0)}
    turning = [c for t, c in robot.commands if t_move < t < t_turn and c != (0, 0)]
    assert turning[0] == (0.0, 0.3) and all(v == 0.0 and 0.1 <= w <= 0.3 for v, w in turning)


def test_back_to_odom_uses_odometry_and_the_normal_speeds():
    robot = Robot(guided=lambda pose, t: None)
    robot.submit('pose_source', 'guided')
    robot.submit('pose_source', 'odom')
    move = robot.submit('move', 0.2)
    assert robot.run() == ok(1, 2, move)
    assert {c for t, c in robot.commands[:-1]} == {(0.2, 0.0)}


def test_a_stale_guided_pose_commands_nothing_and_ends_no_progress():
    # the guided pose stops coming 1 s into the drive
    feed = GuidedFeed()
    robot = Robot(guided=lambda pose, t: feed(pose, min(t, 1.0)))
    robot.submit('pose_source', 'guided')
    goto = robot.submit('goto', 2, 0)
    feedbacks = robot.run()
    assert feedbacks[-1] == m.Feedback('a', goto, Event.NO_PROGRESS)
    last_stamp = 1.0 - 0.2
    stale_from = last_stamp + 0.5 + DT
    assert {c for t, c in robot.commands if t > stale_from and c != (0.0, 0.0)} == set()
    assert any(c[0] > 0 for t, c in robot.commands if t < stale_from)
    # no_progress 1 s after the pose last changed (it froze at the last guided pose)
    assert robot.at(goto)[0] == pytest.approx(last_stamp + 0.2 + 1.0, abs=3 * DT)


def test_no_guided_pose_at_all_is_no_progress_without_a_command():
    robot = Robot(guided=lambda pose, t: None)
    robot.submit('pose_source', 'guided')
    move = robot.submit('move', 1)
    assert robot.run()[-1] == m.Feedback('a', move, Event.NO_PROGRESS)
    assert {c for _, c in robot.commands} == {(0.0, 0.0)}


def test_the_scheduler_picks_the_pose_of_its_source():
    s = m.MotionScheduler(guided_max_age=0.5)
    guided = StampedPose((5.0, 5.0, 0.0), 10.0)
    assert s.pose((1.0, 1.0, 0.0), guided, 10.2) == (1.0, 1.0, 0.0)
    s.submit('a', 1, 'pose_source', ['guided'])
    s.step(None, 10.0)
    assert s.pose((1.0, 1.0, 0.0), guided, 10.2) == (5.0, 5.0, 0.0)
    assert s.pose((1.0, 1.0, 0.0), guided, 10.6) is None


def test_a_move_or_turn_whose_pose_goes_missing_commands_zero_until_it_is_back():
    for action, param, driving in (('move', '1', (0.2, 0.0)), ('turn', '90', (0.0, -0.5))):
        mon = m.MotionMonitor(m.parse_motion(action, [param]), (0.0, 0.0, 0.0), 0.0)
        assert mon.update((0.0, 0.0, 0.0), 0.1) is None and mon.command() == driving
        assert mon.update(None, 0.2) is None and mon.command() == (0.0, 0.0)
        assert mon.update((float('nan'), 0.0, 0.0), 0.3) is None and mon.command() == (0.0, 0.0)
        assert mon.update((0.0, 0.0, 0.0), 0.4) is None and mon.command() == driving
