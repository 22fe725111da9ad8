"""``missions_done``: ends a launch once every robot named has reported its mission's outcome.

fleet_case_study.launch runs it with ``end_when_done:=true`` (required, so roslaunch stops the
whole launch when it exits): a fleet run has no agent that stops the MAS, since any robot may
still be needed by another, so a run that should end by itself needs an observer of the whole
fleet. Pure part: :class:`MissionsAwaited`; :func:`main` is the thin node.

Private parameters: ``~agents`` (names separated by spaces) and ``~linger`` (wall seconds kept
after the last outcome, so that a recorder still writes what followed it; default 1).
"""
from diagnosis_reporter.report import MISSION_STATUS_NAME


class MissionsAwaited(object):
    """The agents whose ``rason/mission`` status has not been heard yet."""

    def __init__(self, agents):
        self.awaited = set(agents)
        if not self.awaited:
            raise ValueError('no agent to await: ~agents is empty')

    def note(self, statuses):
        """Take the statuses of one DiagnosticArray; return the agents newly done."""
        done = []
        for status in statuses:
            if status.name != MISSION_STATUS_NAME:
                continue
            agent = next((kv.value for kv in status.values if kv.key == 'agent'), None)
            if agent in self.awaited:
                self.awaited.discard(agent)
                done.append(agent)
        return done

    @property
    def all_done(self):
        return not self.awaited


def main():
    import threading
    import time

    import rason_rospy

    import rospy
    from diagnostic_msgs.msg import DiagnosticArray

    rason_rospy.init_node('missions_done')
    try:
        awaited = MissionsAwaited(rospy.get_param('~agents', '').split())
    except ValueError as e:
        rospy.logfatal(str(e))
        raise SystemExit(2)
    linger = float(rospy.get_param('~linger', 1.0))
    finished = threading.Event()

    def on_diagnostics(msg):
        for agent in awaited.note(msg.status):
            rospy.loginfo('%s reported its mission; %d to go', agent, len(awaited.awaited))
        if awaited.all_done:
            finished.set()

    rospy.Subscriber('/diagnostics', DiagnosticArray, on_diagnostics, queue_size=100)
    while not finished.wait(0.2):
        if rospy.is_shutdown():
            return
    rospy.loginfo('every mission reported; ending the launch in %.1f s', linger)
    time.sleep(linger)  # wall time: the recorder still writes the statuses just heard
