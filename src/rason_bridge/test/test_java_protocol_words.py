"""The protocol's words are spelt once: rason_msgs/Event.msg's constants, which the Java
side (rason.bridge.Protocol) must repeat exactly."""
import jpype
import pytest
from rason_msgs.msg import Event

from rason_bridge.jvm import start_jvm

start_jvm()
Protocol = jpype.JClass('rason.bridge.Protocol')


@pytest.mark.parametrize('name', ['ACTION_FEEDBACK', 'OK', 'TIMEOUT', 'NO_DECOMPOSER', 'SHUTDOWN', 'BRIDGE_ERROR'])
def test_java_protocol_words_are_the_message_constants(name):
    assert str(getattr(Protocol, name)) == getattr(Event, name)


def test_every_java_protocol_word_is_a_message_constant():
    fields = [str(f.getName()) for f in Protocol.class_.getDeclaredFields()
              if jpype.JClass('java.lang.reflect.Modifier').isPublic(f.getModifiers())]
    assert fields and all(getattr(Event, f, None) == str(getattr(Protocol, f)) for f in fields), fields
