"""``bench_synth``: a synthesizer-like node that publishes bursts of perceptions.

Every 1/rate s it publishes one ``rason_msgs/Perception`` on ``jason/perception``
with ``count`` literals (:func:`rason_bench.protocol.burst`), all new in every
message, paced on the wall clock.

As the flood of the hostile part (``mark_period`` > 0), the last of the ``count``
literals is the current :func:`rason_bench.protocol.flood_mark`: a new mark every
``mark_period`` s, stamped when first published, and one more in the very last
message, after ``duration`` s; then the node publishes nothing more, sets ``~published`` to the number of
messages it published, and waits to be stopped (the last message still goes out).

~params: ``count`` (int, 10), ``rate`` (float Hz, 50), ``source`` (str, ``<node name>_burst``),
``duration`` (float s, 0: until stopped), ``mark_period`` (float s, 0: no marks), ``run``
(int, 0: the marks' run).
"""
import time

import rason_rospy
import rospy
from rason_msgs.msg import Perception

from rason_bench.protocol import FINAL_MARK, burst, flood_mark


class Marks(object):
    """The flood mark of each moment: a new one every ``period`` s (monotonic clock),
    stamped in ms when first asked for."""

    def __init__(self, run, period):
        self.run, self.period = run, period
        self.mark, self.stamp_ms, self._next = 0, None, None

    def current(self, now):
        if self._next is None or now >= self._next:
            self.new(now)
        return flood_mark(self.run, self.mark, self.stamp_ms)

    def new(self, now):
        self.mark += 1
        self.stamp_ms = now * 1000.0
        self._next = now + self.period
        return flood_mark(self.run, self.mark, self.stamp_ms)

    def final(self, now):
        """The mark of the flood's last message."""
        return flood_mark(self.run, FINAL_MARK, now * 1000.0)


def main():
    rason_rospy.init_node('bench_synth')
    count = int(rospy.get_param('~count', 10))
    rate = float(rospy.get_param('~rate', 50.0))
    source = rospy.get_param('~source', rospy.get_name().split('/')[-1] + '_burst')
    duration = float(rospy.get_param('~duration', 0.0))
    mark_period = float(rospy.get_param('~mark_period', 0.0))
    marks = Marks(int(rospy.get_param('~run', 0)), mark_period) if mark_period > 0 else None
    pub = rospy.Publisher('jason/perception', Perception, queue_size=100, tcp_nodelay=True)
    period = 1.0 / rate
    seq = 0
    start = next_time = time.monotonic()
    while not rospy.is_shutdown():
        seq += 1
        now = time.monotonic()
        if duration > 0 and now - start >= duration:
            break
        literals = burst(count - 1, seq) + [marks.current(now)] if marks else burst(count, seq)
        pub.publish(Perception(source=source, perception=literals))
        next_time += period
        delay = next_time - time.monotonic()
        if delay > 0:
            time.sleep(delay)
        else:
            next_time = time.monotonic()  # late: do not try to catch up with a burst
    if rospy.is_shutdown():
        return
    if marks:  # the newest perception: how long it takes to reach the agent is the measure
        pub.publish(Perception(source=source, perception=burst(count - 1, seq) + [marks.final(time.monotonic())]))
    rospy.set_param('~published', seq)
    rospy.loginfo('published %d messages in %.1f s', seq, time.monotonic() - start)
    rospy.spin()
