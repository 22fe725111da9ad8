"""``rosrun rason rason_dialogue``: prints the agents' dialogue (/rason/messages) and each
new diagnosis and mission outcome (/diagnostics), one line each, e.g. for make demo."""
import rason_rospy
import rospy
from diagnostic_msgs.msg import DiagnosticArray
from rason_msgs.msg import AgentMessage

from diagnosis_reporter.report import MISSION_STATUS_NAME, STATUS_NAME
from rason_tools.dialogue import format_diagnosis, format_message, format_mission

#: The statuses printed, and how.
FORMATS = {STATUS_NAME: format_diagnosis, MISSION_STATUS_NAME: format_mission}


def main():
    rason_rospy.init_node('rason_dialogue')
    printed = set()

    def on_message(msg):
        line = format_message(msg.sender, msg.receiver, msg.performative, msg.content, msg.in_reply_to)
        if line is not None:
            rospy.loginfo(line)

    def on_diagnostics(msg):
        # diagnosis_reporter repeats its status every period; print each one once.
        for status in msg.status:
            if status.name not in FORMATS:
                continue
            line = FORMATS[status.name](status.hardware_id,
                                        [(kv.key, kv.value) for kv in status.values])
            if line and line not in printed:
                printed.add(line)
                rospy.loginfo(line)

    rospy.Subscriber('/rason/messages', AgentMessage, on_message, queue_size=100)
    rospy.Subscriber('/diagnostics', DiagnosticArray, on_diagnostics, queue_size=10)
    rospy.spin()
