"""Outcome of one fleet campaign run (issue 34), judged from what its bag recorded (no ROS).

Events as :func:`rason_campaign.bagread.read_events` gives them with the fleet's robots:
``message`` (the agents' messages), ``diagnosis`` and ``mission`` (the ``rason/diagnosis`` and
``rason/mission`` statuses) and ``pose`` (each robot's true pose). The agent of robot ``rK``
is ``rK_robot`` (fleet_case_study.launch's agent prefix).

Every robot of the fleet drives the case study's mission (1 m ahead and back). Per robot:

- its diagnosis against the fault injected into it (``none`` for the others; a robot whose
  mission ran without a fault may report none at all, which is right);
- its mission: claimed completed by its agent, AND the robot(s) that completed it came within
  TOLERANCE of the goal 1 m ahead of its true start, AND, when the robot completed it itself,
  it ended within TOLERANCE of its start;
- for a faulty robot, the time to diagnosis: from its first call for a watcher
  (``callForBids``) to its diagnosis, in simulated seconds (it includes waiting for a robot
  free to watch: one whose own mission ended), and from its first award of the help (the
  watcher's search and the watched move: what the choice of watcher decides); and the robots
  that took its tasks (``accepted`` after an ``award``).
"""
import math
import re

from rason_campaign.mission import TOLERANCE, goal_of
from rason_campaign.steps import classify

AGENT_SUFFIX = '_robot'
# award(contract(r4_robot,2),help(r4_robot,unknown)): the contract and the task's functor
AWARD = re.compile(r'award\((contract\([^()]*\)),(\w+)\(')


def agent_of(robot):
    return robot + AGENT_SUFFIX


def robot_of(agent):
    return agent[:-len(AGENT_SUFFIX)] if agent.endswith(AGENT_SUFFIX) else agent


def parse_pairs(text):
    """``r3:left_actuator r4:odometry`` -> {'r3': 'left_actuator', 'r4': 'odometry'}."""
    return dict(pair.split(':', 1) for pair in text.split())


def _first(events, kind, agent):
    return next(((t, f) for t, k, f in events if k == kind and f.get('agent') == agent),
                (None, None))


def _poses(events, robot, until=None):
    return [f for t, k, f in events
            if k == 'pose' and f.get('robot') == robot and (until is None or t <= until)]


def _distance(pose, point):
    return math.hypot(pose['x'] - point[0], pose['y'] - point[1])


def contractors(events, caller, task='help'):
    """The agents that accepted an award of ``task`` from ``caller``, in order. (The recorder
    may write an answer before the message it answers when both fall in one clock tick, so
    the awards are gathered first.)"""
    messages = [f for _, kind, f in events if kind == 'message']
    awarded = set()
    for f in messages:
        match = AWARD.match(f['content']) if f['sender'] == caller else None
        if match and match.group(2) == task:
            awarded.add((f['receiver'], match.group(1)))
    return [f['sender'] for f in messages
            if f['receiver'] == caller and f['content'].startswith('accepted(')
            and (f['sender'], f['content'][len('accepted('):-1]) in awarded]


def _since(start, end):
    return round(end - start, 3) if start is not None and end is not None else None


def judge_robot(robot, fault, events, tolerance=TOLERANCE):
    """What one robot of the run did.

    :rtype: dict with robot, fault, diagnosis, diagnosis_outcome, called, awarded (its first
        award of help), diagnosed, time_to_diagnosis (from the call), award_to_diagnosis,
        helpers, mission (claimed, completed, by, recovery, goal_error,
        start_error, reason)
    """
    agent = agent_of(robot)
    diagnosed, diagnosis = _first(events, 'diagnosis', agent)
    component = diagnosis.get('component') if diagnosis else None
    if fault == 'none' and component is None:
        outcome = 'correct'
    else:
        outcome = classify(fault, component)
    called = next((t for t, k, f in events if k == 'message' and f['sender'] == agent
                   and f['content'].startswith('callForBids(')), None)
    awarded = next((t for t, k, f in events if k == 'message' and f['sender'] == agent
                    and (AWARD.match(f['content']) or [None, None, None])[2] == 'help'), None)
    out = {'robot': robot, 'fault': fault, 'diagnosis': component, 'diagnosis_outcome': outcome,
           'called': called, 'awarded': awarded, 'diagnosed': diagnosed,
           'time_to_diagnosis': _since(called, diagnosed),
           'award_to_diagnosis': _since(awarded, diagnosed),
           'helpers': [robot_of(a) for a in contractors(events, agent)]}
    out['mission'] = judge_mission(robot, events, tolerance)
    return out


def judge_mission(robot, events, tolerance=TOLERANCE):
    """The robot's mission: what its agent claimed, checked against the true poses."""
    ended, mission = _first(events, 'mission', agent_of(robot))
    out = {'claimed': False, 'completed': False, 'by': [], 'recovery': None, 'ended': ended,
           'goal_error': None, 'start_error': None}
    if mission is None:
        out['reason'] = 'no mission outcome reported'
        return out
    out['by'] = [robot_of(a.strip()) for a in mission.get('by', '').split(',') if a.strip()]
    out['recovery'] = mission.get('recovery')
    out['claimed'] = mission.get('completed') == 'true'
    if not out['claimed']:
        out['reason'] = 'not completed (diagnosis %s, recovery %s)' % (
            mission.get('diagnosis'), out['recovery'])
        return out
    poses = _poses(events, robot)
    if not poses:
        out['reason'] = 'no true pose of %s recorded' % robot
        return out
    start = poses[0]
    goal = goal_of(start)
    reached = [_distance(p, goal) for by in out['by'] for p in _poses(events, by, ended)]
    out['goal_error'] = round(min(reached), 4) if reached else None
    if robot in out['by']:
        at_end = _poses(events, robot, ended)
        out['start_error'] = round(_distance(at_end[-1], (start['x'], start['y'])), 4)
    if out['goal_error'] is None:
        out['reason'] = 'no true pose of %s recorded' % ', '.join(out['by'] or ['anyone'])
    elif out['goal_error'] > tolerance:
        out['reason'] = 'goal missed by %.3f m (> %.2f m)' % (out['goal_error'], tolerance)
    elif out['start_error'] is not None and out['start_error'] > tolerance:
        out['reason'] = 'ended %.3f m from its start (> %.2f m)' % (out['start_error'], tolerance)
    else:
        out['completed'] = True
        out['reason'] = 'completed by %s (recovery %s)' % (', '.join(out['by']), out['recovery'])
    return out


def judge_run(args, events, failure=None, tolerance=TOLERANCE):
    """The outcome of a fleet run with the launch arguments ``args`` (robots, faults).

    :rtype: dict with robots (judge_robot's per robot), completed (every robot's mission),
        faulty_completed, wrong (wrong diagnoses), undiagnosed (faulty robots without a
        diagnosis), messages (agent messages sent), reason
    """
    events = sorted(events, key=lambda e: e[0])
    faults = parse_pairs(args['faults'])
    robots = [judge_robot(r, faults.get(r, 'none'), events, tolerance)
              for r in args['robots'].split()]
    faulty = [r for r in robots if r['fault'] != 'none']
    undone = [r for r in robots if not r['mission']['completed']]
    out = {'robots': robots,
           'completed': not undone and not failure,
           'faulty_completed': sum(r['mission']['completed'] for r in faulty),
           'wrong': sum(r['diagnosis_outcome'] == 'wrong' for r in robots),
           'undiagnosed': sum(r['diagnosis_outcome'] == 'undiagnosed' for r in faulty),
           'messages': sum(1 for _, k, _f in events if k == 'message')}
    reasons = ['%s: %s' % (r['robot'], r['mission']['reason']) for r in undone]
    reasons += ['%s diagnosed %s (fault %s)' % (r['robot'], r['diagnosis'], r['fault'])
                for r in robots if r['diagnosis_outcome'] == 'wrong']
    if failure:
        reasons.insert(0, failure)
    out['reason'] = '; '.join(reasons) or 'every mission completed, every diagnosis right'
    return out
