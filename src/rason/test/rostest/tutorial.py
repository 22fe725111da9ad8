#!/usr/bin/python3
"""The tutorial "Your first robot" (docs/tutorial.md), run as the page says, with the very files
the page includes (src/rason/tutorial/): ``rosrun rason run_launch rason first_robot.launch
record:=true``. What the page says happens: the agent prints where it starts and where
move(0.5) took it, sets off on a 3 m cruise, takes it back once past the line 1 m from its
start, and the robot stops there (the true pose: short of the cruise's end, at rest); the
launch ends by itself with exit status 0 and no "REQUIRED process has died" banner; the bag
replays in the dashboard with the agent's pending move(3) and its belief past_the_line."""
import math
import os
import re
import shutil
import sys
import tempfile
import threading
import time
import unittest

import rosbag
import rason_rospy
import rospy
import rostest
from geometry_msgs.msg import PoseStamped
from rason_msgs.msg import Action

from rason_dashboard.replay import MIND_TYPE, load_bag

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), 'nodes'))
from rason_testing import run_launch  # noqa: E402

NS = 'rover'
START_X = -2.0          # the world's x of rover's start (rason_sim config/one_robot.yaml)
LINE = 1.0              # past_the_line in perceptions.yaml: odometry x > 1 m
CRUISE = 0.5 + 3.0      # where the cruise would end, from the start
BRAKING = 0.12          # m beyond the line: 0.2 m/s for the perception -> agent -> cancel chain
RUN_TIMEOUT = 120.0     # s (wall) for the whole launch


class TestTutorial(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        rason_rospy.init_node('test_tutorial')
        cls.lock = threading.Lock()
        cls.poses = []     # (x, y) true poses in the world
        cls.actions = []   # rason_msgs/Action on /rover/jason/action
        rospy.Subscriber('/%s/true_pose' % NS, PoseStamped, cls._on_pose, queue_size=100)
        rospy.Subscriber('/%s/jason/action' % NS, Action, cls._on_action, queue_size=100)
        cls.tmp = tempfile.mkdtemp(prefix='tutorial_')
        cls.bag = os.path.join(cls.tmp, 'first_robot.bag')
        started = time.monotonic()
        cls.status, cls.output = run_launch('first_robot.launch', 'record:=true', 'bag:=' + cls.bag,
                                            timeout=RUN_TIMEOUT)
        cls.wall = time.monotonic() - started
        rospy.loginfo('the tutorial launch ran %.1f s (wall), exit status %d', cls.wall, cls.status)

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp, ignore_errors=True)

    @classmethod
    def _on_pose(cls, msg):
        with cls.lock:
            cls.poses.append((msg.pose.position.x, msg.pose.position.y))

    @classmethod
    def _on_action(cls, msg):
        with cls.lock:
            cls.actions.append(msg)

    def printed(self, pattern):
        """The groups of the agent's lines (``[driver] text``) matching pattern, in order."""
        return [m.groups() for m in re.finditer(r'\[driver\] ' + pattern + r'\s*$', self.output, re.M)]

    def test_the_launch_ends_by_itself_without_a_banner(self):
        self.assertEqual(self.status, 0, self.output[-3000:])
        self.assertNotIn('REQUIRED process', self.output)
        self.assertIn('run_launch: rover/rason_mas finished: the launch is shut down', self.output)

    def test_the_agent_prints_what_the_tutorial_says(self):
        lines = re.findall(r'\[driver\] (.*?)\s*$', self.output, re.M)
        self.assertEqual([re.sub(r'-?\d+(\.\d+)?', 'N', l) for l in lines],
                         ['starting at N N', 'moved N m: odometry says N N', 'cruising N m ahead',
                          'past the line: cruise taken back', 'stopped at N N'], self.output[-3000:])
        (x, y), = self.printed(r'starting at (\S+) (\S+)')
        self.assertEqual((float(x), float(y)), (0.0, 0.0))
        (x, y), = self.printed(r'moved 0\.5 m: odometry says (\S+) (\S+)')
        self.assertAlmostEqual(float(x), 0.5, delta=0.05)
        self.assertAlmostEqual(float(y), 0.0, delta=0.02)
        (x, y), = self.printed(r'stopped at (\S+) (\S+)')
        self.assertTrue(LINE < float(x) < LINE + BRAKING, x)

    def test_the_robot_moved_and_stopped_where_the_goal_was_taken_back(self):
        with self.lock:
            poses = list(self.poses)
        self.assertTrue(poses, 'no true pose of %s heard' % NS)
        end = poses[-1]
        rospy.loginfo('true pose at the end: %.3f %.3f (started at %.1f)', end[0], end[1], START_X)
        self.assertGreater(end[0] - START_X, LINE)                 # it moved past the line ...
        self.assertLess(end[0] - START_X, LINE + BRAKING)          # ... and stopped there,
        self.assertLess(end[0] - START_X, CRUISE - 1.0)            # far short of the cruise's end
        self.assertLess(abs(end[1]), 0.05)
        # at rest: the last half second (25 poses at 50 Hz) within 2 mm
        last = poses[-25:]
        self.assertLess(max(math.hypot(p[0] - end[0], p[1] - end[1]) for p in last), 0.002)

    def test_taking_the_cruise_back_cancelled_its_move(self):
        with self.lock:
            actions = list(self.actions)
        moves = [a for a in actions if a.action == 'move']
        self.assertEqual([a.parameters for a in moves], [['0.5'], ['3']])
        # action id 0: the cancel of whatever an earlier run left, at every start (docs: preemption)
        cancels = [a for a in actions if a.action == Action.CANCEL and a.action_id != 0]
        self.assertEqual([(c.action_id, c.parameters[:1]) for c in cancels], [(moves[1].action_id, ['dropped'])])

    def test_the_bag_replays_in_the_dashboard(self):
        timeline, counts = load_bag(self.bag)
        self.assertGreater(counts['minds'], 0)
        with rosbag.Bag(self.bag) as bag:
            stamps = [t.to_sec() for _, _, t in bag.read_messages(
                topics=[t for t, i in bag.get_type_and_topic_info().topics.items() if i.msg_type == MIND_TYPE])]
        views = [timeline.view(t) for t in stamps]
        drivers = [a for v in views for r in v['robots'] for a in r['agents'] if a['name'] == 'driver']
        self.assertTrue(drivers, 'no driver agent in the replayed views')
        cruising = [d for d in drivers if any(p['action'].startswith('move(3') for p in d['actions'])]
        self.assertTrue(cruising, 'the pending move(3) never shows')
        self.assertTrue(all(any(g.startswith('!cruise') for g in d['goals']) for d in cruising), [d['goals'] for d in cruising])
        self.assertEqual(drivers[-1]['actions'], [])
        self.assertFalse(any(g.startswith('!cruise') for g in drivers[-1]['goals']), drivers[-1]['goals'])
        self.assertTrue(any(b.startswith('past_the_line') for b in drivers[-1]['beliefs']), drivers[-1]['beliefs'])


if __name__ == '__main__':
    rostest.rosrun('rason', 'tutorial', TestTutorial)
