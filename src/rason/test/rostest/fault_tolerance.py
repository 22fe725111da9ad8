#!/usr/bin/python3
"""Fault tolerance end to end (issue 15): fault_tolerance.launch with one fault injected; the
test checks the mission's outcome on /diagnostics (rason/mission) and judges it from the
simulator's true poses: the goal (1 m ahead of Faulty's start) reached within ~tolerance by
the robot that completed the mission, and, when Faulty completed it, Faulty back within
~tolerance of its start.

Private parameters:
  ~diagnosis       the component the diagnosis must name
  ~recovery        the recovery Faulty must choose (none, compensate, guided, delegate)
  ~by              the agent that must complete the mission
  ~cancel_on_help  cancel the injected fault when Faulty asks for help (a false positive)
  ~tolerance       metres (0.15)
  ~timeout         seconds (wall) for the whole scenario
"""
import math
import threading
import time
import unittest

import rason_rospy

import rospy
import rostest
from diagnosis_reporter.report import MISSION_STATUS_NAME, STATUS_NAME
from diagnostic_msgs.msg import DiagnosticArray
from geometry_msgs.msg import PoseStamped
from rason_msgs.msg import AgentMessage
from rason_msgs.srv import FaultInjector

MISSION_LENGTH = 1.0     # metres ahead of Faulty's start (the thesis's mission)


def planar(msg):
    """(x, y, yaw) of a geometry_msgs/PoseStamped."""
    p, q = msg.pose.position, msg.pose.orientation
    return p.x, p.y, math.atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z))


class MissionRun(object):
    """The true poses of both robots, and the diagnosis and mission statuses of one run."""

    def __init__(self, cancel_on_help):
        self._lock = threading.Lock()
        self.start = None          # Faulty's first true pose
        self.latest = {}           # robot -> its latest true pose
        self.closest = {}          # robot -> its smallest distance to the goal so far
        self.diagnosis = None
        self.mission = None
        self.messages = []
        self._cancel_on_help = cancel_on_help
        self.cancelled = False
        for robot in ('faulty', 'helper'):
            rospy.Subscriber('/%s/true_pose' % robot, PoseStamped, self._on_pose, robot,
                             queue_size=50)
        rospy.Subscriber('/diagnostics', DiagnosticArray, self._on_diagnostics, queue_size=10)
        rospy.Subscriber('/rason/messages', AgentMessage, self._on_message, queue_size=100)

    @property
    def goal(self):
        x, y, yaw = self.start
        return x + MISSION_LENGTH * math.cos(yaw), y + MISSION_LENGTH * math.sin(yaw)

    def _on_pose(self, msg, robot):
        pose = planar(msg)
        with self._lock:
            if robot == 'faulty' and self.start is None:
                self.start = pose
            self.latest[robot] = pose
            if self.start is not None:
                gx, gy = self.goal
                d = math.hypot(pose[0] - gx, pose[1] - gy)
                self.closest[robot] = min(d, self.closest.get(robot, d))

    def _on_diagnostics(self, msg):
        for status in msg.status:
            values = dict((kv.key, kv.value) for kv in status.values)
            if status.name == STATUS_NAME and self.diagnosis is None:
                self.diagnosis = values
            elif status.name == MISSION_STATUS_NAME and self.mission is None:
                with self._lock:
                    self.mission = values
                    self.at_end = dict(self.latest)

    def _on_message(self, msg):
        self.messages.append('%s->%s %s %s' % (msg.sender, msg.receiver or 'all',
                                               msg.performative, msg.content))
        if (self._cancel_on_help and not self.cancelled and msg.sender == 'faulty'
                and msg.receiver == '' and msg.content == 'helpme'):
            rospy.ServiceProxy('/faulty/inject_fault', FaultInjector)('cancel')
            self.cancelled = True


class TestFaultTolerance(unittest.TestCase):

    def test_mission(self):
        diagnosis = rospy.get_param('~diagnosis')
        recovery = rospy.get_param('~recovery')
        by = rospy.get_param('~by')
        tolerance = float(rospy.get_param('~tolerance', 0.15))
        timeout = float(rospy.get_param('~timeout', 240.0))
        run = MissionRun(rospy.get_param('~cancel_on_help', False))

        deadline = time.monotonic() + timeout
        while run.mission is None and time.monotonic() < deadline:
            time.sleep(0.1)
        self.assertIsNotNone(run.mission, 'no mission outcome within %.0f s; diagnosis %s; '
                             'messages: %s' % (timeout, run.diagnosis, run.messages))
        context = 'mission %s; diagnosis %s; messages %s' % (run.mission, run.diagnosis,
                                                            run.messages)
        self.assertEqual(run.diagnosis.get('component'), diagnosis, context)
        self.assertEqual(run.mission.get('diagnosis'), diagnosis, context)
        self.assertEqual(run.mission.get('recovery'), recovery, context)
        self.assertEqual(run.mission.get('completed'), 'true', context)
        self.assertEqual(run.mission.get('by'), by, context)

        self.assertLessEqual(run.closest[by], tolerance,
                             '%s came no closer than %.3f m to the goal %s; %s'
                             % (by, run.closest[by], run.goal, context))
        back = None
        if by == 'faulty':
            x, y, _ = run.at_end['faulty']
            back = math.hypot(x - run.start[0], y - run.start[1])
            self.assertLessEqual(back, tolerance, 'Faulty ended %.3f m from its start %s; %s'
                                 % (back, run.start[:2], context))
        rospy.loginfo('fault tolerance: %s, %s: goal reached by %s within %.3f m%s', diagnosis,
                      recovery, by, run.closest[by],
                      '' if back is None else ', back %.3f m from the start' % back)


if __name__ == '__main__':
    rason_rospy.init_node('test_fault_tolerance')
    rostest.rosrun('rason', 'fault_tolerance', TestFaultTolerance)
