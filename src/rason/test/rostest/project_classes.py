#!/usr/bin/python3
"""A Jason project's own Java classes — an internal action, a belief base, an agent class, an
environment — run under rason_mas as under Jason's runner: compiled here with javac against
Jason's jar into the places Jason's builds put them (build/classes/java/main, lib/*.jar), they
are found there without a parameter, and anywhere else through ~classpath. Every line the
program prints comes from one of those classes."""
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

import rason_rospy

import rospy
import rostest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), 'nodes'))
from jason_runner import agent_lines, run_jason, run_rason_mas  # noqa: E402
from rason_bridge.jvm import jason_lib_classpath  # noqa: E402

HERE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))  # the test folder
PROJECT = os.path.join(HERE, 'agents', 'classes')
#: Seconds a run may take (JVM start included, on a busy machine); the program ends by itself.
RUN_TIMEOUT = 120.0
EXPECTED = [
    '[keeper] twice 21 is 42',  # mylib.twice
    '[keeper] the belief base counted 2 seen beliefs',  # mylib.CountingBB, read by mylib.seen_adds
    '[keeper] made by tagged_agent',  # mylib.TaggedAgent's initial belief
    '[keeper] the environment rang 7 times',  # town.Bell(7)'s answer to the action ring
]


def _sources(folder):
    return sorted(os.path.join(d, f) for d, _, files in os.walk(folder) for f in files if f.endswith('.java'))


class TestProjectClasses(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        rason_rospy.init_node('test_project_classes')
        cls.tmp = tempfile.mkdtemp(prefix='rason_project_classes_')
        # one javac for everything: mylib's classes as a folder, the environment as a jar
        compiled = os.path.join(cls.tmp, 'compiled')
        subprocess.run(['javac', '-nowarn', '-d', compiled, '-cp', os.pathsep.join(jason_lib_classpath())]
                       + _sources(os.path.join(PROJECT, 'src')), check=True)
        cls.mylib = os.path.join(compiled, 'mylib')
        cls.bell_jar = os.path.join(cls.tmp, 'bell.jar')
        subprocess.run(['jar', 'cf', cls.bell_jar, '-C', compiled, 'town'], check=True)

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def project(self, name, classes, jar):
        """A copy of the program in its own folder, its classes under ``classes``, its jar at ``jar``."""
        folder = os.path.join(self.tmp, name)
        os.makedirs(folder)
        for f in ('classes.mas2j', 'keeper.asl'):
            shutil.copy(os.path.join(PROJECT, f), folder)
        shutil.copytree(self.mylib, os.path.join(folder, classes, 'mylib'))
        os.makedirs(os.path.dirname(os.path.join(folder, jar)), exist_ok=True)
        shutil.copy(self.bell_jar, os.path.join(folder, jar))
        return folder

    def test_classes_beside_the_project_are_found_as_under_jasons_runner(self):
        folder = self.project('gradle_layout', 'build/classes/java/main', 'lib/bell.jar')
        mas2j = os.path.join(folder, 'classes.mas2j')
        # Jason's Gradle build runs the project with these on the class path, after Jason's
        jason = run_jason(mas2j, RUN_TIMEOUT, [os.path.join(folder, 'build/classes/java/main'),
                                               os.path.join(folder, 'lib/bell.jar')])
        self.assertEqual((jason.returncode, agent_lines(jason.output)), (0, EXPECTED), jason.text())
        rason = run_rason_mas(mas2j, 'classes_beside', RUN_TIMEOUT)
        self.assertEqual((rason.returncode, agent_lines(rason.output)), (0, EXPECTED), rason.text())

    def test_classes_elsewhere_are_found_through_the_classpath_parameter(self):
        folder = self.project('own_layout', 'out', 'jars/bell.jar')
        # one string, as a Java class path is written; relative to the .mas2j's folder
        rason = run_rason_mas(os.path.join(folder, 'classes.mas2j'), 'classes_given', RUN_TIMEOUT,
                              classpath=os.pathsep.join(['out', 'jars/*.jar']))
        self.assertEqual((rason.returncode, agent_lines(rason.output)), (0, EXPECTED), rason.text())


if __name__ == '__main__':
    rostest.rosrun('rason', 'project_classes', TestProjectClasses)
