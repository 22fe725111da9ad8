"""generic_synthesizer: topics turned into agents' perceptions by ``~perceptions`` (see
:mod:`rason_wiring.synth`).

The rospy plumbing only: one subscriber per entry (its message class resolved at start-up),
each message made into literals by the checked :class:`~rason_wiring.synth.Synthesis`, and
the entry's :class:`~rason_wiring.synth.Gate` deciding when its list goes out on
jason/perception under its source. A thread polls the gates, so a list held back by the rate
limit goes out when its interval is over even if the topic falls silent.
"""
import sys
import threading
import time

import rosgraph
import rason_rospy
import rospy
from rason_msgs.msg import Perception

from rason_wiring import layout, synth
from rason_wiring.config import ConfigError
from rason_wiring.ros_types import Resolver
from rason_wiring.type_check import TypeCheck

#: How often (wall time) the gates are polled: the rate limit's and refresh's resolution.
POLL_PERIOD = 0.02
#: How often (wall time) the master is asked which types the topics are published with.
TYPE_CHECK_PERIOD = 2.0


class _Entry(object):

    def __init__(self, synthesis):
        self.synthesis = synthesis
        self.gate = synthesis.gate()
        self.lock = threading.Lock()


class GenericSynthesizer(object):

    def __init__(self, syntheses):
        self._perception = rospy.Publisher('jason/perception', Perception, queue_size=100)
        self._entries = [_Entry(s) for s in syntheses]
        for entry in self._entries:
            rospy.Subscriber(entry.synthesis.topic, entry.synthesis.msg_class, self._on_message,
                             callback_args=entry, queue_size=10)
        threading.Thread(target=self._poll, daemon=True, name='synth_poll').start()
        self._type_check = TypeCheck([(s.entry, rospy.resolve_name(s.topic), s.type_name) for s in syntheses])
        threading.Thread(target=self._check_types, daemon=True, name='synth_types').start()
        rospy.loginfo('generic_synthesizer: %s', '; '.join(
            '%s: %s (%s) -> source %s' % (s.entry, rospy.resolve_name(s.topic), s.type_name, s.source)
            for s in syntheses))

    def _on_message(self, msg, entry):
        try:
            literals = entry.synthesis.literals(msg)
        except Exception as e:     # a field the message did not fill as its type says
            rospy.logwarn_throttle(5.0, 'generic_synthesizer: %s: message not read: %s',
                                   entry.synthesis.entry, e)
            return
        with entry.lock:           # publishing under the lock keeps the lists in order
            out = entry.gate.offer(literals, rospy.get_time())
            if out is not None:
                self._publish(entry, out)

    def _poll(self):
        while not rospy.is_shutdown():
            now = rospy.get_time()
            for entry in self._entries:
                with entry.lock:
                    out = entry.gate.poll(now)
                    if out is not None:
                        self._publish(entry, out)
            time.sleep(POLL_PERIOD)

    def _check_types(self):
        master = rosgraph.Master(rospy.get_name())
        while not rospy.is_shutdown():
            try:
                published = dict(master.getPublishedTopics('/'))
            except Exception:      # the master is gone: the node is shutting down
                published = {}
            for line in self._type_check.warnings(published, time.monotonic()):
                rospy.logwarn('generic_synthesizer: %s', line)
            time.sleep(TYPE_CHECK_PERIOD)

    def _publish(self, entry, literals):
        self._perception.publish(Perception(source=entry.synthesis.source, perception=literals))


def main():
    rason_rospy.init_node('generic_synthesizer')
    node = rospy.get_name().split('/')[-1]
    try:
        syntheses = synth.parse(layout.wiring_param('perceptions', rospy), Resolver(),
                                default_source=lambda entry: '%s_%s' % (node, entry))
    except (ConfigError, ValueError, TypeError) as e:
        rospy.logfatal('generic_synthesizer: bad configuration: %s', e)
        rospy.signal_shutdown('bad configuration')
        sys.exit(1)
    GenericSynthesizer(syntheses)
    rospy.spin()
