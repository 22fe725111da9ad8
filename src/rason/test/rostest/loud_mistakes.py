#!/usr/bin/python3
"""Mistakes that say so, with the nodes running: robot.launch with a wiring file in the wrong
layout ends at once, saying where the synthesizer looked and what to change, under run_launch
with that fatal line last on screen and under roslaunch through its REQUIRED banner, after the
launch's configuration line; agents that cannot start end run_launch too, though
not a required node; a generic_synthesizer configured with a real but
wrong type (std_msgs/Float32 on a sensor_msgs/BatteryState topic) warns naming both types; and
rason_mas warns once about the expected source that synthesizer never delivers."""
import os
import subprocess
import sys
import time
import unittest

import rason_rospy

import rospy
import rostest
from sensor_msgs.msg import BatteryState

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), 'nodes'))
from rason_testing import (HERE, LogWatcher, ScreenOutput, node_command, run_launch, start_mas,  # noqa: E402
                           stop_mas)

WRAPPED = os.path.join(HERE, 'config', 'wrapped_perceptions.yaml')


def fatal(ns):
    """The synthesizer's fatal line for the wrapped file: where it looked, what it found, what to do."""
    return ('generic_synthesizer: bad configuration: ~perceptions is not set (looked for /%s/generic_synthesizer/'
            'perceptions, found /%s/generic_synthesizer/generic_synthesizer/perceptions): the wiring file loaded '
            'into this node has `generic_synthesizer:` at its top level (its top-level keys: generic_synthesizer), '
            'the layout for loading into the robot\'s namespace, as patrol.launch loads agents/patrol/wiring.yaml; '
            'a file given as robot.launch perceptions:=FILE needs `perceptions:` at its top level: remove the '
            '`generic_synthesizer:` line and unindent what it holds' % (ns, ns))


BATTERY = {'battery': {'topic': 'battery', 'type': 'std_msgs/Float32', 'source': 'battery',
                       'literals': {'charge(C)': {'C': 'data'}}}}


class TestLoudMistakes(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        rason_rospy.init_node('test_loud_mistakes')
        cls.log = LogWatcher()

    def test_a_node_that_cannot_start_ends_run_launch_with_its_fatal_line_last(self):
        start = time.monotonic()
        status, output = run_launch('robot.launch', 'ns:=loud1', 'perceptions:=' + WRAPPED, timeout=30)
        self.assertEqual(status, 1, output[-3000:])
        self.assertLess(time.monotonic() - start, 30)
        lines = [l for l in output.splitlines() if l.strip()]
        # first, after roslaunch's own "logging to" lines and before any node starts
        first = lines.index('run_launch: robot.launch, effective configuration (namespace: nodes):')
        self.assertLess(first, 4, lines[:first])
        self.assertTrue(lines[first + 1].startswith('  /loud1/: ') and 'generic_synthesizer' in lines[first + 1],
                        lines[first + 1])
        self.assertEqual(lines[first + 2], '[configuration] robot.launch: namespace /loud1/, program none, wiring %s, '
                                           'fault none, camera false, profile sim, fleet ros' % WRAPPED)
        self.assertNotIn('process[', '\n'.join(lines[:first]))
        self.assertEqual(lines[-2], 'run_launch: loud1/generic_synthesizer failed (exit status 1): '
                                    'the launch is shut down')
        self.assertEqual(lines[-1], 'run_launch: loud1/generic_synthesizer: ' + fatal('loud1'))

    def test_agents_that_cannot_start_end_run_launch_though_not_required(self):
        status, output = run_launch('robot.launch', 'ns:=loud4', 'mas:=/nonexistent/nothing.mas2j', timeout=30)
        self.assertNotEqual(status, 0, output[-3000:])
        lines = [l for l in output.splitlines() if l.strip()]
        self.assertRegex(lines[-2], r'^run_launch: loud4/rason_mas failed \(exit status %d\): the launch is shut down$'
                         % status)
        self.assertIn('/nonexistent/nothing.mas2j', lines[-1])
        self.assertTrue(lines[-1].startswith('run_launch: loud4/rason_mas: '), lines[-1])

    def test_a_node_that_cannot_start_ends_roslaunch_too(self):
        launch = subprocess.run(['roslaunch', 'rason', 'robot.launch', 'ns:=loud2', 'perceptions:=' + WRAPPED],
                                stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=60)
        self.assertIn(fatal('loud2'), launch.stdout)
        # the configuration line, before the node that fails says anything
        shown = ('[configuration] robot.launch: namespace /loud2/, program none, wiring %s, fault none, '
                 'camera false, profile sim, fleet ros' % WRAPPED)
        self.assertIn(shown, launch.stdout)
        self.assertLess(launch.stdout.index(shown), launch.stdout.index(fatal('loud2')))
        self.assertRegex(launch.stdout, r'REQUIRED process \[loud2/generic_synthesizer-\d+\] has died!')

    def test_a_wrong_type_and_the_source_it_never_delivers_are_named(self):
        rospy.set_param('/loud3/generic_synthesizer/perceptions', BATTERY)
        battery = rospy.Publisher('/loud3/battery', BatteryState, queue_size=1, latch=True)
        battery.publish(BatteryState(percentage=0.5))
        # its screen: the warning comes at once, before a rosout connection may be made
        synth = ScreenOutput(subprocess.Popen(node_command('rason_wiring', 'generic_synthesizer') + ['__ns:=/loud3'],
                                              stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                              universal_newlines=True))
        mas = start_mas('loud3', os.path.join(HERE, 'agents', 'sleeper.mas2j'), expected_sources='[battery]',
                        expect_within=1.0)
        try:
            found = synth.wait_for(
                r'^\[WARN\] \[[0-9.]+\]: generic_synthesizer: battery: /loud3/battery is published as '
                r'sensor_msgs/BatteryState, but the entry reads it as std_msgs/Float32: it perceives nothing from it '
                r'until the entry\'s type is sensor_msgs/BatteryState$', timeout=30)
            self.assertTrue(found, 'no type warning')
            found = self.log.wait_for(r"^perception source 'battery' not heard within 1 s of the start "
                                      r"\(~expected_sources\)", timeout=40, node='/loud3/rason_mas')
            self.assertTrue(found, 'no warning of the silent source')
            self.log.wait_quiet(1.5, pattern='perception source')
            self.assertEqual(len(self.log.lines(r"^perception source 'battery'")), 1, 'warned once')
        finally:
            stop_mas(mas)
            synth.proc.terminate()
            synth.proc.wait(timeout=20)


if __name__ == '__main__':
    rostest.rosrun('rason', 'loud_mistakes', TestLoudMistakes)
