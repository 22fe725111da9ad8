"""Unit tests of motion_decomp.node with rospy's topics and timers replaced by fakes (no ROS
master needed): what goes out on cmd_vel and jason/event, cancels included."""
import pytest
import rospy
from nav_msgs.msg import Odometry

from motion_decomp import node
from rason_msgs.msg import Action, Event


class Fakes(object):
    def __init__(self):
        self.published = []           # (topic, message), in publishing order
        self.subscribers = {}
        self.timers = []
        self.shutdown_hooks = []
        self.now = 0.0


@pytest.fixture
def ros(monkeypatch):
    fakes = Fakes()

    class Publisher(object):
        def __init__(self, topic, data_class, queue_size=None):
            self.topic = topic

        def publish(self, msg):
            fakes.published.append((self.topic, msg))

        def get_num_connections(self):
            return 1

    class Subscriber(object):
        def __init__(self, topic, data_class, callback, queue_size=None):
            self.callback = callback
            self.impl = type('Impl', (), {'connections': []})()
            fakes.subscribers[topic] = self

    class Timer(object):
        def __init__(self, period, callback):
            self.period, self.callback, self.stopped = period.to_sec(), callback, False
            fakes.timers.append(self)

        def shutdown(self):
            self.stopped = True

    monkeypatch.setattr(rospy, 'Publisher', Publisher)
    monkeypatch.setattr(rospy, 'Subscriber', Subscriber)
    monkeypatch.setattr(rospy, 'Timer', Timer)
    monkeypatch.setattr(rospy, 'on_shutdown', fakes.shutdown_hooks.append)
    monkeypatch.setattr(rospy, 'is_shutdown', lambda: False)
    monkeypatch.setattr(rospy, 'get_time', lambda: fakes.now)
    return fakes


@pytest.fixture
def robot(ros):
    decomp = node.MotionDecompNode({}, rate=20.0, agents=())
    control = next(t for t in ros.timers if t.period == pytest.approx(0.05))
    pose = [0.0]

    def send(agent, action_id, action, parameters):
        ros.subscribers['jason/action'].callback(
            Action(agent=agent, action_id=action_id, action=action, parameters=parameters))

    def tick(dx=0.0):
        pose[0] += dx
        odom = Odometry()
        odom.pose.pose.position.x = pose[0]
        odom.pose.pose.orientation.w = 1.0
        ros.subscribers['odom'].callback(odom)
        ros.now += 0.05
        control.callback(None)

    return decomp, send, tick


def out(ros, since=0):
    """What was published since index ``since``, as comparable tuples."""
    result = []
    for topic, msg in ros.published[since:]:
        if topic == 'cmd_vel':
            result.append(('cmd_vel', msg.linear.x, msg.angular.z))
        else:
            result.append((topic, msg.agent, msg.event_type, list(msg.parameters)))
    return result


def test_cancel_of_the_running_motion_commands_zero_at_once_and_the_next_starts_at_the_next_tick(ros, robot):
    _, send, tick = robot
    send('a', 1, 'move', ['1'])
    send('a', 2, 'turn', ['90'])
    tick()
    tick(0.01)
    assert out(ros)[-1] == ('cmd_vel', 0.2, 0.0)
    mark = len(ros.published)
    send('a', 1, Action.CANCEL, [Event.DROPPED])      # no tick in between
    assert out(ros, mark) == [('cmd_vel', 0.0, 0.0),
                              ('jason/event', 'a', Event.ACTION_FEEDBACK, [Event.CANCELLED, '1'])]
    tick()
    assert out(ros)[-1] == ('cmd_vel', 0.0, -0.5)      # the turn runs


def test_cancel_of_a_queued_motion_leaves_the_running_one_alone(ros, robot):
    _, send, tick = robot
    send('a', 1, 'move', ['0.1'])
    send('a', 2, 'move', ['5'])
    tick()
    mark = len(ros.published)
    send('a', 2, Action.CANCEL, [Event.DROPPED])
    assert out(ros, mark) == [('jason/event', 'a', Event.ACTION_FEEDBACK, [Event.CANCELLED, '2'])]
    for _ in range(20):
        tick(0.01)
    events = [o for o in out(ros, mark) if o[0] == 'jason/event']
    assert events == [('jason/event', 'a', Event.ACTION_FEEDBACK, [Event.CANCELLED, '2']),
                      ('jason/event', 'a', Event.ACTION_FEEDBACK, [Event.OK, '1'])]
    # after the move ended nothing else was driven: idle publishes nothing
    assert out(ros)[-2:] == [('cmd_vel', 0.0, 0.0),
                             ('jason/event', 'a', Event.ACTION_FEEDBACK, [Event.OK, '1'])]


def test_started_then_one_feedback_and_bad_parameters_at_once(ros, robot):
    _, send, tick = robot
    send('a', 1, 'move', ['abc'])
    send('a', 2, 'move', ['0'])
    send('a', 3, 'say', ['hi'])                      # someone else's
    tick()
    tick()
    assert [o for o in out(ros) if o[0] == 'jason/event'] == [
        ('jason/event', 'a', Event.ACTION_FEEDBACK, [Event.BAD_PARAMETERS, '1']),
        ('jason/event', 'a', Event.ACTION_STARTED, ['2']),
        ('jason/event', 'a', Event.ACTION_FEEDBACK, [Event.OK, '2'])]


def test_shutdown_stops_the_robot_and_answers_every_motion(ros, robot):
    _, send, tick = robot
    send('a', 1, 'move', ['1'])
    send('b', 2, 'turn', ['1'])
    tick()
    mark = len(ros.published)
    for hook in ros.shutdown_hooks:
        hook()
    assert all(t.stopped for t in ros.timers)
    assert out(ros, mark) == [
        ('cmd_vel', 0.0, 0.0),
        ('jason/event', 'a', Event.ACTION_FEEDBACK, [Event.SHUTDOWN, '1']),
        ('jason/event', 'b', Event.ACTION_FEEDBACK, [Event.SHUTDOWN, '2'])]


def test_agents_filter(ros):
    node.MotionDecompNode({}, rate=20.0, agents={'a'})
    for agent in ('b', 'a'):
        ros.subscribers['jason/action'].callback(
            Action(agent=agent, action_id=1, action='move', parameters=['1']))
    assert [(m.agent, m.event_type) for t, m in ros.published if t == 'jason/event'] == [
        ('a', Event.ACTION_STARTED)]
