"""Jason messages crossing between processes (jason_lib Messages), through JPype without a ROS
master: content survives the trip as text, malformed content is refused with a reason."""
import jpype
import pytest

from rason_bridge.jvm import start_jvm

start_jvm()
Messages = jpype.JClass('rason.messaging.Messages')
Message = jpype.JClass('jason.asSemantics.Message')
ASSyntax = jpype.JClass('jason.asSyntax.ASSyntax')


@pytest.mark.parametrize('content', [
    'hello',
    'hello(1)',
    'robot(faulty,-3.5,1.5,12)',
    'value(42)[source(bob),quality(high)]',
    'name("green \\"big\\" cylinder")',
    '[a,b(1),"c"]',
    'ns1::pos(1,2)',
    '~door(open)',
    '42',
    '"just text"',
    'go(pos(1,2),[a,b])',
    'path("C:\\\\temp")',
    'say("two\\nlines\\tand a tab")',
    'said(x)[how("loudly, \\"really\\"")]',
    '[p("a\\"b"),[q("c\\\\d")]]',
])
def test_content_round_trips_as_text(content):
    term = ASSyntax.parseTerm(content)
    sent = Message('tell', 'alice', 'bob', term)
    text = Messages.contentText(sent)
    back = Messages.parseContent(text)
    assert back.equals(term), (str(text), str(back))
    assert str(back) == str(term)


@pytest.mark.parametrize('text, why', [
    ('', 'empty content'),
    ('   ', 'empty content'),
    ('foo(', 'not a Jason term'),
    ('foo(a) bar', 'not a Jason term'),
    ('@#!', 'not a Jason term'),
])
def test_malformed_content_is_refused_with_a_reason(text, why):
    with pytest.raises(jpype.JException) as info:
        Messages.parseContent(text)
    assert why in str(info.value.getMessage())


def test_received_message_keeps_ids_so_a_reply_finds_its_ask():
    m = Messages.toJason('tell', 'bob', 'alice', ASSyntax.parseTerm('secret(1)'), 'mid7', 'samid3')
    assert str(m.getMsgId()) == 'mid7'
    assert str(m.getInReplyTo()) == 'samid3'
    assert m.isReplyToSyncAsk()
    assert str(m.getSender()) == 'bob'


def test_received_message_without_id_gets_a_fresh_one():
    m = Messages.toJason('achieve', 'bob', 'alice', ASSyntax.parseTerm('go'), '', '')
    assert str(m.getMsgId()).startswith('mid')
    assert m.getInReplyTo() is None
