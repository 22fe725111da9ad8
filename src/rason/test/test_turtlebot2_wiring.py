"""The TurtleBot 2 wiring file (config/turtlebot2/perceptions.yaml) is a configuration
generic_synthesizer accepts, and its bumper entry reads kobuki_msgs/BumperEvent as documented:
the message class is made here from kobuki_node's message definition (kobuki_msgs is not a
Debian package), no ROS master."""
import os

import genpy.dynamic
import pytest
import yaml

from rason_wiring import synth
from rason_wiring.ros_types import Resolver

HERE = os.path.dirname(os.path.abspath(__file__))
WIRING = os.path.join(os.path.dirname(HERE), 'config', 'turtlebot2', 'perceptions.yaml')
# kobuki_msgs/BumperEvent as kobuki_node publishes it on mobile_base/events/bumper
BUMPER_EVENT = 'uint8 LEFT=0\nuint8 CENTER=1\nuint8 RIGHT=2\nuint8 RELEASED=0\nuint8 PRESSED=1\nuint8 bumper\nuint8 state\n'
BumperEvent = genpy.dynamic.generate_dynamic('kobuki_msgs/BumperEvent', BUMPER_EVENT)['kobuki_msgs/BumperEvent']


class TurtlebotResolver(Resolver):
    def message(self, name):
        return BumperEvent if name == 'kobuki_msgs/BumperEvent' else super(TurtlebotResolver, self).message(name)


@pytest.fixture(scope='module')
def syntheses():
    with open(WIRING) as f:
        perceptions = yaml.safe_load(f)['perceptions']
    return {s.entry: s for s in synth.parse(perceptions, TurtlebotResolver())}


def test_the_file_reads_kobuki_node_s_topics(syntheses):
    assert {(s.entry, s.topic, s.source) for s in syntheses.values()} == {
        ('odometry', 'odom', 'odom'), ('bumper', 'mobile_base/events/bumper', 'bumper')}


def test_a_pressed_bumper_is_perceived_and_a_released_one_is_not(syntheses):
    bumper = syntheses['bumper']
    assert [str(l) for l in bumper.literals(BumperEvent(bumper=BumperEvent.RIGHT, state=BumperEvent.PRESSED))] == [
        'bumped(2)']
    assert bumper.literals(BumperEvent(bumper=BumperEvent.RIGHT, state=BumperEvent.RELEASED)) == []
