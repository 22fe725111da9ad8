#!/usr/bin/python3
"""rason_mas refuses to run a project it cannot run as written, or as Jason would run it (a class
not on the class path; another infrastructure and windows: JUnit ProjectCheckTest), with exit status 1 and a fatal line
naming the cause after Jason's own error; and a rason_mas whose name another
node takes exits 1 saying so, while the new one keeps running."""
import os
import subprocess
import sys
import unittest
from xmlrpc.client import ServerProxy

import rosgraph
import rason_rospy
import rospy
import rostest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), 'nodes'))
from rason_testing import HERE, LogWatcher, node_command, stop_mas  # noqa: E402

BAD = os.path.join(HERE, 'agents', 'bad')


def rason_mas(project, name, *params):
    return subprocess.Popen(node_command('rason_bridge', 'rason_mas') + [os.path.join(BAD, project), '__name:=' + name]
                            + list(params),
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)


class TestBadProjects(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        rason_rospy.init_node('test_bad_projects')
        cls.log = LogWatcher()

    def refused(self, project, name, *params):
        proc = rason_mas(project, name, *params)
        try:
            out, _ = proc.communicate(timeout=60)
        except subprocess.TimeoutExpired:
            proc.kill()  # nothing of this test outlives it
            self.fail('%s still runs after 60 s:\n%s' % (project, proc.communicate()[0]))
        self.assertEqual(proc.returncode, 1, out)
        fatal = [l for l in out.splitlines() if l.startswith('[FATAL]')]
        self.assertEqual(len(fatal), 1, out)
        return out, fatal[0]

    def test_a_misspelt_architecture_class_is_named(self):
        _, fatal = self.refused('misspelt_arch.mas2j', 'bad_arch')
        self.assertIn("agent 'a': agentArchClass rason.RosAgArk not found", fatal)

    def test_a_misspelt_agent_class_is_named(self):
        _, fatal = self.refused('misspelt_agent_class.mas2j', 'bad_agent_class')
        self.assertIn("agent 'a': agentClass my.Agnt not found", fatal)

    def test_an_environment_not_on_the_class_path_is_named(self):
        _, fatal = self.refused('missing_env.mas2j', 'missing_env')
        self.assertIn("environment town.Bell not found (a typo, or its class is not on the class path: "
                      "see rason_mas's ~classpath)", fatal)

    def test_an_internal_action_not_on_the_class_path_is_named_after_jasons_warning(self):
        # Jason warns and parses it as an action, which would go to ROS
        out, fatal = self.refused('missing_action.mas2j', 'missing_action')
        self.assertIn("agent 'a': internal action mylib.twice not found (a typo, or its class is not on the class "
                      "path: see rason_mas's ~classpath)", fatal)
        lines = out.splitlines()
        warned = [i for i, l in enumerate(lines) if "internal action class for 'mylib.twice(21,X)'" in l]
        self.assertTrue(warned, out)
        self.assertLess(warned[0], lines.index(fatal), "Jason's warning comes before the fatal line")

    def test_a_classpath_entry_that_does_not_exist_is_a_bad_parameter(self):
        _, fatal = self.refused('ok.mas2j', 'bad_classpath', '_classpath:=classes')
        self.assertIn('bad parameter: classpath: classes (%s) does not exist' % os.path.join(BAD, 'classes'), fatal)

    def test_a_bad_trust_option_is_named(self):
        _, fatal = self.refused('bad_trust.mas2j', 'bad_trust')
        self.assertIn('trust_tellhow', fatal)

    def test_a_missing_include_is_named_with_every_path_tried(self):
        _, fatal = self.refused('missing_include.mas2j', 'missing_include')
        self.assertIn("agent 'a': included file 'no_such_file.asl' not found; tried [%s]"
                      % os.path.join(os.path.realpath(BAD), 'no_such_file.asl'), fatal)

    def test_an_agent_that_cannot_be_created_stops_the_node_after_jasons_error(self):
        out, fatal = self.refused('one_broken.mas2j', 'one_broken')
        self.assertIn('agent b could not be created', fatal)
        lines = out.splitlines()
        parse_error = [i for i, l in enumerate(lines) if 'broken.asl' in l and 'error' in l.lower()]
        self.assertTrue(parse_error, out)
        self.assertLess(parse_error[0], lines.index(fatal), "Jason's error comes before the fatal line")

    def test_a_node_whose_name_is_taken_exits_with_an_error_and_the_new_one_runs_on(self):
        first = rason_mas('ok.mas2j', 'namesake')
        self.assertTrue(self.log.wait_for(r'^\[a\] started$', node='/namesake', timeout=60), 'the first never ran')
        second = rason_mas('ok.mas2j', 'namesake')
        try:
            out, _ = first.communicate(timeout=60)
            self.assertEqual(first.returncode, 1, out)
            self.assertIn('another node registered with this node\'s name', out)
            # the new one started its agent after the first had gone, and is the node of that name now
            self.assertTrue(self.log.wait_for(r'^\[a\] started$', node='/namesake', count=2, timeout=60))
            # the master knows the name as the new node's, and that node answers
            uri = rosgraph.Master('/test_bad_projects').lookupNode('/namesake')
            _, _, pid = ServerProxy(uri).getPid('/test_bad_projects')
            self.assertEqual(pid, second.pid)
            self.assertIsNone(second.poll(), 'the new node ended too')
        finally:
            stop_mas(second)
            if first.poll() is None:
                first.kill()


if __name__ == '__main__':
    rostest.rosrun('rason', 'bad_projects', TestBadProjects)
