"""Helpers shared by the rostest scripts: watching rosout and publishing feedback."""
import re
import threading
import time

import rosgraph
import rospy
from rosgraph_msgs.msg import Log
from rason_msgs.msg import Event, Perception


class LogWatcher(object):
    """Collects every rosout line (with the time it was heard) and waits for patterns."""

    def __init__(self):
        self._lines = []
        self._cond = threading.Condition()
        self._sub = rospy.Subscriber('/rosout', Log, self._on_log, queue_size=None)

    def _on_log(self, msg):
        with self._cond:
            self._lines.append((time.monotonic(), msg.level, msg.name, msg.msg))
            self._cond.notify_all()

    def wait_ready(self, timeout=20.0):
        """Wait until this watcher is connected to every node that publishes on /rosout."""
        master = rosgraph.Master(rospy.get_name())
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline and not rospy.is_shutdown():
            publishers, _, _ = master.getSystemState()
            listed = sum(len(n) for t, n in publishers if t == '/rosout')
            if listed and self._sub.get_num_connections() >= listed:
                return True
            time.sleep(0.02)
        return False

    def clear(self):
        with self._cond:
            del self._lines[:]

    def lines(self, pattern=None):
        with self._cond:
            return [l for l in self._lines if pattern is None or re.search(pattern, l[3])]

    def wait_for(self, pattern, timeout=20.0, count=1):
        """Wait until ``count`` lines match; returns the matching lines (empty on timeout)."""
        deadline = time.monotonic() + timeout
        with self._cond:
            while True:
                found = [l for l in self._lines if re.search(pattern, l[3])]
                if len(found) >= count:
                    return found
                left = deadline - time.monotonic()
                if left <= 0 or rospy.is_shutdown():
                    return []
                self._cond.wait(min(left, 0.1))


def feedback(agent, result, action_id, event_type='action_feedback'):
    """An Event message as a decomposer sends it."""
    return Event(agent=agent, event_type=event_type, parameters=[result, str(action_id)])


def wait_for_subscribers(pub, count=1, timeout=10.0):
    deadline = time.monotonic() + timeout
    while pub.get_num_connections() < count and time.monotonic() < deadline:
        time.sleep(0.02)
    return pub.get_num_connections() >= count


def start_agents(log, timeout=20.0):
    """Once ``log`` hears every node, publish the percept ``go`` that the test agents wait for."""
    if not log.wait_ready(timeout):
        raise AssertionError('not connected to every /rosout publisher')
    pub = rospy.Publisher('jason/perception', Perception, queue_size=1, latch=True)
    if not wait_for_subscribers(pub, timeout=timeout):
        raise AssertionError('rason_mas does not subscribe to jason/perception')
    pub.publish(Perception(source='rostest_start', perception=['go']))
    return pub
