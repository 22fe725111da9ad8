"""The protocol's words are spelt once: rason_msgs' Event.msg and Action.msg constants, which
the Java side (rason.core.Protocol) must repeat exactly."""
import jpype
import pytest
from rason_msgs.msg import Action, Event

from rason_bridge.jvm import start_jvm

start_jvm()
Protocol = jpype.JClass('rason.core.Protocol')


@pytest.mark.parametrize('name', ['ACTION_FEEDBACK', 'ACTION_STARTED', 'OK', 'CANCELLED', 'TIMEOUT',
                                  'NO_DECOMPOSER', 'SHUTDOWN', 'BRIDGE_ERROR', 'DECOMPOSER_LOST',
                                  'SUSPENDED', 'DROPPED', 'RESTART'])
def test_java_protocol_words_are_the_event_constants(name):
    assert str(getattr(Protocol, name)) == getattr(Event, name)


def test_the_cancel_action_name_is_the_action_constant():
    assert str(Protocol.CANCEL) == Action.CANCEL


def test_every_java_protocol_word_is_a_message_constant():
    fields = [str(f.getName()) for f in Protocol.class_.getDeclaredFields()
              if jpype.JClass('java.lang.reflect.Modifier').isPublic(f.getModifiers())]
    assert fields and all(str(getattr(Protocol, f)) in (getattr(Event, f, None), getattr(Action, f, None))
                          for f in fields), fields
