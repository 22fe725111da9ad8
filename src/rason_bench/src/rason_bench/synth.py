"""``bench_synth``: a synthesizer-like node that publishes bursts of perceptions.

Every 1/rate s it publishes one ``rason_msgs/Perception`` on ``jason/perception``
with ``count`` literals (:func:`rason_bench.protocol.burst`), all new in every
message, paced on the wall clock.

~params: ``count`` (int, 10), ``rate`` (float Hz, 50), ``source`` (str, ``<node name>_burst``).
"""
import time

import rospy
from rason_msgs.msg import Perception

from rason_bench.protocol import burst


def main():
    rospy.init_node('bench_synth')
    count = int(rospy.get_param('~count', 10))
    rate = float(rospy.get_param('~rate', 50.0))
    source = rospy.get_param('~source', rospy.get_name().split('/')[-1] + '_burst')
    pub = rospy.Publisher('jason/perception', Perception, queue_size=100, tcp_nodelay=True)
    period = 1.0 / rate
    seq = 0
    next_time = time.monotonic()
    while not rospy.is_shutdown():
        seq += 1
        pub.publish(Perception(source=source, perception=burst(count, seq)))
        next_time += period
        delay = next_time - time.monotonic()
        if delay > 0:
            time.sleep(delay)
        else:
            next_time = time.monotonic()  # late: do not try to catch up with a burst
