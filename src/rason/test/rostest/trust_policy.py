#!/usr/bin/python3
"""Two rason_mas processes and the trust policy: robot2's agents cannot change or read the
plans of robot1's agents unless these trust them (trust_<group> in the .mas2j, ~trust), the
answer to an askHow gets back to the asker, and refusals are logged naming the sender."""
import itertools
import os
import sys
import unittest

import rason_rospy

import rospy
import rostest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), 'nodes'))
from rason_testing import LogWatcher, Robot, run  # noqa: E402

_tricks = itertools.count(1)


def told_plan(n):
    """A tellHow content: a plan for !trickN that prints 'trick N' (as a Jason string inside a percept)."""
    return '"+!trick%d <- .print(\\"trick %d\\")."' % (n, n)


# what a sender prints when the receiver's trust policy refused its message (from the receipt)
REFUSED = r'failed refused: %s refused it \(its trust policy\)'

class TestTrustPolicy(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        rason_rospy.init_node('test_trust_policy')
        cls.log = LogWatcher()
        cls.r1 = Robot('robot1')
        cls.r2 = Robot('robot2')  # carol
        cls.r3 = Robot('robot3')  # mallory
        for r in (cls.r1, cls.r2, cls.r3):
            r.wait_connected()
        assert cls.log.wait_ready()
        assert cls.log.wait_for(r'^\[guarded\] present mallory$', timeout=30)
        assert cls.log.wait_for(r'^\[carol\] present open$', timeout=30)
        assert cls.log.wait_for(r'^\[mallory\] present open$', timeout=30)

    def expect(self, pattern, timeout=10.0):
        found = self.log.wait_for(pattern, timeout=timeout)
        self.assertTrue(found, 'never saw %r' % pattern)
        return found

    def test_a_plan_told_by_another_robot_is_refused_by_default(self):
        n = next(_tricks)
        # the sender learns it too: its receipt says refused, and the send fails
        run(self.log, self.r2, 'carol', 'send(guarded, tellHow, %s)' % told_plan(n), REFUSED % 'guarded')
        self.expect(r'^refused tellHow from carol \(/robot2/rason_mas\) to guarded: guarded takes tellHow from '
                    r'no agent of another robot \(trust_tellHow')
        # the goal the plan was for has no plan: Jason's own failure, nothing printed by the plan
        run(self.log, self.r2, 'carol', 'send(guarded, achieve, trick%d)' % n, 'sent')
        self.expect(r'trick%d' % n + r'.*(relevant|applicable)|(relevant|applicable).*trick%d' % n)
        self.assertEqual(self.log.lines(r'^\[guarded\] trick %d$' % n), [])

    def test_another_robot_cannot_read_plans_by_default(self):
        run(self.log, self.r2, 'carol', 'send(guarded, askHow, "+!greet(X)")', REFUSED % 'guarded')
        self.expect(r'^refused askHow from carol \(/robot2/rason_mas\) to guarded')

    def test_a_trusting_agent_takes_plans_from_other_robots(self):
        n = next(_tricks)
        run(self.log, self.r3, 'mallory', 'send(open, tellHow, %s)' % told_plan(n), 'sent')
        run(self.log, self.r3, 'mallory', 'send(open, achieve, trick%d)' % n, 'sent')
        self.expect(r'^\[open\] trick %d$' % n)

    def test_the_answer_to_an_ask_how_reaches_the_asker_and_only_the_trusted_may_ask(self):
        n = next(_tricks)
        run(self.log, self.r2, 'carol', 'send(open, tellHow, %s)' % told_plan(n), 'sent')
        run(self.log, self.r3, 'mallory', 'send(open, askHow, "+!trick%d")' % n, REFUSED % 'open')
        self.expect(r'^refused askHow from mallory \(/robot3/rason_mas\) to open: open takes askHow from '
                    r"other robots' carol only")
        # carol asks after open has the plan (the refusal above came after carol's tellHow)
        run(self.log, self.r2, 'carol', 'send(open, askHow, "+!trick%d")' % n, 'sent')
        # open answers with a tellHow, which carol takes although she takes no plans from other robots
        deadline = rospy.get_time() + 10
        while True:
            run(self.log, self.r2, 'carol', 'send(carol, achieve, trick%d)' % n, 'sent')
            if self.log.wait_for(r'^\[carol\] trick %d$' % n, timeout=1.0):
                break
            self.assertLess(rospy.get_time(), deadline, 'carol never got the plan she asked for')

    def test_the_parameter_restricts_who_may_give_an_agent_goals(self):
        run(self.log, self.r3, 'mallory', 'send(guarded, achieve, greet(mallory_goal))', REFUSED % 'guarded')
        self.expect(r'^refused achieve from mallory \(/robot3/rason_mas\) to guarded: guarded takes achieve from '
                    r"other robots' carol only")
        run(self.log, self.r2, 'carol', 'send(guarded, achieve, greet(carol_goal))', 'sent')
        self.expect(r'^\[guarded\] asked to greet carol_goal by carol$')
        self.assertEqual(self.log.lines(r'greet mallory_goal'), [])

    def test_tell_and_ask_still_cross(self):
        self.assertEqual(run(self.log, self.r3, 'mallory', 'ask(guarded, askOne, secret)', r'answer .*'),
                         'answer secret(guarded_secret)[source(guarded)]')
        run(self.log, self.r3, 'mallory', 'send(guarded, tell, hello(7))', 'sent')
        self.expect(r'^\[guarded\] told hello\(7\) by mallory$')


if __name__ == '__main__':
    rostest.rosrun('rason', 'trust_policy', TestTrustPolicy)
