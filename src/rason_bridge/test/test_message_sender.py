"""Agent messages to other processes (rason_bridge.message_sender.MessageSender), without ROS:
held until their process is linked, in order, broadcasts at once."""
from rason_bridge.message_sender import HELD, SENT, MessageSender


class Fake(object):
    def __init__(self):
        self.sent = []
        self.links = set()
        self.now = 100.0

    def sender(self, wait=2.0):
        return MessageSender(publish=self.sent.append, linked=self.links.__contains__,
                             connect_wait=wait, clock=lambda: self.now)


def test_message_to_a_linked_process_goes_at_once():
    f = Fake()
    f.links.add('/r2/rason_mas')
    sender = f.sender()
    assert sender.submit('m1', '/r2/rason_mas') == SENT
    assert f.sent == ['m1']


def test_broadcast_goes_at_once_even_without_links():
    f = Fake()
    sender = f.sender()
    assert sender.submit('b1', '') == SENT
    assert f.sent == ['b1']


def test_message_waits_for_its_link_and_keeps_its_order():
    f = Fake()
    sender = f.sender()
    assert sender.submit('m1', '/r2/rason_mas') == HELD
    assert sender.submit('m2', '/r2/rason_mas') == HELD
    assert sender.flush() == (2, [])
    f.links.add('/r2/rason_mas')
    # linked now, but m3 must not overtake the held ones
    assert sender.submit('m3', '/r2/rason_mas') == HELD
    assert sender.flush() == (0, [])
    assert f.sent == ['m1', 'm2', 'm3']
    assert sender.submit('m4', '/r2/rason_mas') == SENT


def test_held_messages_for_one_process_do_not_hold_others():
    f = Fake()
    f.links.add('/r3/rason_mas')
    sender = f.sender()
    sender.submit('to2', '/r2/rason_mas')
    assert sender.submit('to3', '/r3/rason_mas') == SENT
    assert f.sent == ['to3']
    assert sender.held_count() == 1


def test_message_whose_link_never_comes_is_published_after_the_wait_and_reported():
    f = Fake()
    sender = f.sender(wait=2.0)
    sender.submit('m1', '/r2/rason_mas')
    f.now += 1.9
    assert sender.flush() == (1, [])
    f.now += 0.2
    assert sender.flush() == (0, ['m1'])
    assert f.sent == ['m1']
