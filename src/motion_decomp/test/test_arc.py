"""Unit tests of motion_decomp.arc: driving a base with a one-wheel fault in planned arcs
(compensate), on the tests' kinematic model (no ROS). Run with -s to see the measurements."""
import math

import pytest

from motion_decomp import arc, goto
from motion_decomp.arc import ArcSteering
from motion_decomp.goto import Goal, GotoController
from motion_model import drive, healthy, off_line, one_wheel_fault, path_length

TOLERANCE = 0.05
CURVATURE = {'left': 2.0, 'right': -2.0}    # what the thesis's fault model gives
STARTS = [(0.0, 0.0, 0.0), (0.0, 0.0, 2.0), (0.5, -0.3, -1.0), (1.0, 1.0, 3.0), (-0.4, 0.6, -2.5)]
GOAL = Goal(1.0, 0.2, None)


def controller(goal, curvature=None, **options):
    steering = ArcSteering(curvature) if curvature else None
    return GotoController(goal, 0.0, steering, xy_tolerance=TOLERANCE, no_progress_time=1.0, **options)


# ---------------------------------------------------------------- geometry

def test_the_target_is_the_goal_or_a_segment_along_the_line_to_it():
    assert arc.segment_target((0, 0, 1.0), (0.2, 0.1), 0.3) == (0.2, 0.1)
    assert arc.segment_target((1, 1, 0), (1, 3), 0.3) == pytest.approx((1, 1.3))
    assert arc.segment_target((0, 0, 0), (-3, -4), 0.5) == pytest.approx((-0.3, -0.4))


@pytest.mark.parametrize('curvature', [2.0, -2.0, 0.5, -5.0])
def test_the_planned_arc_passes_through_the_target(curvature):
    pose, target = (0.3, -0.2, 2.0), (0.5, 0.1)
    heading, alpha = arc.arc_heading(pose, target, curvature)
    chord = math.hypot(0.2, 0.3)
    assert alpha == pytest.approx(math.asin(chord * abs(curvature) / 2))
    # drive that arc exactly for its length 2 * alpha / |K|: it ends on the target
    length = 2 * alpha / abs(curvature)
    end = heading + curvature * length
    radius = 1 / curvature
    x = pose[0] + radius * (math.sin(end) - math.sin(heading))
    y = pose[1] - radius * (math.cos(end) - math.cos(heading))
    assert (x, y) == pytest.approx(target, abs=1e-9)


def test_a_left_curvature_starts_right_of_the_bearing_and_a_right_one_left_of_it():
    bearing = math.atan2(0.3, 0.0)        # the target straight "north"
    left, alpha = arc.arc_heading((0, 0, 0), (0, 0.3), 2.0)
    right, _ = arc.arc_heading((0, 0, 0), (0, 0.3), -2.0)
    assert left == pytest.approx(bearing - alpha) and alpha == pytest.approx(math.asin(0.3))
    assert right == pytest.approx(bearing + alpha)


def test_the_segment_is_capped_by_the_curvature():
    assert ArcSteering(2.0, 0.3).segment_length == 0.3
    assert ArcSteering(2.0, 5.0).segment_length == pytest.approx(0.9)       # 0.9 * 2 / 2
    assert ArcSteering(-8.0, 0.3).segment_length == pytest.approx(0.225)    # 0.9 * 2 / 8


@pytest.mark.parametrize('curvature, segment', [(0.0, 0.3), (float('nan'), 0.3), (2.0, 0.0),
                                                 (2.0, float('inf'))])
def test_bad_steering_parameters_are_refused(curvature, segment):
    with pytest.raises(ValueError):
        ArcSteering(curvature, segment)


# ---------------------------------------------------------------- the phases of one arc

def test_it_turns_on_the_spot_to_the_arc_heading_then_drives_with_zero_angular_speed():
    c = controller(Goal(0.3, 0.0, None), 2.0)
    c.update((0.0, 0.0, 0.0), 0.0)
    assert c.phase == ArcSteering.TURN
    v, w = c.command()
    assert v == 0 and w < 0             # left curvature: the arc starts to the right
    assert c.steering.heading == pytest.approx(-math.asin(0.3))
    c.update((0.0, 0.0, c.steering.heading + 0.01), 0.1)
    assert c.phase == ArcSteering.DRIVE and c.command() == (0.2, 0.0)


def test_a_far_goal_is_approached_segment_by_segment():
    c = controller(Goal(2.0, 0.0, None), -2.0)
    c.update((0.0, 0.0, 0.0), 0.0)
    assert c.steering.target == pytest.approx((0.3, 0.0))
    assert c.steering.heading == pytest.approx(math.asin(0.3))   # right curvature: to the left


def test_an_arc_ends_at_the_closest_approach_and_the_next_is_planned_from_there():
    c = controller(Goal(2.0, 0.0, None), 2.0)
    heading = -math.asin(0.3)
    c.update((0.0, 0.0, heading), 0.0)
    assert c.phase == ArcSteering.DRIVE and c.steering.target == pytest.approx((0.3, 0.0))
    # a healthy base drives straight along the heading: closest to (0.3, 0) after 0.3 cos(alpha)
    closest = 0.3 * math.cos(heading)
    for s in (0.1, 0.2, closest):
        c.update((s * math.cos(heading), s * math.sin(heading), heading), s)
        assert c.phase == ArcSteering.DRIVE and c.command() == (0.2, 0.0)
    past = closest + 0.02
    c.update((past * math.cos(heading), past * math.sin(heading), heading), 1.0)
    assert c.phase == ArcSteering.TURN and c.command()[0] == 0     # a new arc, from here
    assert c.steering.arcs == 1
    assert c.steering.target[0] > 0.3


def test_an_arc_that_turns_more_than_planned_ends_before_it_circles():
    c = controller(Goal(0.3, 0.0, None), 2.0)
    alpha = math.asin(0.3)
    c.update((0.0, 0.0, -alpha), 0.0)
    assert c.phase == ArcSteering.DRIVE
    # the base spins on the spot while driving (getting no farther from the target)
    for i, yaw in enumerate([-alpha + 0.3, -alpha + 0.6, -alpha + 0.9]):
        c.update((0.0, 0.0, yaw), 0.1 * (i + 1))
    assert 0.9 < 2 * alpha + arc.ARC_TURN_MARGIN
    assert c.phase == ArcSteering.DRIVE
    c.update((0.0, 0.0, -alpha + 2 * alpha + arc.ARC_TURN_MARGIN + 0.01), 0.5)
    assert c.phase == ArcSteering.TURN


def test_it_slows_down_only_on_the_last_arc():
    far = controller(Goal(2.0, 0.0, None), 2.0)
    heading = -math.asin(0.3)
    far.update((0.0, 0.0, heading), 0.0)
    far.update((0.25 * math.cos(heading), 0.25 * math.sin(heading), heading), 1.0)
    assert far.command() == (0.2, 0.0)         # 5 cm before an intermediate target: full speed
    near = controller(Goal(0.3, 0.0, None), 2.0)
    near.update((0.0, 0.0, heading), 0.0)
    near.update((0.25 * math.cos(heading), 0.25 * math.sin(heading), heading), 1.0)
    v, w = near.command()
    assert w == 0 and v == pytest.approx(arc.SLOWDOWN_GAIN * math.hypot(
        0.3 - 0.25 * math.cos(heading), 0.25 * math.sin(heading)))


# ---------------------------------------------------------------- reaching goals under the fault

@pytest.mark.parametrize('start', STARTS)
@pytest.mark.parametrize('side', ['left', 'right'])
@pytest.mark.parametrize('gain_error', [1.0, 0.8, 1.2], ids=['exact', '20%_low', '20%_high'])
def test_compensated_goto_reaches_the_goal_under_the_fault(side, start, gain_error):
    run = drive(controller(GOAL, CURVATURE[side] * gain_error), start, one_wheel_fault(side))
    assert run.result == goto.SUCCEEDED
    assert math.hypot(GOAL.x - run.pose[0], GOAL.y - run.pose[1]) <= TOLERANCE
    # while driving, it never asks for an angular speed: the fault does the turning
    assert all(w == 0 for v, w in run.commands if v != 0)


@pytest.mark.parametrize('side', ['left', 'right'])
def test_compensation_survives_a_lagging_base(side):
    # commands reach the wheels 5 cycles (100 ms) late
    run = drive(controller(GOAL, CURVATURE[side]), (0.0, 0.0, 0.5), one_wheel_fault(side), lag=5)
    assert run.result == goto.SUCCEEDED
    assert math.hypot(GOAL.x - run.pose[0], GOAL.y - run.pose[1]) <= TOLERANCE


def test_compensating_on_a_healthy_base_still_arrives():
    # a wrong diagnosis: the arcs come out straight, each ends at its closest approach
    run = drive(controller(GOAL, 2.0), (0.0, 0.0, 0.0), healthy)
    assert run.result == goto.SUCCEEDED
    assert math.hypot(GOAL.x - run.pose[0], GOAL.y - run.pose[1]) <= TOLERANCE


@pytest.mark.parametrize('side', ['left', 'right'])
@pytest.mark.parametrize('distance', [1.0, 2.0])
def test_without_compensation_the_fault_takes_a_winding_path_and_longer(side, distance):
    """The measurement behind compensate: the same fault, the same goal straight ahead,
    goto with compensation against goto steering as for a healthy base (it keeps turning back
    on the spot, its angular commands lost to the fault)."""
    goal = Goal(distance, 0.0, None)
    compensated = drive(controller(goal, CURVATURE[side]), (0, 0, 0), one_wheel_fault(side))
    plain = drive(controller(goal), (0, 0, 0), one_wheel_fault(side))
    rows = []
    for name, run in (('compensated', compensated), ('uncompensated', plain)):
        rows.append((name, run.result, run.time, off_line(run.path, (0, 0), (goal.x, goal.y)),
                     path_length(run.path), run.turns))
        print('%s %.0f m %-13s %s in %.1f s, %.3f m off the line, path %.2f m, %d turns' %
              ((side, distance) + rows[-1]))
    assert compensated.result == goto.SUCCEEDED
    (_, _, t_c, off_c, _, turns_c), (_, _, t_p, off_p, _, turns_p) = rows
    assert off_c < 0.03 and off_p > 3 * off_c
    assert t_p > 1.1 * t_c and turns_p > turns_c
