"""Agent messages to other processes (rason_bridge.peers.MessageOutbox), without ROS:
held until their process is linked, in order, broadcasts at once."""
from rason_bridge.peers import HELD, SENT, MessageOutbox


class Fake(object):
    def __init__(self):
        self.sent = []
        self.links = set()
        self.now = 100.0

    def outbox(self, wait=2.0):
        return MessageOutbox(publish=self.sent.append, linked=self.links.__contains__,
                             connect_wait=wait, clock=lambda: self.now)


def test_message_to_a_linked_process_goes_at_once():
    f = Fake()
    f.links.add('/r2/rason_mas')
    box = f.outbox()
    assert box.submit('m1', '/r2/rason_mas') == SENT
    assert f.sent == ['m1']


def test_broadcast_goes_at_once_even_without_links():
    f = Fake()
    box = f.outbox()
    assert box.submit('b1', '') == SENT
    assert f.sent == ['b1']


def test_message_waits_for_its_link_and_keeps_its_order():
    f = Fake()
    box = f.outbox()
    assert box.submit('m1', '/r2/rason_mas') == HELD
    assert box.submit('m2', '/r2/rason_mas') == HELD
    assert box.flush() == (2, [])
    f.links.add('/r2/rason_mas')
    # linked now, but m3 must not overtake the held ones
    assert box.submit('m3', '/r2/rason_mas') == HELD
    assert box.flush() == (0, [])
    assert f.sent == ['m1', 'm2', 'm3']
    assert box.submit('m4', '/r2/rason_mas') == SENT


def test_held_messages_for_one_process_do_not_hold_others():
    f = Fake()
    f.links.add('/r3/rason_mas')
    box = f.outbox()
    box.submit('to2', '/r2/rason_mas')
    assert box.submit('to3', '/r3/rason_mas') == SENT
    assert f.sent == ['to3']
    assert box.held_count() == 1


def test_message_whose_link_never_comes_is_published_after_the_wait_and_reported():
    f = Fake()
    box = f.outbox(wait=2.0)
    box.submit('m1', '/r2/rason_mas')
    f.now += 1.9
    assert box.flush() == (1, [])
    f.now += 0.2
    assert box.flush() == (0, ['m1'])
    assert f.sent == ['m1']
