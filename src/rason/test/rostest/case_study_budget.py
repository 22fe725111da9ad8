#!/usr/bin/python3
"""The case study on a robot's budget (issue 35): faulty_helper.launch at real-time factor 1,
lockstep off, with each robot's nodes (rason_mas, decomposers, synthesizers, fault injector,
vision) held to half a core in a CPU cgroup of its own; the simulator, master, recorder and
this test run outside the quota. Both actuators and the left actuator are diagnosed right.
Each run is a campaign run on a master of its own; this launch's master only hosts the test.

Needs a writable CPU cgroup (root; CI runs as root): without one the test fails, saying why."""
import json
import os
import shutil
import tempfile
import unittest

import rostest

from rason_budget import cgroups
from rason_budget.cli import format_summary
from rason_budget.meter import Meter
from rason_campaign import bagread, cli, plan, runner

CORES = 0.5
SEED = 7
ROBOTS = ('faulty', 'helper')
#: Processes each robot's group must have held (the budget really applied to them).
EXPECTED = {'faulty': {'rason_mas', 'motion_decomp', 'fault_injector', 'diagnosis_reporter'},
            'helper': {'rason_mas', 'motion_decomp', 'vision_synth', 'generic_synthesizer'}}
#: Over a run the quota allows at most CORES on average; a period's slack at the ends.
MEAN_SLACK = 0.05


def run_on_budget(fault, out_dir):
    """(the campaign's result dict, the meter's summary) of one run with each robot at CORES."""
    (spec,) = plan.make_plan([fault], 1, SEED, rate=1.0, jitter=False)
    spec.args.update(lockstep='false', budget='true')
    os.makedirs(out_dir)
    with cgroups.Budget({robot: CORES for robot in ROBOTS}) as budget:
        launch = []
        meter = Meter(budget, interval=0.5, root_pid=lambda: launch[0].pid if launch else None)
        with meter:
            record = runner.run(spec, out_dir, timeout=240, base_port=11851, env=budget.env,
                                on_start=launch.append)
    summary = meter.summary()
    with open(os.path.join(out_dir, 'budget.json'), 'w') as f:
        json.dump(summary, f, indent=1, sort_keys=True)
    print('%s on %.1f core per robot (wall %.0f s):\n%s' % (fault, CORES, record.wall, '\n'.join(format_summary(summary))))
    return cli.analyze(spec, record, bagread.read_events), summary


class TestCaseStudyOnHalfACore(unittest.TestCase):

    def setUp(self):
        self.tmp = tempfile.mkdtemp(prefix='rason_budget_')
        self.addCleanup(shutil.rmtree, self.tmp, True)

    def check(self, fault):
        try:
            cgroups.detect()
        except cgroups.BudgetError as e:
            self.fail('the case study on a budget needs a CPU cgroup: %s' % e)
        result, summary = run_on_budget(fault, os.path.join(self.tmp, fault))
        self.assertEqual(result['outcome'], 'correct', result)
        self.assertEqual(result['component'], fault, result)
        for robot in ROBOTS:
            r = summary['robots'][robot]
            self.assertLessEqual(EXPECTED[robot], {p['name'] for p in r['processes']}, r)
            self.assertLessEqual(r['cpu_mean_cores'], CORES + MEAN_SLACK, r)

    def test_both_actuators(self):
        self.check('both_actuators')

    def test_left_actuator(self):
        self.check('left_actuator')


if __name__ == '__main__':
    rostest.rosrun('rason', 'case_study_budget', TestCaseStudyOnHalfACore)
