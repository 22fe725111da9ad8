"""Outcome of one fault-tolerance run (issue 15), judged from what its bag recorded (no ROS).

Events as in :mod:`rason_campaign.steps`, plus

- ``(t, 'mission', {'agent', 'completed', 'by', 'recovery', 'diagnosis'})`` from the
  ``rason/mission`` status on /diagnostics;
- ``(t, 'pose', {'robot', 'x', 'y', 'yaw'})`` from <robot>/true_pose (the simulator's truth).

What the agents say is checked against the truth:

- mission start = Faulty's first ``move`` action; Faulty's true start pose is its last true
  pose at or before it; the goal is the point MISSION_LENGTH ahead of that pose;
- the mission's end and who completed it: the first ``rason/mission`` status (recovery
  arm). The baseline (the thesis's agent) reports no mission; its mission ends normally
  when Faulty drove to the goal and back with no fault noticed, i.e. it concluded ``none``
  without asking for help: then the end is that diagnosis and Faulty completed it. After
  any other diagnosis it stops, so with a fault the baseline never completes;
- goal error = the smallest true distance to the goal of the completing robot(s) up to the
  end; start error = Faulty's true distance from its start at the end (only when Faulty
  completed);
- a run counts as completed only when the agents say so AND the goal error is at most
  TOLERANCE AND, when Faulty completed, the start error is at most TOLERANCE too.
"""
import math

from rason_campaign.steps import classify, extract_steps

MISSION_LENGTH = 1.0    # metres ahead of Faulty's true start (the thesis's move(1))
TOLERANCE = 0.15        # metres, on the goal and (when Faulty completed) on the start
FAULTY = 'faulty'


class MissionOutcome(object):
    """What one run achieved. Times in simulated seconds, distances in metres; None when
    not measured."""

    FIELDS = ('claimed', 'completed', 'by', 'recovery', 'diagnosis', 'diagnosis_outcome',
              'start', 'end', 'time', 'goal', 'goal_error', 'start_error', 'reason')

    def __init__(self, **fields):
        for name in self.FIELDS:
            setattr(self, name, fields.get(name))

    def to_dict(self):
        return {name: getattr(self, name) for name in self.FIELDS}


def _robots_of_agents(events):
    """Agent name -> the robot its actions come from (agents named after their robot
    otherwise, as in the case study)."""
    robots = {}
    for _, kind, f in events:
        if kind == 'action' and f.get('agent') and f.get('robot'):
            robots.setdefault(f['agent'], f['robot'])
    return robots


def _poses(events, robot, until=None):
    return [(t, f) for t, kind, f in events
            if kind == 'pose' and f.get('robot') == robot and (until is None or t <= until)]


def _dist(pose, point):
    return math.hypot(pose['x'] - point[0], pose['y'] - point[1])


def true_start(events, start):
    """Faulty's true pose when its mission started: the last one at or before ``start``
    (the first one recorded when none is that early), or None."""
    poses = _poses(events, FAULTY)
    if not poses:
        return None
    before = [f for t, f in poses if start is not None and t <= start]
    return before[-1] if before else poses[0][1]


def goal_of(start_pose, length=MISSION_LENGTH):
    """The point ``length`` ahead of ``start_pose`` (dict with x, y, yaw)."""
    return (start_pose['x'] + length * math.cos(start_pose['yaw']),
            start_pose['y'] + length * math.sin(start_pose['yaw']))


def _claim(events, arm, steps):
    """(claimed, end time, by, recovery, reason if not claimed) from the agents' reports."""
    missions = [(t, f) for t, kind, f in events if kind == 'mission']
    if missions:
        t, f = missions[0]
        by = [a.strip() for a in f.get('by', '').split(',') if a.strip()]
        recovery = f.get('recovery')
        if f.get('completed') == 'true':
            return True, t, by, recovery, None
        return False, t, by, recovery, 'mission not completed (diagnosis %s, recovery %s)' % (
            f.get('diagnosis'), recovery)
    if arm == 'baseline':
        # The thesis's agent: its mission ran to its end only when it concluded none
        # without having asked for help (a false positive stops it after the diagnosis).
        if steps.component == 'none' and steps.help is None and steps.diagnosed is not None:
            return True, steps.diagnosed, [FAULTY], 'none', None
        if steps.component is None:
            return False, None, [], None, 'no diagnosis recorded'
        return False, None, [], None, 'stopped after the diagnosis %s (thesis behaviour)' % (
            steps.component)
    return False, None, [], None, 'no rason/mission status recorded'


def judge_mission(fault, arm, events, failure=None, tolerance=TOLERANCE):
    """The outcome of a run with ``fault`` injected, in ``arm`` (``recovery`` or
    ``baseline``), from its events; ``failure`` is the runner's or bag reader's text when
    the run itself went wrong (a timeout, a crash, no bag).

    :rtype: MissionOutcome
    """
    events = sorted(events, key=lambda e: e[0])
    steps = extract_steps(events)
    missions = [f for _, kind, f in events if kind == 'mission']
    diagnosis = steps.component
    if diagnosis is None and missions:
        diagnosis = missions[0].get('diagnosis')
    claimed, end, by, recovery, reason = _claim(events, arm, steps)
    out = MissionOutcome(claimed=claimed, completed=False, by=by, recovery=recovery,
                         diagnosis=diagnosis, diagnosis_outcome=classify(fault, diagnosis),
                         start=steps.start, end=end)
    start_pose = true_start(events, steps.start)
    if start_pose is not None:
        out.goal = tuple(round(c, 4) for c in goal_of(start_pose))
    if claimed:
        robots = _robots_of_agents(events)
        reached = [_dist(f, out.goal) for agent in by
                   for _, f in _poses(events, robots.get(agent, agent), end)] \
            if out.goal else []
        out.goal_error = round(min(reached), 4) if reached else None
        if FAULTY in by and start_pose is not None:
            at_end = _poses(events, robots.get(FAULTY, FAULTY), end)
            if at_end:
                out.start_error = round(_dist(at_end[-1][1], (start_pose['x'],
                                                             start_pose['y'])), 4)
        if out.goal_error is None:
            reason = 'no true pose of %s recorded' % (', '.join(by) or 'anyone')
        elif out.goal_error > tolerance:
            reason = 'goal missed by %.3f m (> %.2f m)' % (out.goal_error, tolerance)
        elif FAULTY in by and out.start_error is None:
            reason = 'no true pose of Faulty at the end'
        elif FAULTY in by and out.start_error > tolerance:
            reason = 'Faulty ended %.3f m from its start (> %.2f m)' % (out.start_error,
                                                                        tolerance)
        elif steps.start is None:
            reason = 'Faulty never moved (no move action recorded)'
        else:
            out.completed = True
            out.time = round(end - steps.start, 3)
            reason = 'completed by %s (recovery %s)' % (', '.join(by), recovery)
    if failure:  # e.g. the launch did not end by itself: said, whatever the mission did
        reason = '%s; %s' % (failure, reason) if reason else failure
    out.reason = reason
    return out
