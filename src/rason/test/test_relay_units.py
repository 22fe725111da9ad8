"""The topic relay without ROS or a broker (rason_relay): sealing, what a receiver drops, the
replay gate, the parameters, the fleet key file as rason_mas reads it, and how the broker
connection is tuned."""
import socket

import pytest

from rason_bridge.fleet_key import generate_key, key_id, parse_keys
from rason_relay.envelope import Refused, ReplayGate, open_sealed, seal
from rason_relay.node import TCP_THIN_LINEAR_TIMEOUTS, _tune_for_thin_stream
from rason_relay.relay import Inbound, Outbound
from rason_relay.settings import SettingsError, broker_topic, parse_settings

KEY = generate_key()
OTHER = generate_key()
KEYS = parse_keys(KEY)
TOPIC = '/helper/located/faulty'


def settings(**params):
    return parse_settings(dict({'receive': [TOPIC]}, **params), lambda n: n if n.startswith('/') else '/faulty/' + n,
                          'faulty')


def sealed(payload=b'\x01\x02pose', seq=1, sent=100.0, boot='b1', key=None, topic=TOPIC, sender='helper'):
    return seal(key or KEYS[0], sender, topic, 'geometry_msgs/PoseStamped', 'md5', boot, seq, sent, payload)


def test_a_sealed_message_opens_with_its_header_and_bytes():
    header, payload = open_sealed(dict(KEYS), sealed(), 65536)
    assert payload == b'\x01\x02pose'
    assert header == {'from': 'helper', 'topic': TOPIC, 'type': 'geometry_msgs/PoseStamped', 'md5': 'md5',
                      'boot': 'b1', 'seq': 1, 'sent': 100.0, 'key': KEYS[0][0]}


@pytest.mark.parametrize('spoil, reason', [
    (lambda d: d[:-1] + bytes([d[-1] ^ 1]), 'tag that does not match'),
    (lambda d: d.replace(b'pose', b'posf'), 'tag that does not match'),
    (lambda d: d.replace(b'"seq":1', b'"seq":9'), 'tag that does not match'),
    (lambda d: b'XXXX' + d[4:], 'not a relayed ROS message'),
    (lambda d: d[:10], 'not a relayed ROS message'),
    (lambda d: d + bytes(70000), 'over the 65536 allowed'),
    (lambda d: d[:4] + b'\x02' + d[5:], 'version 2'),
])
def test_altered_truncated_or_huge_messages_are_refused_with_a_reason(spoil, reason):
    with pytest.raises(Refused, match=reason):
        open_sealed(dict(KEYS), spoil(sealed()), 65536)


def test_a_message_signed_with_another_fleet_key_names_the_mismatch():
    with pytest.raises(Refused, match='key files differ'):
        open_sealed(dict(KEYS), sealed(key=parse_keys(OTHER)[0]), 65536)


def test_every_key_of_the_file_verifies_and_the_first_signs():
    keys = parse_keys('# rotating\n%s\n\n%s\n' % (OTHER, KEY))
    assert [k for k, _ in keys] == [key_id(OTHER.encode()), key_id(KEY.encode())]
    header, _ = open_sealed(dict(keys), sealed(), 65536)
    assert header['key'] == key_id(KEY.encode())


def test_key_files_are_read_as_rason_mas_reads_them():
    with pytest.raises(ValueError, match='too short'):
        parse_keys('short')
    with pytest.raises(ValueError, match='no key'):
        parse_keys('# nothing\n\n')
    with pytest.raises(ValueError, match='two keys'):
        parse_keys('%s\n%s\n' % (KEY, KEY))
    # the id rason_mas's FleetKeys.idOf gives the same key (run in jshell)
    assert key_id(b'k' * 32) == '5e318f8c'


def test_the_gate_lets_each_message_through_once_and_in_order():
    gate = ReplayGate(max_age=5.0)
    gate.admit({'from': 'h', 'topic': TOPIC, 'boot': 'b1', 'seq': 1, 'sent': 100.0}, now=100.5)
    gate.admit({'from': 'h', 'topic': TOPIC, 'boot': 'b1', 'seq': 3, 'sent': 100.2}, now=100.5)
    for seq in (3, 2):
        with pytest.raises(Refused, match='seen before or out of order'):
            gate.admit({'from': 'h', 'topic': TOPIC, 'boot': 'b1', 'seq': seq, 'sent': 100.3}, now=100.5)
    # another topic or sender has its own sequence
    gate.admit({'from': 'h', 'topic': '/other', 'boot': 'b1', 'seq': 1, 'sent': 100.3}, now=100.5)
    gate.admit({'from': 'r2', 'topic': TOPIC, 'boot': 'b9', 'seq': 1, 'sent': 100.3}, now=100.5)


def test_a_restarted_sender_is_accepted_but_its_earlier_run_cannot_be_replayed():
    gate = ReplayGate(max_age=5.0)
    gate.admit({'from': 'h', 'topic': TOPIC, 'boot': 'old', 'seq': 50, 'sent': 100.0}, now=100.0)
    gate.admit({'from': 'h', 'topic': TOPIC, 'boot': 'new', 'seq': 1, 'sent': 101.0}, now=101.0)
    with pytest.raises(Refused, match='earlier run'):
        gate.admit({'from': 'h', 'topic': TOPIC, 'boot': 'old', 'seq': 51, 'sent': 100.5}, now=101.0)


def test_messages_older_or_newer_than_max_age_are_stale():
    gate = ReplayGate(max_age=5.0)
    for sent in (94.9, 105.1):
        with pytest.raises(Refused, match='over 5.0 s'):
            gate.admit({'from': 'h', 'topic': TOPIC, 'boot': 'b', 'seq': 1, 'sent': sent}, now=100.0)


def test_the_gate_remembers_a_bounded_number_of_streams():
    gate = ReplayGate(max_age=5.0, max_streams=2)
    for sender in ('a', 'b', 'c'):
        gate.admit({'from': sender, 'topic': TOPIC, 'boot': 'b', 'seq': 1, 'sent': 100.0}, now=100.0)
    assert len(gate._streams) == 2
    with pytest.raises(Refused):
        gate.admit({'from': 'c', 'topic': TOPIC, 'boot': 'b', 'seq': 1, 'sent': 100.0}, now=100.0)


def test_outbound_counts_up_and_inbound_accepts_it_once():
    sender = parse_settings({'send': ['located/faulty']}, lambda n: '/helper/' + n, 'helper')
    out = Outbound(sender, KEYS[0])
    first = out.sealed(TOPIC, 'geometry_msgs/PoseStamped', 'md5', b'one', 100.0)
    second = out.sealed(TOPIC, 'geometry_msgs/PoseStamped', 'md5', b'two', 100.1)
    assert first[0] == second[0] == 'rason/topics/helper/located/faulty'
    inbound = Inbound(settings(), KEYS)
    assert inbound.broker_topics == ['rason/topics/helper/located/faulty']
    assert inbound.accepted(*second, now=100.2)[1] == b'two'
    with pytest.raises(Refused, match='out of order'):
        inbound.accepted(*first, now=100.2)
    with pytest.raises(Refused, match='out of order'):
        inbound.accepted(*second, now=100.2)


def test_outbound_sends_at_most_max_rate_a_second_per_topic():
    out = Outbound(parse_settings({'send': ['/a', '/b'], 'max_rate': 5}, str, 'helper'), KEYS[0])
    sent = [t for t in (0.0, 0.1, 0.19, 0.2, 0.35, 0.41) if out.sealed('/a', 'T', 'md5', b'', t) is not None]
    assert sent == [0.0, 0.2, 0.41]
    assert out.sealed('/b', 'T', 'md5', b'', 0.41) is not None       # each topic its own period
    assert out.sealed('/a', 'T', 'md5', b'', 0.1) is not None        # the clock went back: send


def test_inbound_refuses_a_message_moved_to_another_topic_or_not_received_here():
    inbound = Inbound(settings(receive=[TOPIC, '/helper/odom']), KEYS)
    moved = sealed(topic='/helper/odom')
    with pytest.raises(Refused, match='sealed for /helper/odom'):
        inbound.accepted(broker_topic('rason/', TOPIC), moved, now=100.0)
    with pytest.raises(Refused, match='does not receive'):
        inbound.accepted('rason/topics/elsewhere', sealed(), now=100.0)


def test_settings_resolve_names_and_refuse_what_cannot_work():
    s = settings(mqtt_url='ssl://broker.lan', mqtt_prefix='fleet7', send=['odom'])
    assert (s.host, s.port, s.tls, s.prefix, s.send, s.receive) == ('broker.lan', 8883, True, 'fleet7/',
                                                                    ('/faulty/odom',), (TOPIC,))
    assert settings(receive='/a /b').receive == ('/a', '/b')
    for params, message in (({'mqtt_url': 'http://x'}, 'tcp://HOST:PORT'),
                            ({'mqtt_url': 'tcp://x:99999'}, 'port'),
                            ({'send': [TOPIC]}, 'echo its own'),
                            ({'receive': ['/a/#']}, 'cannot name a broker topic'),
                            ({'receive': 5}, 'list of ROS topic names'),
                            ({'max_age': 0}, 'max_age'),
                            ({'max_rate': -1}, 'max_rate'),
                            ({'mqtt_prefix': 'a+b'}, 'mqtt_prefix')):
        with pytest.raises(SettingsError, match=message):
            settings(**params)


def test_the_broker_connection_is_tuned_for_a_thin_stream_under_a_loss_based_congestion_control():
    with socket.socket() as sock:
        _tune_for_thin_stream(sock)
        assert sock.getsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY)
        assert sock.getsockopt(socket.IPPROTO_TCP, TCP_THIN_LINEAR_TIMEOUTS) == 1
        # BBR (this machine's default) would make Linux ignore the thin-stream timeouts
        assert sock.getsockopt(socket.IPPROTO_TCP, socket.TCP_CONGESTION, 16).rstrip(b'\0') != b'bbr'
