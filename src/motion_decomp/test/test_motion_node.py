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
            self.topic, self.unregistered = topic, False
            fakes.subscribers[topic] = self

        def unregister(self):
            self.unregistered = True

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
    monkeypatch.setattr(rospy, 'logwarn_throttle', lambda *args, **kwargs: None)   # needs ROS time
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
    """What was published on cmd_vel and jason/event since index ``since``, as comparable
    tuples (odom_commanded has tests of its own)."""
    result = []
    for topic, msg in ros.published[since:]:
        if topic == 'cmd_vel':
            result.append(('cmd_vel', msg.linear.x, msg.angular.z))
        elif topic == 'jason/event':
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


# ---------------------------------------------------------------- issue 15: settings, guided pose, odom_commanded

def commanded(ros, since=0):
    """The odom_commanded messages published since index ``since``."""
    return [msg for topic, msg in ros.published[since:] if topic == 'odom_commanded']


def guided_pose(x, y, stamp):
    from geometry_msgs.msg import PoseStamped
    msg = PoseStamped()
    msg.header.stamp = rospy.Time.from_sec(stamp)
    msg.pose.position.x, msg.pose.position.y = x, y
    msg.pose.orientation.w = 1.0
    return msg


def test_a_setting_is_started_at_once_and_answered_ok_at_the_next_tick_without_a_twist(ros, robot):
    _, send, tick = robot
    send('a', 1, 'compensate', ['left', '2'])
    assert out(ros) == [('jason/event', 'a', Event.ACTION_STARTED, ['1'])]
    tick()
    assert out(ros) == [('jason/event', 'a', Event.ACTION_STARTED, ['1']),
                        ('jason/event', 'a', Event.ACTION_FEEDBACK, [Event.OK, '1'])]
    send('a', 2, 'compensate', ['up', '2'])
    send('a', 3, 'pose_source', ['gps'])
    assert out(ros)[-2:] == [('jason/event', 'a', Event.ACTION_FEEDBACK, [Event.BAD_PARAMETERS, '2']),
                             ('jason/event', 'a', Event.ACTION_FEEDBACK, [Event.BAD_PARAMETERS, '3'])]


def test_odom_commanded_integrates_the_twists_at_every_tick_and_comes_at_1_hz_when_idle(ros, robot):
    _, send, tick = robot
    tick()                                   # idle: the first message, the zero pose
    first = commanded(ros)
    assert len(first) == 1 and first[0].pose.pose.position.x == 0.0
    assert (first[0].header.frame_id, first[0].child_frame_id) == ('odom_commanded', 'base_footprint')
    send('a', 1, 'move', ['0.1'])
    mark = len(ros.published)
    ticks = 0
    while not any(o[0] == 'jason/event' and o[2] == Event.ACTION_FEEDBACK for o in out(ros, mark)):
        tick(0.01)                           # the base goes 0.01 m per tick (0.2 m/s)
        ticks += 1
    during = commanded(ros, mark)
    assert len(during) == ticks              # one per control tick while the move runs
    assert [m.header.stamp.to_sec() for m in during] == pytest.approx(
        [0.05 * (i + 2) for i in range(ticks)])
    # 0.2 m/s commanded from the first tick to the end's zero twist
    assert during[-1].pose.pose.position.x == pytest.approx(0.2 * 0.05 * (ticks - 1))
    assert during[-2].twist.twist.linear.x == 0.2 and during[-1].twist.twist.linear.x == 0.0
    mark = len(ros.published)
    for _ in range(41):                      # 2.05 s idle
        tick()
    idle = commanded(ros, mark)
    assert len(idle) == 2                    # at 1 Hz
    assert idle[1].header.stamp.to_sec() - idle[0].header.stamp.to_sec() == pytest.approx(1.0)
    assert idle[1].pose.pose.position.x == during[-1].pose.pose.position.x


def test_a_cancel_stops_the_commanded_odometry_too(ros, robot):
    _, send, tick = robot
    send('a', 1, 'move', ['5'])
    for _ in range(10):
        tick(0.01)
    mark = len(ros.published)
    send('a', 1, Action.CANCEL, [Event.DROPPED])
    stopped = ros.now
    at_cancel = commanded(ros, mark)         # reported at once, like a tick that stops
    assert [(m.header.stamp.to_sec(), m.twist.twist.linear.x) for m in at_cancel] == [
        (pytest.approx(stopped), 0.0)]
    for _ in range(30):
        tick()
    last = commanded(ros)[-1]
    assert last.header.stamp.to_sec() > stopped + 0.9     # a second later, idle
    assert last.pose.pose.position.x == pytest.approx(0.2 * 0.05 * 9)     # ticks 1..9 at 0.2 m/s


def test_guided_poses_drive_after_pose_source_guided_while_fresh(ros):
    node.MotionDecompNode({}, rate=20.0)
    control = next(t for t in ros.timers if t.period == pytest.approx(0.05))
    action = ros.subscribers['jason/action'].callback
    guided = ros.subscribers['guided_pose'].callback
    ros.subscribers['odom'].callback(Odometry())          # the odometry stays at 0 (frozen)
    ros.now = 10.0
    action(Action(agent='a', action_id=1, action='pose_source', parameters=['guided']))
    action(Action(agent='a', action_id=2, action='move', parameters=['0.05']))
    x = 0.0
    for i in range(40):
        ros.now += 0.05
        if i % 2 == 0:                       # a guided pose every 0.1 s, 0.1 s old, moving
            guided(guided_pose(x, 0.0, ros.now - 0.1))
            x += 0.01
        control.callback(None)
    events = [o for o in out(ros) if o[0] == 'jason/event' and o[2] == Event.ACTION_FEEDBACK]
    assert events == [('jason/event', 'a', Event.ACTION_FEEDBACK, [Event.OK, '1']),
                      ('jason/event', 'a', Event.ACTION_FEEDBACK, [Event.OK, '2'])]
    assert ('cmd_vel', 0.1, 0.0) in out(ros)            # the guided linear speed


def test_pose_source_guided_with_a_topic_drives_on_that_topic_only_until_odom(ros):
    node.MotionDecompNode({}, rate=20.0)
    control = next(t for t in ros.timers if t.period == pytest.approx(0.05))
    action = ros.subscribers['jason/action'].callback
    own = ros.subscribers['guided_pose'].callback
    ros.subscribers['odom'].callback(Odometry())
    ros.now = 10.0
    action(Action(agent='a', action_id=1, action='pose_source', parameters=['guided', '/r1/located/r4']))
    control.callback(None)                               # the setting takes effect: subscribed
    watcher = ros.subscribers['/r1/located/r4']
    action(Action(agent='a', action_id=2, action='move', parameters=['1']))
    own(guided_pose(0.0, 0.0, ros.now))                  # the node's own topic is not used now
    ros.now += 0.05
    control.callback(None)
    assert out(ros)[-1] == ('cmd_vel', 0.0, 0.0)
    watcher.callback(guided_pose(0.0, 0.0, ros.now))
    ros.now += 0.05
    control.callback(None)
    assert out(ros)[-1] == ('cmd_vel', 0.1, 0.0)
    action(Action(agent='a', action_id=3, action='pose_source', parameters=['odom']))
    action(Action(agent='a', action_id=2, action=Action.CANCEL, parameters=[Event.DROPPED]))
    for _ in range(3):
        ros.now += 0.05
        control.callback(None)
    assert watcher.unregistered


def test_a_stale_or_broken_guided_pose_is_no_pose_and_a_zero_stamp_counts_as_received(ros):
    node.MotionDecompNode({}, rate=20.0)
    control = next(t for t in ros.timers if t.period == pytest.approx(0.05))
    action = ros.subscribers['jason/action'].callback
    guided = ros.subscribers['guided_pose'].callback
    action(Action(agent='a', action_id=1, action='pose_source', parameters=['guided']))
    action(Action(agent='a', action_id=2, action='move', parameters=['1']))
    ros.now = 100.0
    control.callback(None)                               # the setting takes effect
    guided(guided_pose(0.0, 0.0, 99.0))                  # 1 s old
    ros.now += 0.05
    control.callback(None)
    assert out(ros)[-1] == ('cmd_vel', 0.0, 0.0)
    guided(guided_pose(0.0, 0.0, 0.0))                   # zero stamp: "now"
    ros.now += 0.05
    control.callback(None)
    assert out(ros)[-1] == ('cmd_vel', 0.1, 0.0)
    guided(guided_pose(float('nan'), 0.0, ros.now))      # no pose any more
    ros.now += 0.05
    control.callback(None)
    assert out(ros)[-1] == ('cmd_vel', 0.0, 0.0)


def test_actions_left_out_by_the_actions_parameter_are_not_taken(ros):
    assert node.action_filter('move, turn compensate pose_source') == ('move', 'turn', 'compensate',
                                                                        'pose_source')
    assert node.action_filter(['goto', 'move']) == ('move', 'goto')
    for bad in ('', [], 'move fly'):
        with pytest.raises(ValueError):
            node.action_filter(bad)
    node.MotionDecompNode({}, rate=20.0, actions=('move', 'turn'))
    for action_id, action, parameters in ((1, 'goto', ['1', '1']), (2, 'move', ['1'])):
        ros.subscribers['jason/action'].callback(
            Action(agent='a', action_id=action_id, action=action, parameters=parameters))
    assert [(m.event_type, list(m.parameters)) for t, m in ros.published if t == 'jason/event'] == [
        (Event.ACTION_STARTED, ['2'])]
