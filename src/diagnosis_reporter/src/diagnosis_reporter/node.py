"""diagnosis_reporter_node: the decomposer of report_diagnosis(Component, Evidence) and
report_mission(Completed, By, Recovery, Diagnosis).

Publishes each diagnosis on /diagnostics (DiagnosticStatus ``rason/diagnosis``, values
agent, component, evidence) and each mission outcome (``rason/mission``, values agent,
completed, by, recovery, diagnosis), once at once and then every ``~period`` s while it is
the latest of its name (diagnostic aggregators expect repeats), and answers the action
``Event.OK``, or ``Event.BAD_PARAMETERS`` when a parameter is wrong (at once, without
action_started).
jason/action and jason/event go through rason_decomposer's Decomposer.
"""
import threading

import rason_rospy
import rospy
from diagnostic_msgs.msg import DiagnosticArray, DiagnosticStatus, KeyValue
from rason_decomposer.node import Decomposer
from rason_msgs.msg import Event

from diagnosis_reporter import report


class DiagnosisReporter(object):
    def __init__(self, hardware_id, period):
        self._hardware_id = hardware_id
        self._latest = {}       # status name -> the latest Diagnosis or Mission
        self._lock = threading.Lock()
        self._diag_pub = rospy.Publisher('/diagnostics', DiagnosticArray, queue_size=10)
        self._decomposer = Decomposer([report.ACTION, report.MISSION_ACTION], self._on_start,
                                      self._on_cancel)
        if period > 0:
            rospy.Timer(rospy.Duration(period), lambda _: self._publish())

    def _on_start(self, action):
        mission = action.name == report.MISSION_ACTION
        try:
            parse = report.parse_mission if mission else report.parse
            outcome = parse(action.agent, list(action.parameters))
        except report.BadDiagnosis as e:
            rospy.logerr('diagnosis_reporter: %s', e)
            self._decomposer.refuse(action, Event.BAD_PARAMETERS)
            return
        rospy.loginfo('diagnosis_reporter: %s', outcome.message)
        with self._lock:
            self._latest[report.MISSION_STATUS_NAME if mission else report.STATUS_NAME] = outcome
        self._publish()
        self._decomposer.finish(action, Event.OK)

    def _on_cancel(self, action, reason):
        # answered within on_start: nothing runs that could be stopped
        pass

    def _publish(self):
        with self._lock:
            latest = sorted(self._latest.items())
        if not latest:
            return
        array = DiagnosticArray(status=[
            DiagnosticStatus(level=outcome.level, name=name, message=outcome.message,
                             hardware_id=self._hardware_id,
                             values=[KeyValue(k, v) for k, v in outcome.values()])
            for name, outcome in latest])
        array.header.stamp = rospy.Time.now()
        self._diag_pub.publish(array)


def main():
    rason_rospy.init_node('diagnosis_reporter')
    namespace = rospy.get_namespace().strip('/') or 'robot'
    DiagnosisReporter(rospy.get_param('~hardware_id', namespace), float(rospy.get_param('~period', 1.0)))
    rospy.spin()
