"""rason_simlink without a ROS master: framing, the topic checks, presence, the protocol over a
socket pair, the socket file."""
import os
import socket
import stat
import threading
import time

import pytest

from rason_simlink import framing, presence, sockets, topics
from rason_simlink.connection import Connection
from rason_simlink.reporting import Backoff, RateLimited
from rason_simlink.session import Session

MD5 = {t.type: 'md5-of-' + t.type for t in topics.TOPICS}


def records_of(*chunks, max_body=framing.MAX_BODY):
    reader = framing.RecordReader(max_body)
    out = []
    for chunk in chunks:
        out += reader.feed(chunk)
    return out, reader.pending


# --- framing ---

def test_records_come_whole_however_the_stream_is_split():
    head, payload = framing.data_parts(7, b'\x00\x01' * 1000)
    stream = framing.json_record(framing.HELLO, {'side': 'robot'}) + head + payload
    whole, _ = records_of(stream)
    for size in (1, 2, 5, 6, 7, 333):
        chunks = [stream[i:i + size] for i in range(0, len(stream), size)]
        assert records_of(*chunks) == (whole, 0)
    assert framing.decode_json(whole[0][1]) == {'side': 'robot'}
    assert whole[1][0] == framing.DATA
    assert framing.decode_data(whole[1][1]) == (7, b'\x00\x01' * 1000)


def test_a_partial_record_waits_for_the_rest():
    head, payload = framing.data_parts(1, b'abcdef')
    records, pending = records_of(head, payload[:3])
    assert records == [] and pending == len(head) + 3
    reader = framing.RecordReader()
    reader.feed(head + payload[:3])
    assert [framing.decode_data(b) for _, b in reader.feed(payload[3:])] == [(1, b'abcdef')]
    assert reader.pending == 0


def test_an_empty_payload_is_a_record():
    head, payload = framing.data_parts(3, b'')
    assert [framing.decode_data(b) for _, b in records_of(head + payload)[0]] == [(3, b'')]


def test_a_record_over_the_cap_is_refused_from_its_header_alone():
    with pytest.raises(framing.FramingError, match='over the 100-byte cap'):
        records_of(framing.HEADER.pack(101, framing.DATA), max_body=100)
    with pytest.raises(framing.FramingError, match='cap'):
        framing.data_parts(0, b'x' * 200, max_body=100)
    assert records_of(framing.HEADER.pack(100, framing.DATA) + b'x' * 100, max_body=100)[1] == 0


def test_what_is_not_a_record_is_an_error():
    with pytest.raises(framing.FramingError, match='unknown record kind'):
        records_of(b'GET / HTTP/1.1\r\n')
    with pytest.raises(framing.FramingError, match='not JSON'):
        framing.decode_json(b'{nope')
    with pytest.raises(framing.FramingError, match='not a JSON object'):
        framing.decode_json(b'[1, 2]')
    with pytest.raises(framing.FramingError, match='no channel'):
        framing.decode_data(b'\x01')


# --- topics ---

def test_the_sides_send_what_the_other_receives():
    world_sends = {t.name for t in topics.sent_by('world')}
    assert world_sends == {t.name for t in topics.received_by('robot')}
    assert {'odom', 'true_pose', '/clock', '/tf', '/tf_static'} <= world_sends
    assert set(topics.CAMERA_TOPICS) <= world_sends
    assert {t.name for t in topics.sent_by('robot')} == \
        {'cmd_vel', 'set_pose'} | set(topics.ACK_TOPICS)
    assert {t.name for t in topics.TOPICS if t.on_demand} == set(topics.CAMERA_TOPICS)
    assert {t.name for t in topics.TOPICS if t.ack} == set(topics.ACK_TOPICS)
    assert [t.name for t in topics.TOPICS if t.latched] == ['/tf_static']


def test_an_announcement_is_checked_against_this_sides_table_and_definitions():
    def announce(topic, type_=None, md5=None):
        type_ = type_ or topics.BY_NAME[topic].type
        return {'channel': 0, 'topic': topic, 'type': type_, 'md5': md5 or MD5[type_]}

    assert topics.check_announcement('robot', announce('odom'), MD5.get) is None
    assert topics.check_announcement('world', announce('cmd_vel'), MD5.get) is None
    assert 'not one the world side receives' in \
        topics.check_announcement('world', announce('odom'), MD5.get)
    assert 'not one the robot side receives' in \
        topics.check_announcement('robot', {'topic': '/rosout'}, MD5.get)
    assert "'std_msgs/String' over the link, 'geometry_msgs/Twist' expected" in \
        topics.check_announcement('world', announce('cmd_vel', 'std_msgs/String', 'x'), MD5.get)
    wrong_md5 = topics.check_announcement('robot', announce('odom', md5='old'), MD5.get)
    assert 'nav_msgs/Odometry differs between the two sides (md5 old over the link' in wrong_md5
    assert 'not built on the robot side' in \
        topics.check_announcement('robot', announce('odom'), lambda t: None)


def test_a_sender_of_another_type_is_not_relayed():
    twist = topics.BY_NAME['cmd_vel']
    assert topics.check_sender(twist, twist.type, 'm', 'm') is None
    assert 'std_msgs/String (md5 s)' in topics.check_sender(twist, 'std_msgs/String', 's', 'm')
    assert topics.check_sender(twist, twist.type, 'other', 'm') is not None


# --- presence ---

def test_the_robot_side_reports_only_changes_and_all_after_a_drop():
    robot = presence.RobotPresence()
    cameras = {name: 0 for name in topics.CAMERA_TOPICS}
    acks = {name: 0 for name in topics.ACK_TOPICS}
    assert robot.update(cameras, acks) == {'subscribed': [], 'publishing': []}
    assert robot.update(cameras, acks) is None
    cameras['camera/depth_registered/image_raw'] = 2
    acks['robots_seen'] = 1
    assert robot.update(cameras, acks) == {'subscribed': ['camera/depth_registered/image_raw'],
                                           'publishing': ['robots_seen']}
    assert robot.update(cameras, acks) is None
    robot.forget()
    assert robot.update(cameras, acks) is not None


def test_the_world_side_mirrors_presence_and_a_lost_link_wants_nothing():
    world = presence.WorldPresence()
    sub, unsub, adv, unadv, unknown = world.apply(
        {'subscribed': ['camera/rgb/image_raw'], 'publishing': ['robots_seen', 'odom_filtered']})
    assert (sub, unsub, adv, unadv, unknown) == (
        {'camera/rgb/image_raw'}, set(), {'robots_seen', 'odom_filtered'}, set(), set())
    assert world.apply({'subscribed': ['camera/rgb/image_raw'],
                        'publishing': ['robots_seen']})[:4] == (set(), set(), set(),
                                                                 {'odom_filtered'})
    assert world.link_lost() == (set(), {'camera/rgb/image_raw'}, set(), {'robots_seen'})
    assert world.link_lost() == (set(), set(), set(), set())


def test_the_world_side_ignores_names_that_are_not_mirrored():
    world = presence.WorldPresence()
    sub, _, adv, _, unknown = world.apply({'subscribed': ['odom', 'cmd_vel'],
                                           'publishing': ['cmd_vel', 'robots_seen']})
    assert sub == set() and adv == {'robots_seen'}
    assert unknown == {'odom', 'cmd_vel'}


# --- reporting ---

def test_reports_are_rate_limited_per_key_and_count_what_was_held_back():
    now = [0.0]
    limiter = RateLimited(5.0, clock=lambda: now[0])
    lines = []
    for _ in range(3):
        limiter.report('a', lines.append, 'lost')
    limiter.report('b', lines.append, 'other')
    now[0] = 5.0
    limiter.report('a', lines.append, 'lost')
    assert lines == ['lost', 'other', 'lost (2 more like this since)']


def test_backoff_doubles_to_a_ceiling_and_resets():
    backoff = Backoff(0.1, 0.5)
    assert [backoff.next_wait() for _ in range(5)] == [0.1, 0.2, 0.4, 0.5, 0.5]
    backoff.reset()
    assert backoff.next_wait() == 0.1


# --- the protocol over a socket pair ---

class Side:
    """One end: a Connection and a Session, recording what it publishes and logs."""

    def __init__(self, sock, side, robot, md5=MD5):
        self.published, self.presence, self.errors = [], [], []
        self.closed_reason = threading.Event()
        self.reasons = []
        self.changed = threading.Condition()

        def closed(reason):
            self.reasons.append(reason)
            self.closed_reason.set()

        self.conn = Connection(sock, lambda k, b: self.session.handle(k, b), closed,
                               max_queued_bytes=1 << 20)
        self.ready = []
        self.session = Session(side, robot, self.conn, md5.get, self._publish, self._presence,
                               log_error=self._error, log_info=lambda text: None,
                               on_ready=self.ready.append)
        self.session.start()
        self.conn.start()

    def _note(self, target, value):
        with self.changed:
            target.append(value)
            self.changed.notify_all()

    def _publish(self, topic, payload):
        self._note(self.published, (topic, payload))

    def _presence(self, report):
        self._note(self.presence, report)

    def _error(self, text):
        self._note(self.errors, text)

    def wait(self, condition, timeout=5.0):
        deadline = time.monotonic() + timeout
        with self.changed:
            while not condition():
                assert time.monotonic() < deadline, 'condition not met in %g s' % timeout
                self.changed.wait(0.02)   # also polls what changes without a notify


@pytest.fixture
def pair():
    made = []

    def make(world_robot='rover', robot_robot='rover', world_md5=MD5, robot_md5=MD5):
        a, b = socket.socketpair(socket.AF_UNIX, socket.SOCK_STREAM)
        world = Side(a, 'world', world_robot, world_md5)
        robot = Side(b, 'robot', robot_robot, robot_md5)
        made.extend([world, robot])
        return world, robot

    yield make
    for side in made:
        side.conn.close('test over')


def test_messages_cross_both_ways_in_order(pair):
    world, robot = pair()
    world.wait(lambda: world.session.peer_ready)
    robot.wait(lambda: robot.session.peer_ready)
    frame = bytes(range(256)) * 4000   # a camera frame's worth
    for i in range(20):
        assert world.session.send('odom', b'odom %d' % i)
    assert world.session.send('camera/rgb/image_raw', frame)
    assert robot.session.send('cmd_vel', b'twist')
    robot.session.send_presence({'subscribed': ['camera/rgb/image_raw'], 'publishing': []})
    robot.wait(lambda: len(robot.published) == 21)
    assert robot.published[:20] == [('odom', b'odom %d' % i) for i in range(20)]
    assert robot.published[20] == ('camera/rgb/image_raw', frame)
    world.wait(lambda: world.published == [('cmd_vel', b'twist')] and world.presence)
    assert world.presence == [{'subscribed': ['camera/rgb/image_raw'], 'publishing': []}]


def test_a_robot_side_of_another_robot_is_refused_with_the_reason(pair):
    world, robot = pair(world_robot='helper', robot_robot='rover')
    assert world.closed_reason.wait(5) and robot.closed_reason.wait(5)
    robot.wait(lambda: robot.errors)
    assert any("paths are crossed" in e for e in world.errors + robot.errors)
    assert world.ready == [] and robot.ready == []   # never put in place of a working link


def test_an_accepted_peer_is_reported_ready_once(pair):
    world, robot = pair()
    world.wait(lambda: world.ready and robot.ready)
    assert world.ready == [world.session] and robot.ready == [robot.session]


def test_a_presence_report_before_the_hello_is_refused():
    a, b = socket.socketpair(socket.AF_UNIX, socket.SOCK_STREAM)
    world = Side(a, 'world', 'rover')
    b.sendall(framing.json_record(framing.PRESENCE, {'subscribed': [], 'publishing': []}))
    assert world.closed_reason.wait(5)
    assert world.presence == [] and any('before the HELLO' in e for e in world.errors)
    b.close()


def test_two_robot_sides_refuse_each_other():
    a, b = socket.socketpair(socket.AF_UNIX, socket.SOCK_STREAM)
    one, two = Side(a, 'robot', 'rover'), Side(b, 'robot', 'rover')
    assert one.closed_reason.wait(5) and two.closed_reason.wait(5)
    assert any("one world side and one robot side" in e for e in one.errors + two.errors)


def test_a_type_whose_definition_differs_is_not_published_and_says_why(pair):
    old = dict(MD5, **{'nav_msgs/Odometry': 'old-odometry'})
    world, robot = pair(world_md5=old)
    world.wait(lambda: world.session.peer_ready)
    world.session.send('odom', b'1')
    world.session.send('odom', b'2')
    world.session.send('true_pose', b'pose')
    robot.wait(lambda: robot.published == [('true_pose', b'pose')])
    assert any('nav_msgs/Odometry differs between the two sides' in e for e in robot.errors)
    assert not robot.closed_reason.is_set()


def test_garbage_on_the_socket_drops_the_link_with_the_reason():
    a, b = socket.socketpair(socket.AF_UNIX, socket.SOCK_STREAM)
    world = Side(a, 'world', 'rover')
    b.sendall(b'\xff' * 64)
    assert world.closed_reason.wait(5)
    assert 'unknown record kind' in world.reasons[0]
    b.close()


def test_a_peer_that_goes_away_closes_the_link_once():
    a, b = socket.socketpair(socket.AF_UNIX, socket.SOCK_STREAM)
    world = Side(a, 'world', 'rover')
    b.close()
    assert world.closed_reason.wait(5)
    assert len(world.reasons) == 1 and 'the peer closed the link' in world.reasons[0]
    assert world.session.send('odom', b'late') is False
    world.conn.close('again')
    assert len(world.reasons) == 1


def test_data_is_dropped_not_queued_without_bound_when_the_peer_does_not_read():
    a, b = socket.socketpair(socket.AF_UNIX, socket.SOCK_STREAM)
    conn = Connection(a, lambda k, body: None, lambda reason: None, max_queued_bytes=1 << 20,
                      send_timeout=30)
    conn.start()
    frame = b'x' * (256 << 10)
    sent = [conn.send_data(0, frame) for _ in range(200)]   # 50 MB nobody reads
    assert sent.count(True) < 200 and conn.dropped == sent.count(False)
    conn.close('test over')
    b.close()


# --- the socket file ---

def test_the_socket_file_is_private_replaces_a_stale_one_and_goes_on_close(tmp_path):
    path = str(tmp_path / 'links' / 'rover.sock')
    listener = sockets.listen(path)
    assert stat.S_IMODE(os.stat(path).st_mode) == 0o600
    assert stat.S_IMODE(os.stat(os.path.dirname(path)).st_mode) == 0o700
    with pytest.raises(ValueError, match='already listens'):
        sockets.listen(path)
    client = sockets.connect(path)
    assert client is not None
    client.close()
    listener.sock.close()              # killed: the file stays behind, nobody answers
    assert os.path.exists(path)
    assert sockets.connect(path) is None
    listener = sockets.listen(path)
    listener.close()
    assert not os.path.exists(path)
    assert sockets.connect(path) is None


def test_a_socket_path_that_cannot_be_is_refused_clearly(tmp_path):
    with pytest.raises(ValueError, match='at most 107'):
        sockets.listen('/tmp/' + 'x' * 120)
    with pytest.raises(ValueError, match='empty'):
        sockets.check_path('')
    plain = tmp_path / 'file.sock'
    plain.write_text('not a socket')
    with pytest.raises(ValueError, match='not a socket'):
        sockets.listen(str(plain))


def test_the_default_path_is_under_ros_home():
    assert sockets.default_path('rover', '/ros') == '/ros/rason/sim_link/rover.sock'
