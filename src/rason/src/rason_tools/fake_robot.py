"""``rosrun rason fake_robot.py``: a scripted stand-in for a robot's decomposer and
synthesizer, for rostests and the demo.

~results (dict, {}): action name -> feedback result: a word of rason_msgs/Event ("OK",
    "no_progress", ...) or any other text;
    actions not listed are dropped, as a decomposer drops what it does not handle.
~delays (dict, {}): action name -> seconds before the feedback; an action cancelled
    (Action.CANCEL, or its agent's link gone) meanwhile is answered "cancelled" at once and
    never with its scripted result.
~seen_after_turns (int, -1): after this many answered turn actions, publish
    ~seen_perception on jason/perception (-1: never).
~seen_perception (list of str, []): the perception list published once "seen".
~source (str, "<node name>_robots"): the perception source.

Every taken action is announced (action_started) and answered once, through
rason_decomposer's Decomposer.
"""
import threading

import rason_rospy
import rospy
from rason_decomposer.node import Decomposer
from rason_msgs.msg import Perception


class FakeRobot(object):
    def __init__(self):
        self.results = rospy.get_param('~results', {})
        self.delays = rospy.get_param('~delays', {})
        self.seen_after = rospy.get_param('~seen_after_turns', -1)
        self.seen_perception = rospy.get_param('~seen_perception', [])
        self.source = rospy.get_param('~source', rospy.get_name().split('/')[-1] + '_robots')
        self.turns = 0
        self.lock = threading.Lock()
        self.timers = {}    # action -> threading.Timer of its delayed answer
        self.perception = rospy.Publisher('jason/perception', Perception, queue_size=10)
        # takes, announces, answers once and cancels the scripted actions
        self.decomposer = Decomposer(list(self.results), self.on_start, self.on_cancel)
        rospy.Timer(rospy.Duration(0.1), self.publish_perception)

    def on_start(self, action):
        delay = float(self.delays.get(action.name, 0.0))
        if delay <= 0:
            self.answer(action)
            return
        timer = threading.Timer(delay, self.answer, args=(action,))
        timer.daemon = True
        with self.lock:
            self.timers[action] = timer
        timer.start()

    def on_cancel(self, action, reason):
        with self.lock:
            timer = self.timers.pop(action, None)
        if timer is not None:
            timer.cancel()
        rospy.loginfo('fake_robot: %s #%d cancelled (%s)', action.name, action.action_id, reason)

    def answer(self, action):
        with self.lock:
            self.timers.pop(action, None)
        # counted before the answer, so the perception may already show it when the agent
        # goes on; a cancelled action is not answered again (finish() is then False)
        if action.name == 'turn' and self.decomposer.holds(action):
            with self.lock:
                self.turns += 1
        self.decomposer.finish(action, self.results[action.name])

    def publish_perception(self, _event):
        with self.lock:
            seen = 0 <= self.seen_after <= self.turns
        self.perception.publish(Perception(source=self.source,
                                           perception=self.seen_perception if seen else []))


def main():
    rason_rospy.init_node('fake_robot')
    FakeRobot()
    rospy.spin()
