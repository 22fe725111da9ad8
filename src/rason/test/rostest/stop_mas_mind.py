#!/usr/bin/python3
"""The state an agent ends in when it stops its MAS with .stopMAS is the last jason/mind: a
subscriber receives it, a bag recorded with rosbag record holds it, and the dashboard's replay
of that bag shows it at the end."""
import os
import signal
import subprocess
import sys
import tempfile
import unittest

import rosgraph
import rason_rospy
import rospy
import rostest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), 'nodes'))
from jason_runner import run_rason_mas  # noqa: E402
from rason_testing import wait_for  # noqa: E402
from rason_dashboard.replay import load_bag  # noqa: E402
from rason_msgs.msg import MindState  # noqa: E402

HERE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))  # the test folder
PROGRAM = os.path.join(HERE, 'agents', 'mind', 'finisher.mas2j')
TOPIC = '/jason/mind'  # rason_mas runs from /


def subscribed(node_prefix):
    """Whether a node whose name starts with node_prefix subscribes to TOPIC."""
    _, subscribers, _ = rosgraph.Master('/test_stop_mas_mind').getSystemState()
    return any(n.startswith(node_prefix) for t, nodes in subscribers if t == TOPIC for n in nodes)


class TestStopMasMind(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        rason_rospy.init_node('test_stop_mas_mind')

    def test_the_last_state_is_published_recorded_and_replayed(self):
        received = []

        def ended():
            return [a for m in list(received) for a in m.agents if 'finished[source(self)]' in a.beliefs]
        sub = rospy.Subscriber(TOPIC, MindState, received.append, queue_size=100)
        bag = os.path.join(tempfile.mkdtemp(prefix='stop_mas_mind_'), 'run.bag')
        recorder = subprocess.Popen(['rosbag', 'record', '-O', bag, TOPIC],
                                    stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, start_new_session=True)
        try:
            wait_for(lambda: subscribed('/record_'), 20.0, 'rosbag record to subscribe')  # its anonymous name
            run = run_rason_mas(PROGRAM, 'finisher_mas', 90.0)
            self.assertEqual(run.returncode, 0, run.text())
            wait_for(ended, 10.0, 'the state the agent ended in on jason/mind')
        finally:
            sub.unregister()
            os.killpg(recorder.pid, signal.SIGINT)  # rosbag record closes the bag on SIGINT
            recorder.wait(20.0)
        # the bag is written as run.bag.active and renamed by rosbag's recorder process, which
        # can end after the `rosbag record` wrapper waited for above
        wait_for(lambda: os.path.exists(bag), 20.0, 'rosbag record to close %s' % bag)
        last = ended()[-1]
        self.assertEqual((list(last.goals), list(last.intentions)), ([], []))

        timeline, counts = load_bag(bag)
        self.assertGreater(counts['minds'], 0, 'no jason/mind in the bag')
        (robot,) = timeline.view()['robots']
        agent = robot['agents'][0]
        self.assertIn('finished[source(self)]', agent['beliefs'])
        self.assertEqual((agent['goals'], agent['intentions']), ([], []))


if __name__ == '__main__':
    rostest.rosrun('rason', 'stop_mas_mind', TestStopMasMind)
