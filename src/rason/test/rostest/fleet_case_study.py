#!/usr/bin/python3
"""The case study as one fleet program on simulated robots (issue 34): fleet_case_study.launch,
every robot running agents/fleet/fleet_robot.mas2j, over either fleet channel. The test reads
what the callers print (the contract net's awards, who took them, who found them) on /rosout
and the diagnoses on /diagnostics.

Private parameters:
  ~diagnoses        "agent:component ..." : each faulty robot's agent and the component its
                    diagnosis must name
  ~kill_helper_of   an agent of diagnoses: once the robot it awarded has found it, that
                    robot's rason_mas is killed (SIGKILL); the caller must award another
                    bidder within ~next_award_within seconds and still be diagnosed right
  ~next_award_within  seconds, default 5
  ~missions         "agent:recovery ...": agents whose missions must be completed after their
                    diagnosis (fleet_case_study.launch recovery:=true) with that recovery,
                    judged from the simulator's true poses: the goal 1 m ahead of the robot's
                    start reached within ~tolerance, and the robot back within ~tolerance of
                    its start; for delegate, the goal reached by the robot that took the
                    mission over (the one it awarded reach(...) last, not a faulty one). A
                    guide (guided) or a delegate must have been chosen by contract net.
  ~tolerance        metres (0.15)
  ~timeout          seconds (wall) for the whole scenario
"""
import math
import os
import re
import signal
import threading
import time
import unittest
from xmlrpc.client import ServerProxy

import rosgraph
import rason_rospy
import rospy
import rostest
from diagnosis_reporter.report import MISSION_STATUS_NAME, STATUS_NAME
from diagnostic_msgs.msg import DiagnosticArray
from geometry_msgs.msg import PoseStamped
from rosgraph_msgs.msg import Log


MISSION_LENGTH = 1.0     # metres ahead of each robot's start (the thesis's mission)
FLEET = ['r%d' % k for k in range(1, 9)]     # rason_sim's fleet.yaml
# the lines of agents/fleet/contract_net.asl and case_study/faulty_dialogue.asl the test reads
AGENT_LINE = re.compile(r'^\[(\w+)\] (.*)$')
AWARDING = re.compile(r'^awarding (\w+)\(.* to (\w+) \(bid ')
TOOK = re.compile(r'^(\w+) took (\w+)\(')
FOUND = re.compile(r'^(\w+) found me, ')


def robot_of(agent):
    """The robot (namespace) whose agent this is: r3_robot -> r3."""
    return agent.split('_')[0]


def planar(msg):
    """(x, y, yaw) of a geometry_msgs/PoseStamped."""
    p, q = msg.pose.position, msg.pose.orientation
    return p.x, p.y, math.atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z))


class TrueTrack(object):
    """A robot's true poses: its start, the closest it came to the goal 1 m ahead of the
    start, and where it was when its mission's outcome was heard."""

    def __init__(self):
        self.start = self.latest = self.at_end = None
        self.poses = []

    @property
    def closest(self):
        """How close (m) the robot came to its own goal."""
        return self.closest_to(self.goal()) if self.start is not None else math.inf

    def closest_to(self, point):
        """How close (m) the robot came to ``point`` (x, y)."""
        return min((math.hypot(x - point[0], y - point[1]) for x, y, _ in self.poses), default=math.inf)

    def goal(self):
        x, y, yaw = self.start
        return x + MISSION_LENGTH * math.cos(yaw), y + MISSION_LENGTH * math.sin(yaw)

    def add(self, pose):
        if self.start is None:
            self.start = pose
        self.latest = pose
        self.poses.append(pose)


class FleetRun(object):
    """What the callers said (with the wall time each line was heard: their awards, the robots
    that took them, the helpers that found them), the first diagnosis and mission outcome of
    each agent, and the true poses of every robot of the fleet (``tracks``, by robot). The
    callers' lines come from /rosout, which is the same on either fleet channel (over MQTT the
    agents' messages never reach ROS)."""

    def __init__(self):
        self._lock = threading.Lock()
        self._lines = []         # (heard at, agent, the rest of its line)
        self._diagnoses = {}
        self._missions = {}
        self.tracks = {robot: TrueTrack() for robot in FLEET}
        for robot in FLEET:
            rospy.Subscriber('/%s/true_pose' % robot, PoseStamped, self._on_pose, robot, queue_size=50)
        rospy.Subscriber('/rosout', Log, self._on_log, queue_size=None)
        rospy.Subscriber('/diagnostics', DiagnosticArray, self._on_diagnostics, queue_size=100)

    def _on_pose(self, msg, robot):
        with self._lock:
            self.tracks[robot].add(planar(msg))

    def _on_log(self, msg):
        match = AGENT_LINE.match(msg.msg)
        if match:
            with self._lock:
                self._lines.append((time.monotonic(), match.group(1), match.group(2)))

    def _on_diagnostics(self, msg):
        with self._lock:
            for status in msg.status:
                values = dict((kv.key, kv.value) for kv in status.values)
                if status.name == STATUS_NAME:
                    self._diagnoses.setdefault(values.get('agent'), values)
                elif status.name == MISSION_STATUS_NAME and values.get('agent') not in self._missions:
                    self._missions[values.get('agent')] = values
                    track = self.tracks.get(robot_of(values.get('agent') or ''))
                    if track is not None:
                        track.at_end = track.latest

    def messages(self):
        """The agents' lines so far, for a failure's context."""
        with self._lock:
            return ['[%s] %s' % (agent, text) for _, agent, text in self._lines]

    def _said(self, agent, pattern):
        with self._lock:
            lines = list(self._lines)
        return [(t, pattern.match(text)) for t, a, text in lines if a == agent and pattern.match(text)]

    def diagnosis(self, agent):
        with self._lock:
            return self._diagnoses.get(agent)

    def mission(self, agent):
        with self._lock:
            return self._missions.get(agent)

    def awards(self, caller, task='help'):
        """(heard at, robot) of each award of a ``task`` (help, guide, reach) the caller made, in order."""
        return [(t, m.group(2)) for t, m in self._said(caller, AWARDING) if m.group(1) == task]

    def helpers(self, caller, task='help'):
        """The robots that took the caller's award of a ``task``, in order."""
        return [m.group(1) for _, m in self._said(caller, TOOK) if m.group(2) == task]

    def found(self, helper, caller):
        """Whether the caller heard ``helper`` found it."""
        return any(m.group(1) == helper for _, m in self._said(caller, FOUND))


def await_condition(what, seconds, condition, messages):
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline:
        if condition():
            return
        time.sleep(0.1)
    raise AssertionError('%s: not within %.0f s; messages: %s' % (what, seconds, messages()[-60:]))


def kill_agents_of(robot_agent):
    """SIGKILL the rason_mas of the robot whose agent is robot_agent (r2_robot: /r2/rason_mas)."""
    node = '/%s/rason_mas' % robot_agent.split('_')[0]
    uri = rosgraph.Master('/test_fleet_case_study').lookupNode(node)
    _, _, pid = ServerProxy(uri).getPid('/test_fleet_case_study')
    os.kill(pid, signal.SIGKILL)
    return node


class TestFleetCaseStudy(unittest.TestCase):

    def test_fleet(self):
        expected = dict(pair.split(':') for pair in rospy.get_param('~diagnoses').split())
        victim_caller = rospy.get_param('~kill_helper_of', '')
        within = float(rospy.get_param('~next_award_within', 5.0))
        timeout = float(rospy.get_param('~timeout', 240.0))
        missions = dict(pair.split(':') for pair in rospy.get_param('~missions', '').split())
        tolerance = float(rospy.get_param('~tolerance', 0.15))
        run = FleetRun()
        deadline = time.monotonic() + timeout

        killed_helper = None
        if victim_caller:
            await_condition('%s to be found by the robot it awarded' % victim_caller, timeout,
                            lambda: any(run.found(h, victim_caller) for h in run.helpers(victim_caller)),
                            run.messages)
            killed_helper = helper = run.helpers(victim_caller)[-1]
            killed_node = kill_agents_of(helper)
            killed = time.monotonic()
            rospy.loginfo('killed %s (%s), which watched %s', killed_node, helper, victim_caller)
            await_condition('%s to award another robot after %s died' % (victim_caller, helper), within + 5.0,
                            lambda: any(t > killed and r != helper for t, r in run.awards(victim_caller)),
                            run.messages)
            next_award = min(t for t, r in run.awards(victim_caller) if t > killed and r != helper)
            self.assertLessEqual(next_award - killed, within,
                                 'the next award came %.1f s after %s was killed' % (next_award - killed, helper))

        for agent in expected:
            await_condition('the diagnosis of %s' % agent, max(1.0, deadline - time.monotonic()),
                            lambda: run.diagnosis(agent) is not None, run.messages)
        for agent, component in expected.items():
            self.assertEqual(run.diagnosis(agent).get('component'), component,
                             '%s: %s; messages: %s' % (agent, run.diagnosis(agent), run.messages()[-60:]))
            self.assertTrue(run.helpers(agent), '%s was never watched; messages: %s' % (agent, run.messages()[-60:]))
        last_helpers = {agent: run.helpers(agent)[-1] for agent in expected}
        self.assertEqual(len(set(last_helpers.values())), len(last_helpers),
                         'each caller had a helper of its own: %s' % last_helpers)
        for agent, helper in last_helpers.items():
            self.assertNotIn(helper, expected, '%s was watched by %s, a faulty robot' % (agent, helper))
            self.assertTrue(run.found(helper, agent), '%s never found %s' % (helper, agent))
        if victim_caller:
            self.assertNotEqual(last_helpers[victim_caller], killed_helper, 'a killed robot cannot have helped to the end')

        for agent in missions:
            await_condition('the mission outcome of %s' % agent, max(1.0, deadline - time.monotonic()),
                            lambda: run.mission(agent) is not None, run.messages)
        for agent, recovery in missions.items():
            mission, track = run.mission(agent), run.tracks[robot_of(agent)]
            context = '%s: mission %s; diagnosis %s' % (agent, mission, run.diagnosis(agent))
            self.assertEqual(mission.get('recovery'), recovery, context)
            self.assertEqual(mission.get('completed'), 'true', context)
            contracted = {'guided': 'guide', 'delegate': 'reach'}.get(recovery)
            if contracted:
                chosen = run.helpers(agent, contracted)
                self.assertTrue(chosen, '%s: no robot took %s(...) by contract net; %s' % (agent, contracted, context))
                self.assertNotIn(chosen[-1], expected, '%s: %s, a faulty robot, took %s' % (agent, chosen[-1], contracted))
            if recovery == 'delegate':
                by = mission.get('by')
                self.assertEqual(by, chosen[-1], context)
                closest = run.tracks[robot_of(by)].closest_to(track.goal())
                self.assertLessEqual(closest, tolerance, '%s came no closer than %.3f m to the goal of %s; %s'
                                     % (by, closest, agent, context))
                rospy.loginfo('%s: goal within %.3f m, reached by %s (delegate)', agent, closest, by)
                continue
            self.assertLessEqual(track.closest, tolerance, '%s came no closer than %.3f m to its goal; %s'
                                 % (agent, track.closest, context))
            back = math.hypot(track.at_end[0] - track.start[0], track.at_end[1] - track.start[1])
            self.assertLessEqual(back, tolerance, '%s ended %.3f m from its start; %s' % (agent, back, context))
            rospy.loginfo('%s: goal within %.3f m, back %.3f m from its start (%s)', agent, track.closest, back, recovery)


if __name__ == '__main__':
    rason_rospy.init_node('test_fleet_case_study')
    rostest.rosrun('rason', 'fleet_case_study', TestFleetCaseStudy)
