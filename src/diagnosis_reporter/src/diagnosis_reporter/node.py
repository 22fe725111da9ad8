"""diagnosis_reporter_node: the decomposer of report_diagnosis(Component, Evidence).

Publishes each diagnosis on /diagnostics (DiagnosticStatus ``rason/diagnosis``, values
agent, component, evidence), once at once and then every ``~period`` s while it is the
latest (diagnostic aggregators expect repeats), and answers the action ``Event.OK``, or
``Event.BAD_PARAMETERS`` when the component is unknown (at once, without action_started).
jason/action and jason/event go through rason_decomposer's Decomposer.
"""
import threading

import rospy
from diagnostic_msgs.msg import DiagnosticArray, DiagnosticStatus, KeyValue
from rason_decomposer.node import Decomposer
from rason_msgs.msg import Event

from diagnosis_reporter import report


class DiagnosisReporter(object):
    def __init__(self, hardware_id, period):
        self._hardware_id = hardware_id
        self._latest = None
        self._lock = threading.Lock()
        self._diag_pub = rospy.Publisher('/diagnostics', DiagnosticArray, queue_size=10)
        self._decomposer = Decomposer([report.ACTION], self._on_start, self._on_cancel)
        if period > 0:
            rospy.Timer(rospy.Duration(period), lambda _: self._publish())

    def _on_start(self, action):
        try:
            diagnosis = report.parse(action.agent, list(action.parameters))
        except report.BadDiagnosis as e:
            rospy.logerr('diagnosis_reporter: %s', e)
            self._decomposer.refuse(action, Event.BAD_PARAMETERS)
            return
        rospy.loginfo('diagnosis_reporter: %s', diagnosis.message)
        with self._lock:
            self._latest = diagnosis
        self._publish()
        self._decomposer.finish(action, Event.OK)

    def _on_cancel(self, action, reason):
        # answered within on_start: nothing runs that could be stopped
        pass

    def _publish(self):
        with self._lock:
            diagnosis = self._latest
        if diagnosis is None:
            return
        status = DiagnosticStatus(level=diagnosis.level, name=report.STATUS_NAME,
                                  message=diagnosis.message, hardware_id=self._hardware_id,
                                  values=[KeyValue(k, v) for k, v in diagnosis.values()])
        array = DiagnosticArray(status=[status])
        array.header.stamp = rospy.Time.now()
        self._diag_pub.publish(array)


def main():
    rospy.init_node('diagnosis_reporter')
    namespace = rospy.get_namespace().strip('/') or 'robot'
    DiagnosisReporter(rospy.get_param('~hardware_id', namespace), float(rospy.get_param('~period', 1.0)))
    rospy.spin()
