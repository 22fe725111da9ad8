"""Unit tests of rason_decomposer.node.Decomposer with rospy's topics replaced by fakes
(no ROS master needed): the protocol as seen on jason/event."""
import threading

import pytest
import rospy

from rason_decomposer import node
from rason_msgs.msg import Action, Event


class FakePublisher(object):
    def __init__(self, topic, data_class, queue_size=None):
        self.topic, self.published, self.connections = topic, [], 1
        self.connections_when_published = []

    def publish(self, msg):
        self.connections_when_published.append(self.connections)
        self.published.append(msg)

    def get_num_connections(self):
        return self.connections


class FakeConnection(object):
    def __init__(self):
        self.header = {'callerid': '/bridge', 'topic': 'jason/action'}


class FakeSubscriber(object):
    def __init__(self, topic, data_class, callback, queue_size=None):
        self.topic, self.callback = topic, callback
        self.impl = type('Impl', (), {})()
        self.impl.connections = []


class FakeTimer(object):
    def __init__(self, period, callback):
        self.period, self.callback, self.stopped = period, callback, False

    def shutdown(self):
        self.stopped = True


@pytest.fixture
def ros(monkeypatch):
    made = {'shutdown_hooks': []}

    def publisher(*args, **kwargs):
        made['pub'] = FakePublisher(*args, **kwargs)
        return made['pub']

    def subscriber(*args, **kwargs):
        made['sub'] = FakeSubscriber(*args, **kwargs)
        return made['sub']

    def timer(*args, **kwargs):
        made['timer'] = FakeTimer(*args, **kwargs)
        return made['timer']

    monkeypatch.setattr(rospy, 'Publisher', publisher)
    monkeypatch.setattr(rospy, 'Subscriber', subscriber)
    monkeypatch.setattr(rospy, 'Timer', timer)
    monkeypatch.setattr(rospy, 'on_shutdown', made['shutdown_hooks'].append)
    monkeypatch.setattr(rospy, 'is_shutdown', lambda: False)
    return made


class Handler(object):
    """Records the calls; by default starts the work and leaves it running."""

    def __init__(self):
        self.calls = []
        self.decomposer = None
        self.start = lambda action: None
        self.cancel = lambda action, reason: None

    def on_start(self, action):
        self.calls.append(('start', action.agent, action.action_id, action.name, list(action.parameters)))
        self.start(action)

    def on_cancel(self, action, reason):
        self.calls.append(('cancel', action.agent, action.action_id, reason))
        self.cancel(action, reason)


@pytest.fixture
def setup(ros):
    handler = Handler()
    dec = node.Decomposer(['move', 'turn'], handler.on_start, handler.on_cancel, listener_wait=2.0)
    handler.decomposer = dec
    link = FakeConnection()
    ros['sub'].impl.connections = [link]

    def send(agent, action_id, action, parameters=(), header=link.header):
        msg = Action(agent=agent, action_id=action_id, action=action, parameters=list(parameters))
        msg._connection_header = header
        ros['sub'].callback(msg)

    return dec, handler, send, ros, link


def events(ros):
    return [(e.agent, e.event_type, list(e.parameters)) for e in ros['pub'].published]


def started(agent, action_id):
    return (agent, Event.ACTION_STARTED, [str(action_id)])


def feedback(agent, action_id, result):
    return (agent, Event.ACTION_FEEDBACK, [result, str(action_id)])


def test_topics_are_relative_and_the_watch_runs_at_10_hz(setup):
    _, _, _, ros, _ = setup
    assert ros['pub'].topic == 'jason/event' and ros['sub'].topic == 'jason/action'
    assert ros['timer'].period.to_sec() == pytest.approx(0.1)


def test_own_action_is_started_then_answered_once(setup):
    dec, handler, send, ros, _ = setup
    send('a', 4, 'move', ['1'])
    assert handler.calls == [('start', 'a', 4, 'move', ['1'])]
    assert events(ros) == [started('a', 4)]
    [action] = dec.held()
    assert dec.finish(action, Event.OK) is True
    assert dec.finish(action, Event.NO_PROGRESS) is False
    assert dec.refuse(action, Event.BAD_PARAMETERS) is False
    assert events(ros) == [started('a', 4), feedback('a', 4, Event.OK)]
    assert dec.held() == [] and not dec.holds(action)


def test_other_actions_are_dropped_silently(setup):
    dec, handler, send, ros, _ = setup
    send('a', 1, 'beep', [])
    send('a', 2, 'report_diagnosis', ['none'])
    assert handler.calls == [] and events(ros) == [] and dec.held() == []


def test_only_the_served_agents_actions_are_taken(ros):
    handler = Handler()
    node.Decomposer('move', handler.on_start, handler.on_cancel, agents=['a'])
    for agent in ('b', 'a'):
        ros['sub'].callback(Action(agent=agent, action_id=1, action='move', parameters=['1']))
    assert handler.calls == [('start', 'a', 1, 'move', ['1'])]
    assert events(ros) == [started('a', 1)]


def test_cancel_is_not_an_action_name(ros):
    with pytest.raises(ValueError):
        node.Decomposer([Action.CANCEL], lambda a: None, lambda a, r: None)


def test_refuse_from_on_start_answers_without_action_started(setup):
    dec, handler, send, ros, _ = setup
    handler.start = lambda action: dec.refuse(action, Event.BAD_PARAMETERS)
    send('a', 9, 'move', ['abc'])
    assert events(ros) == [feedback('a', 9, Event.BAD_PARAMETERS)]
    assert dec.held() == []


def test_finish_inside_on_start_goes_out_after_action_started(setup):
    dec, handler, send, ros, _ = setup
    handler.start = lambda action: dec.finish(action, Event.OK)
    send('a', 2, 'turn', ['0'])
    assert events(ros) == [started('a', 2), feedback('a', 2, Event.OK)]


def test_on_start_that_raises_answers_decomposer_error(setup):
    _, handler, send, ros, _ = setup

    def broken(action):
        raise RuntimeError('boom')

    handler.start = broken
    send('a', 3, 'move', ['1'])
    assert events(ros) == [started('a', 3), feedback('a', 3, node.DECOMPOSER_ERROR)]


def test_the_same_id_again_while_held_is_dropped(setup):
    dec, handler, send, ros, _ = setup
    send('a', 1, 'move', ['1'])
    send('a', 1, 'move', ['2'])
    assert len(handler.calls) == 1 and events(ros) == [started('a', 1)]


def test_cancel_stops_the_action_and_answers_cancelled_once(setup):
    dec, handler, send, ros, _ = setup
    send('a', 1, 'move', ['1'])
    send('a', 2, 'move', ['1'])
    [first, second] = dec.held()
    send('a', 2, Action.CANCEL, [Event.DROPPED])
    assert handler.calls[-1] == ('cancel', 'a', 2, Event.DROPPED)
    assert events(ros)[-1] == feedback('a', 2, Event.CANCELLED)
    assert dec.held() == [first]
    # the handler's own end of the cancelled action is not a second answer
    assert dec.finish(second, Event.OK) is False
    send('a', 2, Action.CANCEL, [Event.DROPPED])        # already cancelled: ignored
    assert [c for c in handler.calls if c[0] == 'cancel'] == [('cancel', 'a', 2, Event.DROPPED)]
    assert events(ros).count(feedback('a', 2, Event.CANCELLED)) == 1
    assert dec.finish(first, Event.OK) is True


def test_cancel_of_an_unknown_or_finished_action_is_ignored(setup):
    dec, handler, send, ros, _ = setup
    send('a', 1, 'move', ['1'])
    dec.finish(dec.held()[0], Event.OK)
    before = events(ros)
    send('a', 1, Action.CANCEL, [Event.TIMEOUT])
    send('a', 77, Action.CANCEL, [Event.TIMEOUT])
    send('b', 0, Action.CANCEL, [Event.RESTART])
    assert events(ros) == before
    assert all(c[0] == 'start' for c in handler.calls)


def test_cancel_zero_stops_every_action_of_that_agent_only(setup):
    dec, handler, send, ros, _ = setup
    send('a', 1, 'move', ['1'])
    send('b', 1, 'move', ['1'])
    send('a', 2, 'turn', ['90'])
    send('a', 0, Action.CANCEL, [Event.RESTART])
    assert [c for c in handler.calls if c[0] == 'cancel'] == [
        ('cancel', 'a', 1, Event.RESTART), ('cancel', 'a', 2, Event.RESTART)]
    assert events(ros)[-2:] == [feedback('a', 1, Event.CANCELLED), feedback('a', 2, Event.CANCELLED)]
    assert [(h.agent, h.action_id) for h in dec.held()] == [('b', 1)]


def test_a_cancel_without_reason_still_cancels(setup):
    dec, handler, send, ros, _ = setup
    send('a', 1, 'move', ['1'])
    send('a', 1, Action.CANCEL, [])
    assert handler.calls[-1] == ('cancel', 'a', 1, '')
    assert events(ros)[-1] == feedback('a', 1, Event.CANCELLED)


def test_lost_link_stops_its_actions_at_the_next_watch(setup):
    dec, handler, send, ros, link = setup
    other = FakeConnection()
    ros['sub'].impl.connections = [link, other]
    send('a', 1, 'move', ['1'])
    send('b', 5, 'move', ['1'], header=other.header)
    ros['timer'].callback(None)
    assert len(dec.held()) == 2          # both links there: nothing stopped
    # the connection of 'a' goes; a new connection with an equal header is not it
    ros['sub'].impl.connections = [other, FakeConnection()]
    ros['timer'].callback(None)
    assert handler.calls[-1] == ('cancel', 'a', 1, node.REQUESTER_LOST)
    assert events(ros)[-1] == feedback('a', 1, Event.CANCELLED)
    assert [(h.agent, h.action_id) for h in dec.held()] == [('b', 5)]
    ros['timer'].callback(None)
    assert events(ros).count(feedback('a', 1, Event.CANCELLED)) == 1


def test_action_without_connection_header_is_never_lost(setup):
    dec, handler, send, ros, _ = setup
    send('a', 1, 'move', ['1'], header=None)
    ros['sub'].impl.connections = []
    ros['timer'].callback(None)
    assert len(dec.held()) == 1


def test_a_closing_subscriber_is_not_a_lost_link(setup):
    dec, handler, send, ros, _ = setup
    send('a', 1, 'move', ['1'])
    ros['sub'].impl.connections = None
    ros['timer'].callback(None)
    assert len(dec.held()) == 1


def test_shutdown_stops_and_answers_every_held_action(setup):
    dec, handler, send, ros, _ = setup
    send('a', 1, 'move', ['1'])
    send('b', 2, 'turn', ['1'])
    for hook in ros['shutdown_hooks']:
        hook()
    assert ros['timer'].stopped
    assert [c for c in handler.calls if c[0] == 'cancel'] == [
        ('cancel', 'a', 1, Event.SHUTDOWN), ('cancel', 'b', 2, Event.SHUTDOWN)]
    assert events(ros)[-2:] == [feedback('a', 1, Event.SHUTDOWN), feedback('b', 2, Event.SHUTDOWN)]


def run_with_deadline(function, seconds=5.0):
    """Runs function on a thread; fails (instead of hanging) on a deadlock."""
    errors = []

    def body():
        try:
            function()
        except BaseException as e:  # noqa: B902 - reported below
            errors.append(e)

    thread = threading.Thread(target=body, daemon=True)
    thread.start()
    thread.join(seconds)
    assert not thread.is_alive(), 'deadlock'
    if errors:
        raise errors[0]


def test_callbacks_may_call_the_decomposer_back(setup):
    # no lock of the decomposer is held while on_start/on_cancel run
    dec, handler, send, ros, _ = setup
    seen = []
    handler.start = lambda action: seen.append(('holds', dec.holds(action), len(dec.held())))
    handler.cancel = lambda action, reason: seen.append(('finish', dec.finish(action, Event.OK)))
    run_with_deadline(lambda: send('a', 1, 'move', ['1']))
    run_with_deadline(lambda: send('a', 1, Action.CANCEL, [Event.DROPPED]))
    assert seen == [('holds', True, 1), ('finish', False)]
    assert events(ros) == [started('a', 1), feedback('a', 1, Event.CANCELLED)]


def test_a_cancel_during_on_start_waits_for_it(setup):
    dec, handler, send, ros, _ = setup
    in_start, release = threading.Event(), threading.Event()

    def slow_start(action):
        in_start.set()
        assert release.wait(5.0)

    handler.start = slow_start
    starter = threading.Thread(target=send, args=('a', 1, 'move', ['1']), daemon=True)
    starter.start()
    assert in_start.wait(5.0)
    # the cancel arrives from another thread (e.g. the link watch) while on_start runs
    ros['sub'].impl.connections = []
    run_with_deadline(lambda: ros['timer'].callback(None))
    assert [c[0] for c in handler.calls] == ['start']     # on_cancel not before on_start ended
    assert events(ros) == []
    release.set()
    starter.join(5.0)
    assert not starter.is_alive()
    assert handler.calls[-1] == ('cancel', 'a', 1, node.REQUESTER_LOST)
    assert events(ros) == [started('a', 1), feedback('a', 1, Event.CANCELLED)]


def test_the_first_event_waits_for_a_listener_of_jason_event(setup):
    dec, handler, send, ros, _ = setup
    ros['pub'].connections = 0
    timer = threading.Timer(0.3, lambda: setattr(ros['pub'], 'connections', 1))
    timer.start()
    try:
        send('a', 1, 'move', ['1'])
    finally:
        timer.cancel()
    assert events(ros) == [started('a', 1)]
    assert ros['pub'].connections_when_published == [1]
