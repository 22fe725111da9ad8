#!/usr/bin/python3
"""The conformance suite: each program of test/conformance runs whole in one rason_mas (rosrun,
from /) and split over two or three (roslaunch), and both runs print the outcome the program's
outcome.txt says; so does the whole program under Jason's own runner (in its folder), but for
the differences UNDER_JASON lists. The lines are read from each process's screen output, so none
is lost to a rosout connection made late."""
import glob
import os
import re
import signal
import subprocess
import sys
import threading
import time
import unittest

import rason_rospy

import rospy
import rostest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), 'nodes'))
from fleet_wire import MQTT, fleet_channel, fleet_params  # noqa: E402
from jason_runner import jason_command  # noqa: E402
from rason_testing import node_command  # noqa: E402

#: One line per program: its directory under test/conformance.
PROGRAMS = [
    'tender',     # a contract net through the directory facilitator and its subscription
    'auction',    # a sealed-bid auction: broadcast, bids, the winner told to all
    'howto',      # plans asked for (askHow) and taught (tellHow), then used
    'spawn',      # agents created at run time, found through the directory, killed
    'modules',    # one module included twice, in two namespaces, used through them
]

#: What Jason's runner prints instead of a line of outcome.txt (None: nothing), each a difference
#: the README's "what differs" gives the reason for: Jason's local DF is an agent called df, which
#: .all_names lists, and it never tells subscribers that a provider went.
UNDER_JASON = {
    'spawn': {
        '[foreman] result: let go of [hand,hand_1]; left [foreman,tally]':
            '[foreman] result: let go of [hand,hand_1]; left [df,foreman,tally]',
        '[tally] result: hand is gone': None,
        '[tally] result: hand_1 is gone': None,
    },
}

HERE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))  # the test folder
CONFORMANCE = os.path.join(HERE, 'conformance')
RESULT = re.compile(r'(\[\w+\] result: .*?)\s*$')
#: Seconds a run may take to print its whole outcome (JVM start included, on a busy machine).
RUN_TIMEOUT = 90.0


class Run(object):
    """A process group whose screen output is scanned for result lines."""

    def __init__(self, args, cwd='/'):
        self.results = []
        self.output = []
        self._cond = threading.Condition()
        # rason_mas from /: nothing may depend on the working directory
        self.proc = subprocess.Popen(args, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                     universal_newlines=True, start_new_session=True)
        threading.Thread(target=self._read, daemon=True).start()

    def _read(self):
        for line in self.proc.stdout:
            with self._cond:
                self.output.append(line.rstrip())
                m = RESULT.search(line)
                if m:
                    self.results.append(m.group(1))
                self._cond.notify_all()

    def wait_results(self, count, timeout):
        deadline = time.monotonic() + timeout
        with self._cond:
            while len(self.results) < count and time.monotonic() < deadline:
                self._cond.wait(0.2)
            return sorted(self.results)

    def stop(self):
        if self.proc.poll() is None:
            os.killpg(self.proc.pid, signal.SIGINT)
            try:
                self.proc.wait(timeout=30)
            except subprocess.TimeoutExpired:
                os.killpg(self.proc.pid, signal.SIGKILL)
                self.proc.wait()


class TestConformance(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        rason_rospy.init_node('test_conformance')

    def check(self, program):
        directory = os.path.join(CONFORMANCE, program)
        with open(os.path.join(directory, 'outcome.txt')) as f:
            outcome = sorted(line.strip() for line in f if line.strip())
        parts = len(glob.glob(os.path.join(directory, 'part*.mas2j')))
        self.assertIn(parts, (2, 3), '%s: part1.mas2j, part2.mas2j and maybe part3.mas2j' % program)
        jason = UNDER_JASON.get(program, {})
        runs = {
            'whole': (node_command('rason_bridge', 'rason_mas') + [os.path.join(directory, 'whole.mas2j'),
                                                                 '__ns:=/conf_whole'], '/', outcome),
            'split': (['roslaunch', os.path.join(CONFORMANCE, 'split.launch'), 'dir:=' + directory,
                       'parts:=%d' % parts] + ['%s:=%s' % item for item in fleet_params().items()], '/', outcome),
            'jason': jason_command(os.path.join(directory, 'whole.mas2j'))
            + (sorted(jason.get(line, line) for line in outcome if jason.get(line, line) is not None),),
        }
        modes = ('whole', 'split', 'jason')
        if fleet_channel() == MQTT:
            modes = ('split',)
            print('%s: the split run only over MQTT; the whole run and Jason\'s runner use no fleet channel'
                  ' and run in the ros variant of this test' % program)
        for mode in modes:
            args, cwd, expected = runs[mode]
            run = Run(args, cwd)
            try:
                got = run.wait_results(len(expected), RUN_TIMEOUT)
            finally:
                run.stop()
            print('%s %s: %s' % (program, mode, got))
            self.assertEqual(got, expected, '%s run %s printed %r; its output ended with:\n%s'
                             % (program, mode, got, '\n'.join(run.output[-30:])))


def _add_tests():
    for program in PROGRAMS:
        def test(self, program=program):
            self.check(program)
        setattr(TestConformance, 'test_%s' % program, test)


_add_tests()

if __name__ == '__main__':
    rostest.rosrun('rason', 'conformance', TestConformance)
