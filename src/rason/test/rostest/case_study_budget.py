#!/usr/bin/python3
"""The case study on a robot's budget (issue 35): faulty_helper.launch at real-time factor 1,
lockstep off, with each robot's nodes (rason_mas, decomposers, synthesizers, fault injector,
vision) held to half a core in a CPU cgroup of its own; the simulator, master, recorder and
this test run outside the quota. Both actuators and the left actuator are diagnosed right.
Each run is a campaign run on a master of its own (rason_budget.case_study); this launch's
master only hosts the test.

Needs a writable CPU cgroup (root; CI runs as root): without one the test fails, saying why."""
import os
import shutil
import tempfile
import unittest

import rostest

from rason_budget import case_study, cgroups
from rason_budget.cli import format_summary

CORES = 0.5
#: Processes each robot's group must have held (the budget really applied to them).
EXPECTED = {'faulty': {'rason_mas', 'motion_decomp', 'fault_injector', 'diagnosis_reporter'},
            'helper': {'rason_mas', 'motion_decomp', 'vision_synth', 'generic_synthesizer'}}
#: Over a run the quota allows at most CORES on average; a period's slack at the ends.
MEAN_SLACK = 0.05


class TestCaseStudyOnHalfACore(unittest.TestCase):

    def setUp(self):
        self.tmp = tempfile.mkdtemp(prefix='rason_budget_')
        self.addCleanup(shutil.rmtree, self.tmp, True)

    def check(self, fault):
        try:
            cgroups.detect()
        except cgroups.BudgetError as e:
            self.fail('the case study on a budget needs a CPU cgroup: %s' % e)
        result, summary = case_study.run(fault, CORES, os.path.join(self.tmp, fault))
        print('%s on %.1f core per robot (wall %.0f s):\n%s' % (fault, CORES, result['wall'],
                                                              '\n'.join(format_summary(summary))))
        self.assertEqual(result['outcome'], 'correct', result)
        self.assertEqual(result['component'], fault, result)
        for robot in case_study.ROBOTS:
            r = summary['robots'][robot]
            self.assertLessEqual(EXPECTED[robot], {p['name'] for p in r['processes']}, r)
            self.assertLessEqual(r['cpu_mean_cores'], CORES + MEAN_SLACK, r)

    def test_both_actuators(self):
        self.check('both_actuators')

    def test_left_actuator(self):
        self.check('left_actuator')


if __name__ == '__main__':
    rostest.rosrun('rason', 'case_study_budget', TestCaseStudyOnHalfACore)
