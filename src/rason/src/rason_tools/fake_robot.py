"""``rosrun rason fake_robot.py``: a scripted stand-in for a robot's decomposer and
synthesizer, for rostests and the demo.

~results (dict, {}): action name -> feedback result: a word of rason_msgs/Event ("OK",
    "no_progress", ...) or any other text;
    actions not listed are dropped, as a decomposer drops what it does not handle.
~delays (dict, {}): action name -> seconds before the feedback.
~seen_after_turns (int, -1): after this many answered turn actions, publish
    ~seen_perception on jason/perception (-1: never).
~seen_perception (list of str, []): the perception list published once "seen".
~source (str, "<node name>_robots"): the perception source.
"""
import threading
import time

import rospy
from rason_msgs.msg import Action, Event, Perception


class FakeRobot(object):
    def __init__(self):
        self.results = rospy.get_param('~results', {})
        self.delays = rospy.get_param('~delays', {})
        self.seen_after = rospy.get_param('~seen_after_turns', -1)
        self.seen_perception = rospy.get_param('~seen_perception', [])
        self.source = rospy.get_param('~source', rospy.get_name().split('/')[-1] + '_robots')
        self.turns = 0
        self.events = rospy.Publisher('jason/event', Event, queue_size=100)
        self.perception = rospy.Publisher('jason/perception', Perception, queue_size=10)
        rospy.Subscriber('jason/action', Action, self.on_action, queue_size=100)
        rospy.Timer(rospy.Duration(0.1), self.publish_perception)

    def on_action(self, msg):
        if msg.action not in self.results:
            return
        delay = float(self.delays.get(msg.action, 0.0))
        threading.Timer(delay, self.answer, args=(msg,)).start()

    def answer(self, msg):
        # an event published before rason_mas is connected would be lost
        deadline = time.monotonic() + 5.0
        while self.events.get_num_connections() == 0 and time.monotonic() < deadline:
            time.sleep(0.01)
        if msg.action == 'turn':
            self.turns += 1
        self.events.publish(Event(agent=msg.agent, event_type=Event.ACTION_FEEDBACK,
                                  parameters=[self.results[msg.action], str(msg.action_id)]))

    def publish_perception(self, _event):
        seen = 0 <= self.seen_after <= self.turns
        self.perception.publish(Perception(source=self.source,
                                           perception=self.seen_perception if seen else []))


def main():
    rospy.init_node('fake_robot')
    FakeRobot()
    rospy.spin()
