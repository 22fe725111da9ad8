#!/usr/bin/python3
"""rason_wiring's generic_decomposer, configured only by YAML (agents/wiring/actions.yaml),
between a Jason agent and what this test runs: a topic (the message arrives with its fields),
std_srvs services (OK, the reason from the response, a missing service, a service that
raises, a slow one that holds up nothing), an actionlib server (success, abort, reject,
feedback as perceptions, the cancel of a goal taken back, a missing server), and malformed
configurations (the node exits 1 with one fatal line naming the entry)."""
import os
import sys
import threading
import time
import unittest

import actionlib
import rason_rospy
import rospy
import rostest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), 'nodes'))
from rason_testing import LogWatcher, Robot, run, run_refused_node, wait_for  # noqa: E402
from move_base_msgs.msg import MoveBaseAction, MoveBaseFeedback  # noqa: E402
from std_msgs.msg import String  # noqa: E402
from std_srvs.srv import SetBool, SetBoolResponse, Trigger, TriggerResponse  # noqa: E402

NS = 'wire'
AGENT = 'wirer'
#: goal x coordinates the test's move_base server treats specially
REJECT_X, ABORT_X, ENDLESS_X = -1.0, 99.0, 50.0


class Recorder(object):
    """What a test server saw, with a condition to wait on."""

    def __init__(self):
        self._cond = threading.Condition()
        self.items = []

    def add(self, item):
        with self._cond:
            self.items.append(item)
            self._cond.notify_all()

    def wait_for(self, test, timeout=10.0):
        deadline = time.monotonic() + timeout
        with self._cond:
            while not any(test(i) for i in self.items):
                left = deadline - time.monotonic()
                if left <= 0:
                    return False
                self._cond.wait(left)
            return True


class MoveBaseServer(object):
    """A move_base action server: goals at x = -1 are rejected, at 99 aborted, at 50 run with
    feedback every 0.1 s until cancelled; others succeed after feedback at half way and there."""

    def __init__(self):
        self.seen = Recorder()     # ('goal', x, y), ('cancel', x)
        self._cancelled = set()
        self._server = actionlib.ActionServer('move_base', MoveBaseAction, self._on_goal,
                                              self._on_cancel, auto_start=False)
        self._server.start()

    def _on_goal(self, gh):
        p = gh.get_goal().target_pose
        self.seen.add(('goal', p.pose.position.x, p.pose.position.y, p.header.frame_id))
        if p.pose.position.x == REJECT_X:
            gh.set_rejected()
            return
        gh.set_accepted()
        threading.Thread(target=self._run, args=(gh, p.pose.position.x), daemon=True).start()

    def _run(self, gh, x):
        if x == ABORT_X:
            gh.set_aborted()
            return
        steps = [x / 2, x] if x != ENDLESS_X else (0.1 * i for i in range(1, 10 ** 6))
        for position in steps:
            if gh.get_goal_id().id in self._cancelled or rospy.is_shutdown():
                return
            feedback = MoveBaseFeedback()
            feedback.base_position.pose.position.x = position
            gh.publish_feedback(feedback)
            time.sleep(0.2)
        gh.set_succeeded()

    def _on_cancel(self, gh):
        self._cancelled.add(gh.get_goal_id().id)
        self.seen.add(('cancel', gh.get_goal().target_pose.pose.position.x))
        gh.set_canceled()


class TestWiring(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        rason_rospy.init_node('test_wiring')
        cls.log = LogWatcher()
        cls.speech = Recorder()
        rospy.Subscriber('speech', String, lambda m: cls.speech.add(m.data), queue_size=10)
        cls.pause_over = threading.Event()
        rospy.Service('light', SetBool, lambda r: SetBoolResponse(r.data, '' if r.data else 'bulb_broken'))
        rospy.Service('reset', Trigger, lambda r: TriggerResponse(False, 'Motor stalled!'))
        rospy.Service('explode', Trigger, cls._explode)
        rospy.Service('pause', Trigger, cls._pause)
        cls.move_base = MoveBaseServer()
        cls.robot = Robot(NS)
        cls.robot.wait_connected()
        if not cls.log.wait_ready():
            raise AssertionError('not connected to every /rosout publisher')
        # the decomposer's publisher must reach us before the agent says anything
        wait_for(lambda: any(t == '/%s/speech' % NS for t, _ in rospy.get_published_topics()), 20,
                 'generic_decomposer to advertise speech', interval=0.05)

    @staticmethod
    def _explode(_request):
        raise RuntimeError('the test server fails on purpose')

    @classmethod
    def _pause(cls, _request):
        time.sleep(2.0)
        cls.pause_over.set()
        return TriggerResponse(True, '')

    def act(self, command, expect='ok'):
        return run(self.log, self.robot, AGENT, command, expect, timeout=20)

    # ---------------------------------------------------------------- topic

    def test_a_topic_action_publishes_the_message_with_its_fields(self):
        self.act('say("hello, wiring")')
        self.assertTrue(self.speech.wait_for(lambda d: d == 'hello, wiring', timeout=5))

    # ---------------------------------------------------------------- services

    def test_a_service_that_succeeds_answers_ok(self):
        self.act('light(true)')

    def test_a_service_failure_gives_the_reason_from_the_response(self):
        self.assertIn('bulb_broken', self.act('light(false)', 'failed .*'))
        self.assertIn('failure_reason("Motor stalled!")', self.act('reset', 'failed .*'))

    def test_a_missing_service_is_service_unavailable(self):
        self.assertIn('service_unavailable', self.act('calibrate', 'failed .*'))

    def test_a_service_that_raises_is_service_error(self):
        self.assertIn('service_error', self.act('explode', 'failed .*'))

    def test_an_argument_that_does_not_fit_fails_naming_the_field(self):
        self.assertIn('bad_value("data")', self.act('light(maybe)', 'failed .*'))

    def test_a_slow_service_holds_up_no_other_action(self):
        self.pause_over.clear()
        self.act('say_during_pause')
        self.assertTrue(self.speech.wait_for(lambda d: d == 'during pause', timeout=5))
        self.assertFalse(self.pause_over.is_set(), 'the topic action waited for the slow call')
        self.assertTrue(self.log.wait_for(r'^\[wirer\] pause over$', timeout=10))

    # ---------------------------------------------------------------- actionlib

    def test_a_goal_that_succeeds_answers_ok_with_its_fields(self):
        self.act('goto(2, 0.5)')
        self.assertTrue(self.move_base.seen.wait_for(lambda s: s == ('goal', 2.0, 0.5, 'odom'), timeout=1))

    def test_an_aborted_goal_fails_aborted(self):
        self.assertIn('aborted', self.act('goto(%d, 0)' % ABORT_X, 'failed .*'))

    def test_a_rejected_goal_fails_rejected(self):
        self.assertIn('rejected', self.act('goto(%d, 0)' % REJECT_X, 'failed .*'))

    def test_a_missing_action_server_is_server_unavailable(self):
        self.assertIn('server_unavailable', self.act('dock', 'failed .*'))

    def test_feedback_is_perceived_and_a_goal_taken_back_is_cancelled_on_the_server(self):
        self.log.clear()
        self.robot.perceive('rostest_drive', 'drive(%d, 1)' % ENDLESS_X)
        # the feedback reaches the agent as at(X, Y) while the goal runs
        self.assertTrue(self.log.wait_for(r'^\[wirer\] at 0\.[1-9]\d* 0(\.0)?$', timeout=15),
                        [l[3] for l in self.log.lines(r'^\[wirer\]')])
        self.assertFalse(self.move_base.seen.wait_for(lambda s: s[0] == 'cancel', timeout=0))
        self.robot.perceive('rostest_drive', 'stop')
        dropped = self.log.wait_for(r'^\[wirer\] drive dropped$', timeout=10)
        self.assertTrue(dropped)
        self.assertTrue(self.move_base.seen.wait_for(lambda s: s == ('cancel', ENDLESS_X), timeout=5),
                        'the server never saw the cancel')
        # the perception of the goal is cleared once it is taken back
        wait_for(lambda: [l for l in self.log.lines(r'^\[wirer\] no position$') if l[0] >= dropped[0][0]], 5,
                 'at(X, Y) to be cleared')
        self.assertFalse(self.log.lines(r'drive (arrived|failed)'))

    # ---------------------------------------------------------------- malformed configurations

    def refused(self, name, actions):
        code, fatal, out = run_refused_node('rason_wiring', 'generic_decomposer', NS, name, 'actions', actions)
        self.assertEqual(code, 1, out)
        self.assertEqual(len(fatal), 1, out)
        return fatal[0]

    def test_an_unknown_message_type_stops_the_node_naming_the_entry(self):
        fatal = self.refused('bad_type', {'say(Text)': {'kind': 'topic', 'name': 'speech',
                                                        'type': 'std_msgs/Strin', 'fields': {'data': 'Text'}}})
        self.assertIn("say(Text): unknown message type 'std_msgs/Strin'", fatal)

    def test_a_bad_field_path_stops_the_node_naming_the_entry(self):
        fatal = self.refused('bad_path', {'goto(X)': {
            'kind': 'actionlib', 'name': 'move_base', 'type': 'move_base_msgs/MoveBase',
            'fields': {'target_pose.pose.postion.x': 'X'}}})
        self.assertIn("goto(X): bad field path target_pose.pose.postion.x", fatal)

    def test_a_functor_that_is_not_an_atom_stops_the_node(self):
        fatal = self.refused('bad_functor', {'Say(Text)': {'kind': 'topic', 'name': 'speech',
                                                           'type': 'std_msgs/String', 'fields': {'data': 'Text'}}})
        self.assertIn("functor 'Say' is not a Jason atom", fatal)

    def test_a_missing_argument_and_an_unknown_kind_stop_the_node(self):
        fatal = self.refused('bad_argument', {'say(Text)': {'kind': 'topic', 'name': 'speech',
                                                            'type': 'std_msgs/String', 'fields': {'data': 'Txt'}}})
        self.assertIn('field data: missing argument Txt', fatal)
        fatal = self.refused('bad_kind', {'say(Text)': {'kind': 'telegram', 'name': 'speech',
                                                        'type': 'std_msgs/String', 'fields': {'data': 'Text'}}})
        self.assertIn("unknown kind 'telegram'", fatal)

    def test_no_actions_at_all_stops_the_node(self):
        self.assertIn('~actions', self.refused('no_actions', {}))


if __name__ == '__main__':
    rostest.rosrun('rason', 'wiring', TestWiring)
