"""When a fleet connection stuck after a partition is reset and when a lost subscriber
connection is made again (rason_bridge.repair_rules; no ROS)."""
import socket
import struct

from rason_bridge.repair_rules import (GRACE, TCP_ESTABLISHED, TCP_INFO_SIZE, WINDOW, PeerReturns, Relinks,
                                       TcpInfo, parse_tcp_info, stuck)


def test_tcp_info_of_a_real_idle_connection():
    with socket.socket() as server:
        server.bind(('127.0.0.1', 0))
        server.listen(1)
        with socket.create_connection(server.getsockname()) as client:
            accepted, _ = server.accept()
            with accepted:
                info = parse_tcp_info(client.getsockopt(socket.IPPROTO_TCP, socket.TCP_INFO, TCP_INFO_SIZE))
    assert info.state == TCP_ESTABLISHED
    assert info.unacked == 0 and info.retransmits == 0
    assert 0 <= info.last_ack_recv < 5


def test_tcp_info_fields_at_their_offsets():
    raw = struct.pack('=8B13I', 1, 4, 3, 0, 5, 0, 0, 0, *([0] * 4 + [7] + [0] * 7 + [2500]))
    assert parse_tcp_info(raw) == TcpInfo(state=1, retransmits=3, backoff=5, unacked=7, last_ack_recv=2.5)


def _info(unacked=3, last_ack_recv=8.0, state=TCP_ESTABLISHED):
    return TcpInfo(state=state, retransmits=4, backoff=4, unacked=unacked, last_ack_recv=last_ack_recv)


def test_stuck_when_the_peer_is_back_and_nothing_was_acknowledged_since():
    assert stuck(_info(), back_for=GRACE)
    assert stuck(_info(last_ack_recv=1.0), back_for=0.9)


def test_not_stuck_when_acknowledged_since_the_peer_came_back():
    assert not stuck(_info(last_ack_recv=0.4), back_for=0.9)


def test_not_stuck_with_nothing_unacknowledged_or_not_established():
    assert not stuck(_info(unacked=0), back_for=1.0)
    assert not stuck(_info(state=4), back_for=1.0)


def test_the_peer_gets_a_grace_after_it_came_back_and_the_rule_ends_after_the_window():
    assert not stuck(_info(last_ack_recv=60.0), back_for=GRACE - 0.1)
    assert not stuck(_info(last_ack_recv=60.0), back_for=WINDOW + 0.1)
    assert not stuck(_info(), back_for=None)


def test_a_peer_heard_without_an_absence_never_came_back():
    peers = PeerReturns(away_after=2.0)
    for t in (0.0, 0.5, 1.0, 2.9, 4.8):  # gaps under 2 s: presence never lost
        peers.heard('/r2/rason_mas', t)
    assert peers.back_for('/r2/rason_mas', 5.0) is None
    assert peers.back_for('/r3/rason_mas', 5.0) is None


def test_a_peer_heard_again_after_an_absence_is_back_until_it_goes_silent():
    peers = PeerReturns(away_after=2.0)
    peers.heard('/r2/rason_mas', 10.0)
    peers.heard('/r2/rason_mas', 16.0)  # 6 s of silence: a partition
    peers.heard('/r2/rason_mas', 16.5)
    assert peers.back_for('/r2/rason_mas', 17.0) == 1.0
    assert peers.back_for('/r2/rason_mas', 18.6) is None  # silent again for 2 s


def test_a_lost_publisher_is_tried_at_once_then_at_doubling_intervals_up_to_the_longest():
    relinks = Relinks(longest=2.0)
    assert relinks.due('/m', ['uri1', 'uri2'], 0.0) == []
    times = []
    now = 1.0
    while now < 9.0:
        for uri in relinks.due('/m', ['uri2'], now):
            assert uri == 'uri1'
            relinks.started('/m', uri, now)
            relinks.ended('/m', uri, gone=False)
            times.append(now)
        now = round(now + 0.1, 1)
    assert times == [1.0, 1.5, 2.5, 4.5, 6.5, 8.5]


def test_no_second_attempt_while_one_is_under_way():
    relinks = Relinks()
    relinks.due('/m', ['uri1'], 0.0)
    assert relinks.due('/m', [], 1.0) == ['uri1']
    relinks.started('/m', 'uri1', 1.0)
    assert relinks.due('/m', [], 5.0) == []
    relinks.ended('/m', 'uri1', gone=False)
    assert relinks.due('/m', [], 5.0) == ['uri1']


def test_a_publisher_linked_again_starts_over_and_one_that_refused_is_forgotten():
    relinks = Relinks()
    relinks.due('/m', ['uri1', 'uri2'], 0.0)
    for uri in relinks.due('/m', [], 1.0):
        relinks.started('/m', uri, 1.0)
    relinks.ended('/m', 'uri1', gone=False)
    relinks.ended('/m', 'uri2', gone=True)
    assert relinks.due('/m', ['uri1'], 1.2) == []
    assert relinks.due('/m', [], 1.3) == ['uri1']  # lost again: tried at once
    assert relinks.due('/other', [], 1.3) == []
