"""The rason_mas node's threads as plain parts, driven step by step without ROS or Java:
perception pump, outbound pump, held flusher, presence loop, mind publisher, log pump."""
import collections
import itertools

import pytest

from rason_bridge.coalesce import PerceptionCoalescer
from rason_bridge.held_flusher import HeldFlusher
from rason_bridge.log_pump import LogPump, batch_lines, level_name
from rason_bridge.mind_publisher import MindPublisher
from rason_bridge.outbound_pump import OutboundItems, OutboundPump
from rason_bridge.perception_pump import SUMMARY_PERIOD, PerceptionPump
from rason_bridge.presence_loop import PresenceLoop


class Clock(object):
    def __init__(self):
        self.now = 100.0

    def __call__(self):
        return self.now


class Log(object):
    def __init__(self):
        self.lines = []

    def __call__(self, fmt, *args):
        self.lines.append(fmt % args)


# ---- perception pump ---------------------------------------------------------------------

def perception_pump(perceive, clock=None):
    warn, error = Log(), Log()
    pump = PerceptionPump(PerceptionCoalescer(max_sources=10, max_source_length=256), perceive,
                          release_memory=lambda: None, warn=warn, error=error, clock=clock or Clock())
    return pump, warn, error


def test_perception_pump_hands_on_the_newest_message_of_a_source():
    got = []
    pump, _, _ = perception_pump(lambda *m: got.append(m))
    pump.put('cam', ['a(1)'], 1)
    pump.put('cam', ['a(2)'], 2)
    pump.put('lidar', ['b(1)'], 3)
    pump.step()
    pump.step()
    assert sorted(got) == [('cam', ['a(2)'], 2), ('lidar', ['b(1)'], 3)]


def test_perception_pump_survives_a_failing_perceive_and_says_which_source():
    def perceive(*_):
        raise RuntimeError('boom')
    pump, _, error = perception_pump(perceive)
    pump.put('cam', ['a'], 1)
    pump.step()
    assert error.lines == ["could not hand the perception of 'cam' to the agents: boom"]


def test_perception_pump_reports_skipped_messages_at_most_once_a_period():
    clock = Clock()
    pump, warn, _ = perception_pump(lambda *m: None, clock)
    for i in range(5):
        pump.put('cam', ['a(%d)' % i], i)
    pump.step()
    assert warn.lines == []
    clock.now += SUMMARY_PERIOD
    pump.step()
    assert len(warn.lines) == 1 and 'perceptions come faster than the agents take them' in warn.lines[0]


# ---- outbound pump -----------------------------------------------------------------------

def test_outbound_pump_hands_on_everything_queued_then_ends_once_stopped():
    queue = collections.deque(['a', 'boom', 'b'])
    handled, error = [], Log()

    def take(wait_ms):
        if queue:
            return queue.popleft()
        pump.stop(join_timeout=0)  # the queue is empty: as if the node stopped meanwhile
        return None

    def handle(item):
        if item == 'boom':
            raise ValueError('bad item')
        handled.append(item)
    pump = OutboundPump(take, handle, error)
    pump.run()
    assert handled == ['a', 'b']
    assert error.lines == ['could not publish boom: bad item']


class JavaItem(object):
    def __init__(self, **fields):
        for name, value in fields.items():
            setattr(self, name, lambda value=value: value)


class Action(JavaItem):
    pass


class Cancel(JavaItem):
    pass


class AgentMessage(JavaItem):
    pass


class Announce(JavaItem):
    pass


class Stop(JavaItem):
    pass


class Receiver(object):
    def __init__(self):
        self.calls = []

    def __getattr__(self, name):
        return lambda *args: self.calls.append((name,) + args)


def test_outbound_items_call_the_receiver_method_of_their_kind():
    kinds = {c.__name__: c for c in (Action, Cancel, AgentMessage, Announce, Stop)}
    items = OutboundItems(lambda name: kinds[name.rsplit('$', 1)[1]])
    r = Receiver()
    items.dispatch(Action(agent='bob', actionId=3, action='move', parameters=['1', '2']), r)
    items.dispatch(Cancel(agent='bob', actionId=3, reason='dropped'), r)
    items.dispatch(AgentMessage(sender='bob', receiverMas='/r2', receiver='al', performative='tell',
                                content='hi', msgId='m1', inReplyTo=''), r)
    items.dispatch(Announce(), r)
    items.dispatch(Stop(exitValue=3), r)
    assert r.calls == [('publish_action', 'bob', 3, 'move', ['1', '2']), ('publish_cancel', 'bob', 3, 'dropped'),
                       ('publish_message', 'bob', '/r2', 'al', 'tell', 'hi', 'm1', ''), ('announce',),
                       ('stop_requested', 3)]


# ---- held flusher ------------------------------------------------------------------------

class HeldActions(object):
    """An action sender holding ``held`` actions; each flush sends one."""

    def __init__(self, held=0):
        self.held = held
        self.refreshed = 0

    def has_held(self):
        return self.held > 0

    def refresh_listed(self):
        self.refreshed += 1

    def flush(self):
        self.held = max(0, self.held - 1)
        return self.held


class HeldMessages(object):
    """A message sender holding ``held`` messages; each flush sends one, the first flush the unlinked ones."""

    def __init__(self, held=0, unlinked=()):
        self.held = held
        self.unlinked = list(unlinked)

    def held_count(self):
        return self.held

    def flush(self):
        self.held = max(0, self.held - 1)
        unlinked, self.unlinked = self.unlinked, []
        return self.held, unlinked


def test_held_flusher_flushes_until_nothing_is_held_and_reports_the_unlinked():
    actions, messages = HeldActions(held=3), HeldMessages(held=1, unlinked=['m'])
    unlinked, pauses = [], []
    flusher = HeldFlusher(actions, messages, unlinked.append, pause=pauses.append)
    flusher.step(woken=False)
    assert (actions.held, messages.held) == (0, 0)
    assert unlinked == ['m'] and len(pauses) == 2
    assert actions.refreshed == 0


def test_held_flusher_with_nothing_held_refreshes_the_subscriber_count():
    actions = HeldActions()
    flusher = HeldFlusher(actions, HeldMessages(), lambda m: None, pause=lambda s: None)
    flusher.step(woken=False)
    assert actions.refreshed == 1


def test_held_flusher_stops_flushing_when_the_process_ends():
    actions = HeldActions(held=10)
    flusher = HeldFlusher(actions, HeldMessages(), lambda m: None, alive=lambda: False, pause=lambda s: None)
    flusher.step(woken=True)
    assert actions.held == 9


# ---- presence loop -----------------------------------------------------------------------

def test_presence_loop_announces_every_period_and_ticks_every_step():
    clock, sent, ticks = Clock(), [], []
    loop = PresenceLoop(sent.append, lambda: ticks.append(1), period=0.5, error=Log(), clock=clock)
    loop.step()
    clock.now += 0.3
    loop.step()
    clock.now += 0.25
    loop.step()
    assert sent == [False, False] and len(ticks) == 3


def test_presence_loop_sends_nothing_after_the_leaving_announcement():
    sent = []
    loop = PresenceLoop(sent.append, lambda: None, period=0.5, error=Log(), clock=Clock())
    loop.leave()
    loop.announce()
    assert sent == [True]


def test_presence_loop_logs_a_failed_tick_and_goes_on():
    def tick():
        raise RuntimeError('gone')
    error = Log()
    loop = PresenceLoop(lambda leaving: None, tick, period=0.5, error=error, clock=Clock())
    loop.step()
    assert error.lines == ['presence tick failed: gone']


# ---- mind publisher ----------------------------------------------------------------------

class MindPort(object):
    """Java's MindPort as the publisher uses it."""

    def __init__(self):
        self.periods = []
        self.minds = []

    def setPeriodNanos(self, period):
        self.periods.append(period)

    def changes(self):
        return self.minds.pop(0) if self.minds else None

    def inspectorUrl(self):
        return 'http://localhost:3272'

    def requestReads(self):
        self.pending = 2
        self.minds.append([])  # what the agents read then

    def readsPending(self):
        self.pending = max(0, getattr(self, 'pending', 0) - 1)  # one more agent read each time asked
        return self.pending


class Publisher(object):
    def __init__(self):
        self.subscribers = 0
        self.sent = []

    def get_num_connections(self):
        return self.subscribers

    def publish(self, msg):
        self.sent.append(msg)


def test_mind_publisher_reads_only_while_subscribed_and_publishes_changes():
    bridge, pub = MindPort(), Publisher()
    mind = MindPublisher(bridge, pub, '/r1/rason_mas', 0.5, lambda: 7, RuntimeError, Log())
    bridge.minds = [[]]
    mind.step()
    assert bridge.periods == [] and pub.sent == []
    pub.subscribers = 1
    mind.step()
    assert bridge.periods == [500000000]
    assert len(pub.sent) == 1 and pub.sent[0].mas_id == '/r1/rason_mas'
    assert pub.sent[0].inspector_url == 'http://localhost:3272'
    mind.step()  # nothing changed: nothing published
    assert len(pub.sent) == 1
    pub.subscribers = 0
    mind.step()
    assert bridge.periods == [500000000, 0]


def test_mind_publisher_finish_publishes_the_state_the_agents_end_in():
    bridge, pub = MindPort(), Publisher()
    mind = MindPublisher(bridge, pub, '/r1/rason_mas', 0.5, lambda: 7, RuntimeError, Log())
    pub.subscribers = 1
    bridge.minds = [[]]
    mind.step()
    mind.finish(timeout=5.0, poll=0)
    assert bridge.pending == 0 and len(pub.sent) == 2


def test_mind_publisher_finish_without_subscribers_reads_nothing():
    bridge, pub = MindPort(), Publisher()
    mind = MindPublisher(bridge, pub, '/r1/rason_mas', 0.5, lambda: 7, RuntimeError, Log())
    mind.finish(timeout=5.0, poll=0)
    assert not hasattr(bridge, 'pending') and pub.sent == []


# ---- log pump ----------------------------------------------------------------------------

@pytest.mark.parametrize('java_level, name', [(1000, 'error'), (900, 'warn'), (800, 'info'), (700, 'debug'),
                                              (300, 'debug'), (1200, 'error')])
def test_java_log_levels(java_level, name):
    assert level_name(java_level) == name


class Batch(object):
    """A LogQueue.Batch: levels, code-point ends and the lines' text."""

    def __init__(self, lines):
        self._levels = [level for level, _ in lines]
        self._ends = list(itertools.accumulate(len(text) for _, text in lines))
        self._text = ''.join(text for _, text in lines)

    def levels(self):
        return self._levels

    def ends(self):
        return self._ends

    def text(self):
        return self._text


class Lines(object):
    def __init__(self, lines, dropped=0):
        self.queued = list(lines)
        self.dropped = dropped

    def drainBatch(self, most):
        taken, self.queued = self.queued[:most], self.queued[most:]
        return Batch(taken)

    def takeDropped(self):
        dropped, self.dropped = self.dropped, 0
        return dropped


def test_batch_lines_cuts_the_text_at_the_ends_with_each_level():
    assert batch_lines(Batch([(800, '[bob] hé😀'), (1000, ''), (700, 'x')])) == [
        ('info', '[bob] hé😀'), ('error', ''), ('debug', 'x')]


def test_log_pump_writes_every_line_on_close_after_detaching():
    written, detached = [], []
    lines = Lines([(800, '[bob] hello')] * 600 + [(1000, 'jason failed')], dropped=2)
    LogPump(lines, written.extend).close(lambda: detached.append(True))
    assert detached == [True]
    assert written[0] == ('info', '[bob] hello') and written[-1] == ('error', 'jason failed')
    assert len([w for w in written if w[0] != 'warn']) == 601
    assert ('warn', '2 log lines of the agents were dropped: they came faster than rosout took them') in written
