"""Unit tests of motion_decomp.goto: driving to a goal pose, on an ideal unicycle integrated
here (no ROS)."""
import math

import pytest

from motion_decomp import goto
from motion_decomp.goto import Goal, GotoController

DT = 0.02    # 50 Hz, the simulator's odometry rate


def drive(controller, pose, steps=5000, lag=0):
    """Run the controller on a unicycle from ``pose``; ``lag`` cycles of command delay.
    Returns (result, final pose, path of poses)."""
    x, y, yaw = pose
    t = 0.0
    path = [pose]
    pending = [(0.0, 0.0)] * lag
    for _ in range(steps):
        result = controller.update((x, y, yaw), t)
        if result is not None:
            return result, (x, y, yaw), path
        pending.append(controller.command())
        v, w = pending.pop(0)
        x += v * math.cos(yaw) * DT
        y += v * math.sin(yaw) * DT
        yaw = math.atan2(math.sin(yaw + w * DT), math.cos(yaw + w * DT))
        t += DT
        path.append((x, y, yaw))
    raise AssertionError('no result after %d steps at %r' % (steps, (x, y, yaw)))


@pytest.mark.parametrize('start, goal', [
    ((0, 0, 0), Goal(1.0, 0.0, None)),              # straight ahead
    ((0, 0, 0), Goal(-1.0, 0.5, None)),             # behind: turns first
    ((0, 0, math.pi / 2), Goal(0.5, -2.0, None)),
    ((1, 1, 0), Goal(1.02, 1.0, None)),             # within tolerance already
])
def test_reaches_the_position_within_tolerance(start, goal):
    result, (x, y, _), _ = drive(GotoController(goal, 0.0), start)
    assert result == goto.SUCCEEDED
    assert math.hypot(goal.x - x, goal.y - y) <= goto.DEFAULTS['xy_tolerance']


def test_it_aims_at_half_the_tolerance():
    for goal in (Goal(1.0, 0.0, 0.5), Goal(-0.7, 0.3, None)):
        _, (x, y, yaw), _ = drive(GotoController(goal, 0.0), (0, 0, 0))
        assert math.hypot(goal.x - x, goal.y - y) <= goto.DEFAULTS['xy_tolerance'] / 2 + 0.001
        if goal.yaw is not None:
            assert abs(goal.yaw - yaw) <= goto.DEFAULTS['yaw_tolerance'] / 2 + 0.001


def test_inside_the_tolerance_it_stops_once_it_gets_no_closer():
    c = GotoController(Goal(1.0, 0.0, None), 0.0)
    assert c.update((0.96, 0.0, 0.0), 0.0) is None      # 4 cm: inside, still closing in
    assert c.update((0.97, 0.0, 0.0), 0.1) is None      # 3 cm: closer
    assert c.update((0.97, 0.02, 0.0), 0.2) == goto.SUCCEEDED   # 3.6 cm: farther again


def test_turns_on_the_spot_before_driving_away():
    _, _, path = drive(GotoController(Goal(0.0, 1.0, None), 0.0), (0, 0, 0))
    # until it faces the goal (within FACING) it has not moved
    facing = next(i for i, p in enumerate(path) if abs(p[2] - math.pi / 2) <= goto.FACING)
    assert all(math.hypot(p[0], p[1]) < 1e-9 for p in path[:facing])


def test_ends_with_the_goal_heading_when_it_has_one():
    result, (x, y, yaw), _ = drive(GotoController(Goal(1.0, 1.0, math.radians(-90)), 0.0), (0, 0, 0))
    assert result == goto.SUCCEEDED
    assert math.hypot(1 - x, 1 - y) <= goto.DEFAULTS['xy_tolerance']
    assert abs(math.remainder(yaw - math.radians(-90), 2 * math.pi)) <= goto.DEFAULTS['yaw_tolerance']


def test_a_lagging_base_still_gets_there():
    # commands reach the wheels 5 cycles (100 ms) late: it may overshoot, then comes back
    result, (x, y, _), _ = drive(GotoController(Goal(2.0, -1.0, 0.0), 0.0), (0, 0, 3.0), lag=5)
    assert result == goto.SUCCEEDED and math.hypot(2 - x, -1 - y) <= 0.05


def test_speeds_stay_within_the_limits():
    c = GotoController(Goal(5.0, 5.0, None), 0.0, linear_speed=0.3, angular_speed=0.4)
    for pose in [(0, 0, 0), (0, 0, math.pi / 4), (1, 1, math.pi / 4 + 0.3), (4.99, 4.99, 0)]:
        c.update(pose, 0.1)
        v, w = c.command()
        assert 0 <= v <= 0.3 and abs(w) <= 0.4


def test_no_progress_when_the_pose_does_not_change():
    c = GotoController(Goal(1.0, 0.0, None), 10.0, no_progress_time=1.0)
    assert c.update((0, 0, 0), 10.0) is None
    assert c.command()[0] > 0
    assert c.update((0, 0, 0), 10.9) is None
    assert c.update((0, 0, 0), 11.1) == goto.NO_PROGRESS
    assert c.command() == (0.0, 0.0)
    assert c.update((0.5, 0, 0), 11.2) == goto.NO_PROGRESS    # ended stays ended


def test_no_odometry_at_all_is_no_progress_without_a_command():
    c = GotoController(Goal(1.0, 0.0, None), 0.0, no_progress_time=1.0)
    assert c.update(None, 0.5) is None and c.command() == (0.0, 0.0)
    assert c.update((float('nan'), 0, 0), 0.9) is None and c.command() == (0.0, 0.0)
    assert c.update(None, 1.1) == goto.NO_PROGRESS


def test_timeout():
    c = GotoController(Goal(100.0, 0.0, None), 0.0, max_duration=5.0)
    result, (x, _, _), _ = drive(c, (0, 0, 0))
    assert result == goto.TIMEOUT and 0.5 < x < 1.1


@pytest.mark.parametrize('quaternion, yaw', [
    ((0, 0, 0, 0), None),
    ((0, 0, 0, 1), 0.0),
    ((0, 0, math.sin(math.pi / 4), math.cos(math.pi / 4)), math.pi / 2),
])
def test_goal_from_pose(quaternion, yaw):
    goal = goto.goal_from_pose(1, 2, *quaternion)
    assert (goal.x, goal.y) == (1.0, 2.0)
    assert goal.yaw == (None if yaw is None else pytest.approx(yaw))


@pytest.mark.parametrize('pose, message', [
    ((float('nan'), 0, 0, 0, 0, 1), 'not finite'),
    ((0, 0, 0, 0, 0, 2), 'not a unit quaternion'),
    ((0, 0, 1, 0, 0, 0), 'about z only'),
])
def test_bad_goals_are_refused(pose, message):
    with pytest.raises(ValueError, match=message):
        goto.goal_from_pose(*pose)


def test_bad_options_are_refused():
    with pytest.raises(ValueError, match='unknown option'):
        GotoController(Goal(0, 0, None), 0.0, speed=1)
    with pytest.raises(ValueError, match='xy_tolerance must be a positive number'):
        GotoController(Goal(0, 0, None), 0.0, xy_tolerance=0)


def test_a_goal_function_is_resolved_at_the_first_pose():
    seen = []

    def ahead(pose):
        seen.append(pose)
        return Goal(pose[0] + math.cos(pose[2]), pose[1] + math.sin(pose[2]), None)

    c = GotoController(ahead, 0.0, no_progress_time=1.0)
    assert c.update(None, 0.5) is None and c.goal is None and c.command() == (0.0, 0.0)
    result, (x, y, _), _ = drive(c, (1.0, 2.0, math.pi / 2))
    assert seen == [(1.0, 2.0, math.pi / 2)]
    assert result == goto.SUCCEEDED and math.hypot(1.0 - x, 3.0 - y) <= 0.05


def test_a_steering_drives_until_the_position_then_the_controller_aligns():
    calls = []

    class Straight(object):
        phase = 'mine'

        def steer(self, pose, goal, linear_speed, angular_speed):
            calls.append((goal, linear_speed, angular_speed))
            return (linear_speed, 0.0)

    c = GotoController(Goal(1.0, 0.0, 0.5), 0.0, Straight(), linear_speed=0.3, angular_speed=0.4)
    assert c.update((0.0, 0.0, 0.0), 0.0) is None
    assert c.command() == (0.3, 0.0) and c.phase == 'mine'
    assert calls == [(Goal(1.0, 0.0, 0.5), 0.3, 0.4)]
    assert c.update((0.99, 0.0, 0.0), 1.0) is None
    assert c.phase == GotoController.ALIGN and c.command()[0] == 0 and c.command()[1] > 0
    assert len(calls) == 1        # the steering is not asked once the position is reached
