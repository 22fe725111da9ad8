#!/usr/bin/python3
"""robot.launch profile:=turtlebot2 against the simulator under a TurtleBot 2's topic names
(turtlebot2_sim.launch: rason_sim's rover reads kobuki_node's ``mobile_base/commands/velocity``,
publishes ``odom``), run as a user would (``rosrun rason run_launch rason turtlebot2_sim.launch``):
the velocity reaches the base only through kobuki_node's topic (nobody is left on ``cmd_vel``),
the tutorial's agent perceives the odometry and its goal moves the robot past the line, and the
launch ends with the agent, status 0."""
import os
import re
import sys
import threading
import unittest

import rosgraph
import rason_rospy
import rospy
import rostest
from geometry_msgs.msg import PoseStamped

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), 'nodes'))
from rason_testing import poll, run_launch  # noqa: E402

NS = 'rover'
START_X = -2.0          # the world's x of rover's start (rason_sim config/one_robot.yaml)
LINE = 1.0              # past_the_line in the tutorial's perceptions.yaml: odometry x > 1 m
KOBUKI_VELOCITY = '/rover/mobile_base/commands/velocity'


class TestTurtlebot2Profile(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        rason_rospy.init_node('test_turtlebot2_profile')
        cls.lock = threading.Lock()
        cls.poses = []
        cls.graph = None
        rospy.Subscriber('/%s/true_pose' % NS, PoseStamped, cls._on_pose, queue_size=100)
        watcher = threading.Thread(target=cls._watch_graph, daemon=True)
        watcher.start()
        cls.status, cls.output = run_launch('turtlebot2_sim.launch', timeout=100)
        watcher.join(timeout=5)

    @classmethod
    def _on_pose(cls, msg):
        with cls.lock:
            cls.poses.append(msg.pose.position.x)

    @classmethod
    def _watch_graph(cls):
        """The master's (publishers, subscribers) once the base's topics are wired both ways:
        the velocity published and read, the odometry published and read by the fault injector
        (nodes register their topics one by one, so a snapshot taken early can miss one). If
        that never happens, the last snapshot, for the assertions to say what was missing."""
        master = rosgraph.Master(rospy.get_name())
        last = [None]

        def wired():
            try:
                publishers, subscribers, _ = master.getSystemState()
            except Exception:       # the launch's master is not up yet
                return None
            pubs, subs = dict(publishers), dict(subscribers)
            last[0] = pubs, subs
            if (pubs.get(KOBUKI_VELOCITY) and subs.get(KOBUKI_VELOCITY) and pubs.get('/rover/odom')
                    and '/rover/fault_injector' in subs.get('/rover/odom', [])):
                return pubs, subs
            return None
        cls.graph = poll(wired, timeout=60, interval=0.2) or last[0]

    def test_the_velocity_goes_through_kobuki_node_s_topic_only(self):
        self.assertIsNotNone(self.graph, 'no master answered')
        pubs, subs = self.graph
        self.assertEqual(pubs.get(KOBUKI_VELOCITY), ['/rover/fault_injector'])
        self.assertEqual(subs.get(KOBUKI_VELOCITY), ['/rason_sim'])
        self.assertNotIn('/rover/cmd_vel', pubs)
        self.assertNotIn('/rover/cmd_vel', subs)
        self.assertIn('/rason_sim', pubs.get('/rover/odom', []))
        self.assertIn('/rover/fault_injector', subs.get('/rover/odom', []))

    def test_the_agent_s_goal_moves_the_robot_and_it_perceives_the_odometry(self):
        self.assertEqual(self.status, 0, self.output[-3000:])
        self.assertIn('run_launch: rover/rason_mas finished: the launch is shut down', self.output)
        self.assertIn('profile turtlebot2', self.output)
        moved = re.search(r'\[driver\] moved 0\.5 m: odometry says (\S+) (\S+)\s*$', self.output, re.M)
        self.assertTrue(moved, self.output[-3000:])
        self.assertAlmostEqual(float(moved.group(1)), 0.5, delta=0.05)
        self.assertIn('[driver] past the line: cruise taken back', self.output)
        with self.lock:
            poses = list(self.poses)
        self.assertTrue(poses, 'no true pose of %s heard' % NS)
        self.assertGreater(poses[-1] - START_X, LINE)


if __name__ == '__main__':
    rostest.rosrun('rason', 'turtlebot2_profile', TestTurtlebot2Profile)
