"""When actions are published, held or refused (rason_bridge.action_sender), without ROS."""
from rason_bridge.action_sender import DEFERRED, NO_DECOMPOSER, SENT, ActionSender


class FakeGraph(object):
    """Connections of our publisher and subscribers listed by the master."""

    def __init__(self, connected=0, listed=0):
        self.connected = connected
        self.listed = listed
        self.now = 100.0
        self.sent = []
        self.failed = []

    def sender(self, wait=2.0):
        return ActionSender(publish=self.sent.append,
                            connected=lambda: self.connected,
                            listed=lambda: self.listed,
                            fail=lambda a, r: self.failed.append((a, r)),
                            connect_wait=wait, clock=lambda: self.now)


def test_connected_decomposer_gets_the_action_at_once():
    g = FakeGraph(connected=1, listed=1)
    sender = g.sender()
    sender.refresh_listed()
    assert sender.submit('move(1)') == SENT
    assert g.sent == ['move(1)']


def test_no_subscriber_at_all_is_no_decomposer():
    g = FakeGraph(connected=0, listed=0)
    assert g.sender().submit('move(1)') == NO_DECOMPOSER
    assert g.sent == []


def test_listed_but_not_yet_connected_is_held_then_sent_on_connection():
    g = FakeGraph(connected=0, listed=1)
    sender = g.sender()
    assert sender.submit('move(1)') == DEFERRED
    assert sender.flush() == 1 and g.sent == []
    g.connected = 1
    assert sender.flush() == 0
    assert g.sent == ['move(1)']


def test_second_decomposer_still_connecting_holds_the_action():
    g = FakeGraph(connected=1, listed=2)
    sender = g.sender()
    sender.refresh_listed()
    assert sender.submit('turn(5)') == DEFERRED
    g.now += 0.5
    assert sender.flush() == 1
    g.connected = 2
    sender.flush()
    assert g.sent == ['turn(5)']


def test_held_action_goes_to_the_connected_ones_after_the_wait():
    g = FakeGraph(connected=1, listed=2)
    sender = g.sender(wait=2.0)
    sender.refresh_listed()
    sender.submit('turn(5)')
    g.now += 2.5
    assert sender.flush() == 0
    assert g.sent == ['turn(5)'] and g.failed == []


def test_held_action_fails_when_the_subscriber_never_connects():
    g = FakeGraph(connected=0, listed=1)
    sender = g.sender(wait=2.0)
    sender.submit('move(1)')
    g.now += 2.5
    assert sender.flush() == 0
    assert g.failed == [('move(1)', NO_DECOMPOSER)] and g.sent == []


def test_held_action_fails_when_the_subscriber_goes_away():
    g = FakeGraph(connected=0, listed=1)
    sender = g.sender()
    sender.submit('move(1)')
    g.listed = 0
    sender.flush()
    assert g.failed == [('move(1)', NO_DECOMPOSER)]


def test_master_behind_a_live_connection_still_sends():
    g = FakeGraph(connected=1, listed=0)
    sender = g.sender()
    assert sender.submit('move(1)') == SENT
    assert g.sent == ['move(1)']


def test_held_actions_keep_their_order():
    g = FakeGraph(connected=0, listed=1)
    sender = g.sender()
    for a in ('a', 'b', 'c'):
        sender.submit(a)
    g.connected = 1
    sender.flush()
    assert g.sent == ['a', 'b', 'c']


def test_an_action_never_overtakes_one_held_before_it():
    g = FakeGraph(connected=0, listed=1)
    sender = g.sender()
    assert sender.submit('move(1)') == DEFERRED
    g.connected = 1  # connected now, but move(1) is still held: its cancel must wait behind it
    assert sender.submit('cancel move(1)') == DEFERRED
    assert g.sent == []
    assert sender.flush() == 0
    assert g.sent == ['move(1)', 'cancel move(1)']
