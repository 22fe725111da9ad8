#!/usr/bin/python3
"""Jason programs behave under rason_mas as under Jason's own runner: Jason's agent-testing
framework (its files included as $jasonJar/test/jason/inc/...) reports the same summary, and a
failing test ends both with exit status 1; variables Jason renames print in Jason's short form.
Jason's runner runs in the project's folder (it resolves relative paths from the working
directory), rason_mas from / (it resolves them from the .mas2j's folder)."""
import os
import re
import sys
import unittest

import rason_rospy

import rospy
import rostest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), 'nodes'))
from jason_runner import agent_lines, run_jason, run_rason_mas  # noqa: E402

HERE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))  # the test folder
PROGRAMS = os.path.join(HERE, 'agents', 'jason')
POSES_TESTS = os.path.join(HERE, '..', 'agents', 'case_study', 'poses_tests.mas2j')
SUMMARY = re.compile(r'#\d+ tests executed, #\d+ (?:passed|PASSED) and #\d+ (?:failed|FAILED)\.')
#: Seconds a run may take (JVM start included, on a busy machine); the programs end by themselves.
RUN_TIMEOUT = 120.0


def renumbered(lines):
    """Lines with every short unnamed variable (_12) as _N: the numbers count terms made so far."""
    return [re.sub(r'\b_[0-9]+\b', '_N', line) for line in lines]


class TestJasonRunnerParity(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        rason_rospy.init_node('test_jason_runner_parity')

    def both(self, mas2j, name):
        jason = run_jason(mas2j, RUN_TIMEOUT)
        self.assertIsNotNone(jason.returncode, "Jason's runner did not end:\n" + jason.text())
        rason = run_rason_mas(mas2j, name, RUN_TIMEOUT)
        self.assertIsNotNone(rason.returncode, 'rason_mas did not end:\n' + rason.text())
        return jason, rason

    def summary(self, run):
        found = [m.group(0) for m in (SUMMARY.search(l) for l in agent_lines(run.output, 'test_manager')) if m]
        self.assertEqual(len(found), 1, 'one summary expected in:\n' + run.text())
        return found[0]

    def test_jasons_testing_framework_reports_the_same_summary(self):
        jason, rason = self.both(POSES_TESTS, 'poses_tests')
        self.assertEqual(jason.returncode, 0, jason.text())
        self.assertEqual(rason.returncode, 0, rason.text())
        self.assertEqual(self.summary(jason), '#13 tests executed, #13 PASSED and #0 failed.', jason.text())
        self.assertEqual(self.summary(rason), self.summary(jason))
        # test by test, the same lines
        self.assertEqual(agent_lines(rason.output, 'test_poses'), agent_lines(jason.output, 'test_poses'))

    def test_a_failing_test_ends_rason_mas_with_a_non_zero_status(self):
        jason, rason = self.both(os.path.join(PROGRAMS, 'failing_tests.mas2j'), 'failing_tests')
        self.assertEqual(jason.returncode, 1, jason.text())
        self.assertEqual(rason.returncode, 1, rason.text())
        self.assertEqual(self.summary(jason), '#2 tests executed, #1 passed and #1 FAILED.', jason.text())
        self.assertEqual(self.summary(rason), self.summary(jason))

    def test_renamed_variables_print_as_under_jason(self):
        jason, rason = self.both(os.path.join(PROGRAMS, 'unnamed_vars.mas2j'), 'unnamed_vars')
        self.assertEqual(jason.returncode, 0, jason.text())
        self.assertEqual(rason.returncode, 0, rason.text())
        printed = renumbered(agent_lines(jason.output, 'unnamed_vars'))
        self.assertEqual(printed, ['[unnamed_vars] trigger named(_N), body .print(_N)'], jason.text())
        self.assertEqual(renumbered(agent_lines(rason.output, 'unnamed_vars')), printed, rason.text())


if __name__ == '__main__':
    rostest.rosrun('rason', 'jason_runner_parity', TestJasonRunnerParity)
