#!/usr/bin/python3
"""The patrol example (agents/patrol, wired only by agents/patrol/wiring.yaml) on the
simulator: the patrol completes (every waypoint reached by the true pose, said on the speech
topic, the lamp service switched on and off, the agents stop by themselves), and a low battery
perceived through generic_synthesizer takes the patrol back: move_base sees the cancel (the
goal ends preempted), the robot stops at once, the agents stop."""
import math
import os
import sys
import threading
import time
import unittest

import rospkg
import rason_rospy
import rospy
import rostest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), 'nodes'))
from rason_testing import LogWatcher, start_mas, stop_mas, wait_for_subscribers  # noqa: E402
from sim_testing import BaseWatch, SimRobot  # noqa: E402
from actionlib_msgs.msg import GoalStatus  # noqa: E402
from move_base_msgs.msg import MoveBaseActionResult  # noqa: E402
from sensor_msgs.msg import BatteryState  # noqa: E402
from std_msgs.msg import String  # noqa: E402

NS = 'faulty'
MAS = os.path.join(rospkg.RosPack().get_path('rason'), 'agents', 'patrol', 'patrol.mas2j')
WAYPOINTS = [(1.0, 0.0), (1.0, 0.8), (0.0, 0.8), (0.0, 0.0)]    # patrol.asl's, odom frame
REACHED = 0.05 + 0.03    # the server's xy tolerance, and wheel odometry against the truth


def to_world(odom, truth, point):
    """``point`` of the odometry frame in the world, given one pose in both."""
    turn = truth[2] - odom[2]
    dx, dy = point[0] - odom[0], point[1] - odom[1]
    return (truth[0] + dx * math.cos(turn) - dy * math.sin(turn),
            truth[1] + dx * math.sin(turn) + dy * math.cos(turn))


class TestPatrol(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        rason_rospy.init_node('test_patrol')
        cls.log = LogWatcher()
        cls.robot = SimRobot(NS)
        cls.watch = BaseWatch(NS)
        cls.results = []
        cls.speech = []
        rospy.Subscriber('/%s/move_base/result' % NS, MoveBaseActionResult,
                         lambda m: cls.results.append((m.status.status, time.monotonic())), queue_size=10)
        rospy.Subscriber('/%s/speech' % NS, String, lambda m: cls.speech.append(m.data), queue_size=10)
        cls.battery = rospy.Publisher('/%s/battery' % NS, BatteryState, queue_size=10)
        assert wait_for_subscribers(cls.battery, timeout=30), 'generic_synthesizer does not listen to battery'
        deadline = time.monotonic() + 30
        while cls.watch.odom is None or cls.robot.pose() is None:
            assert time.monotonic() < deadline, 'no odometry or true pose'
            time.sleep(0.05)

    def setUp(self):
        self.battery.publish(BatteryState(percentage=1.0))
        self.log.clear()
        del self.results[:], self.speech[:]
        self.odom, self.truth = self.watch.odom, self.robot.pose()
        self.mas = start_mas(NS, MAS)

    def tearDown(self):
        stop_mas(self.mas)

    def wait_exit(self, timeout=120.0):
        try:
            return self.mas.wait(timeout=timeout)
        except Exception:
            self.fail('the agents did not stop by themselves within %.0f s' % timeout)

    def test_the_patrol_completes(self):
        self.assertEqual(self.wait_exit(), 0)
        reached = [l[3] for l in self.log.lines(r'^\[patrol\] reached ')]
        self.assertEqual([' '.join(r.split()[2:4]) for r in reached], ['1 0', '1 0.8', '0 0.8', '0 0'])
        self.assertTrue(self.log.lines(r'^\[patrol\] patrol complete$'))
        path = self.watch.path()
        for waypoint in WAYPOINTS:
            target = to_world(self.odom, self.truth, waypoint)
            miss = min(math.hypot(x - target[0], y - target[1]) for x, y in path)
            rospy.loginfo('waypoint %s: the true path passed %.3f m from it', waypoint, miss)
            self.assertLess(miss, REACHED, waypoint)
        self.assertEqual(self.speech, ['patrol started', 'patrol complete'])
        self.assertEqual([l[3] for l in self.log.lines(r'^lamp: ')], ['lamp: on', 'lamp: off'])
        self.assertEqual([r[0] for r in self.results], [GoalStatus.SUCCEEDED] * 4)

    def test_a_low_battery_takes_the_goal_back_and_the_robot_stops(self):
        self.assertTrue(self.log.wait_for(r'^\[patrol\] heading to 1 0\.8$', timeout=60))
        start = self.robot.pose()
        deadline = time.monotonic() + 30
        while math.hypot(self.robot.pose()[0] - start[0], self.robot.pose()[1] - start[1]) < 0.15:
            self.assertLess(time.monotonic(), deadline, 'the robot never set off for the second waypoint')
            time.sleep(0.02)
        low_at, sim_low = time.monotonic(), rospy.get_time()
        self.battery.publish(BatteryState(percentage=0.1))
        self.assertTrue(self.log.wait_for(r'^\[patrol\] battery low: patrol stopped$', timeout=10))
        self.assertEqual(self.wait_exit(30), 0)
        self.assertEqual([r[0] for r in self.results], [GoalStatus.SUCCEEDED, GoalStatus.PREEMPTED])
        commands = self.watch.commands_since(low_at)
        self.assertEqual(commands[-1], (0.0, 0.0))
        coast, spread = self.watch.rest_after(sim_low)
        rospy.loginfo('battery low -> goal preempted %.0f ms later (wall); the robot moved %.3f m more, '
                      'then %.4f m in 0.5 s', (self.results[-1][1] - low_at) * 1e3, coast, spread)
        self.assertLess(spread, 0.002)
        self.assertLess(coast, 0.15)    # 0.2 m/s: the perception -> agent -> cancel chain, then braking
        self.assertFalse(self.log.lines(r'^\[patrol\] reached 1 0\.8'))
        self.assertEqual(self.speech, ['patrol started', 'battery low: patrol stopped'])
        self.assertEqual([l[3] for l in self.log.lines(r'^lamp: ')], ['lamp: on', 'lamp: off'])


if __name__ == '__main__':
    rostest.rosrun('rason', 'patrol', TestPatrol)
