#!/usr/bin/python3
"""The cooperative fault diagnosis end to end (thesis chapter 7): faulty_helper.launch with
one fault injected; the test checks the dialogue that happened on /rason/messages, the
diagnosis on /diagnostics, and that Faulty's agents stopped by themselves.

Private parameters:
  ~expected        the component the diagnosis must name
  ~expect_help     whether Faulty must ask for help (false for the no-fault run)
  ~cancel_on_help  cancel the injected fault when Faulty asks for help: Faulty then moves
                   as planned while observed, a bad_move false positive
  ~timeout         seconds (wall) for the whole scenario
"""
import time
import unittest
from xmlrpc.client import ServerProxy

import rosgraph
import rason_rospy
import rospy
import rostest
from diagnosis_reporter.report import STATUS_NAME
from diagnostic_msgs.msg import DiagnosticArray
from rason_msgs.msg import AgentMessage
from rason_msgs.srv import FaultInjector

FAULTY_MAS = '/faulty/rason_mas'


class CaseStudyRun(object):
    """What a test needs to see of one scenario: the agent messages and the diagnosis."""

    def __init__(self, cancel_on_help):
        self.messages = []
        self.diagnosis = None
        self._cancel_on_help = cancel_on_help
        self._cancelled = None
        rospy.Subscriber('/rason/messages', AgentMessage, self._on_message, queue_size=100)
        rospy.Subscriber('/diagnostics', DiagnosticArray, self._on_diagnostics, queue_size=10)

    def _on_message(self, msg):
        self.messages.append((msg.sender, msg.receiver, msg.performative, msg.content))
        if (self._cancel_on_help and self._cancelled is None and msg.sender == 'faulty'
                and msg.receiver == '' and msg.content == 'helpme'):
            inject = rospy.ServiceProxy('/faulty/inject_fault', FaultInjector)
            self._cancelled = inject('cancel').return_message

    def _on_diagnostics(self, msg):
        for status in msg.status:
            if status.name == STATUS_NAME and self.diagnosis is None:
                self.diagnosis = dict((kv.key, kv.value) for kv in status.values)

    def said(self, sender, receiver, content_prefix):
        return any(s == sender and r == receiver and c.startswith(content_prefix)
                   for s, r, _, c in self.messages)

    @property
    def cancelled(self):
        return self._cancelled


def node_alive(name):
    """True while the node answers; the master keeps dead nodes registered."""
    try:
        uri = rosgraph.Master('/test_case_study').lookupNode(name)
        ServerProxy(uri).getPid('/test_case_study')
        return True
    except (rosgraph.MasterError, OSError):
        return False


class TestCaseStudy(unittest.TestCase):

    def test_diagnosis(self):
        expected = rospy.get_param('~expected')
        expect_help = rospy.get_param('~expect_help', True)
        cancel_on_help = rospy.get_param('~cancel_on_help', False)
        timeout = float(rospy.get_param('~timeout', 150.0))
        run = CaseStudyRun(cancel_on_help)

        deadline = time.monotonic() + timeout
        while run.diagnosis is None and time.monotonic() < deadline:
            time.sleep(0.1)
        self.assertIsNotNone(run.diagnosis, 'no diagnosis within %.0f s; messages: %s'
                             % (timeout, run.messages))
        self.assertEqual(run.diagnosis.get('agent'), 'faulty')
        self.assertEqual(run.diagnosis.get('component'), expected,
                         'evidence: %s; messages: %s' % (run.diagnosis.get('evidence'),
                                                         run.messages))

        if expect_help:
            self.assertTrue(run.said('faulty', '', 'helpme'), run.messages)
            self.assertTrue(run.said('helper', 'faulty', 'found(faulty)'), run.messages)
            self.assertTrue(run.said('faulty', 'helper', 'thanks'), run.messages)
        else:
            self.assertFalse(run.said('faulty', '', 'helpme'), run.messages)
        if cancel_on_help:
            self.assertIsNotNone(run.cancelled, 'the fault was never cancelled')
            self.assertIn('false positive', run.diagnosis.get('evidence', ''))

        # The scenario ends by itself: Faulty's agents stop (.stopMAS), its process leaves.
        while node_alive(FAULTY_MAS) and time.monotonic() < deadline + 15.0:
            time.sleep(0.2)
        self.assertFalse(node_alive(FAULTY_MAS), 'Faulty\'s rason_mas is still running')


if __name__ == '__main__':
    rason_rospy.init_node('test_case_study')
    rostest.rosrun('rason', 'case_study', TestCaseStudy)
