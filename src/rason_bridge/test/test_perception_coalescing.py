"""Perception messages coalesced per source (rason_bridge.coalesce): latest list wins,
sources in turn, a bounded table, a summary of what was overtaken."""
import sys
import threading
import time

import pytest

from rason_bridge.coalesce import ADDED, DROPPED, REPLACED, FloodEnd, PerceptionCoalescer


def blocked_in_a_wait(thread, timeout=5.0):
    """Wait until ``thread`` waits on a threading.Condition (a put waiting for room);
    fails after ``timeout`` s."""
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        frame = sys._current_frames().get(thread.ident)
        while frame is not None:
            if frame.f_code is threading.Condition.wait.__code__:
                return
            frame = frame.f_back
        time.sleep(0.001)
    pytest.fail('the thread never waited on a condition')


def test_the_newest_message_of_a_source_wins():
    c = PerceptionCoalescer()
    assert c.put('cam', ['robot(a,1)'], 1) == ADDED
    assert c.put('cam', ['robot(a,2)'], 2) == REPLACED
    assert c.put('cam', [], 3) == REPLACED  # an empty list is a message like any other
    assert c.take(0) == ('cam', [], 3)
    assert c.take(0) is None


def test_sources_are_taken_in_the_order_they_started_waiting():
    c = PerceptionCoalescer()
    c.put('a', ['x(1)'], 1)
    c.put('b', ['y(1)'], 2)
    c.put('a', ['x(2)'], 3)  # keeps a's place: a flooding source cannot push b back
    c.put('c', ['z(1)'], 4)
    assert [c.take(0)[0] for _ in range(3)] == ['a', 'b', 'c']


def test_a_source_taken_waits_again_behind_the_others_of_its_kind():
    c = PerceptionCoalescer()
    for s in 'abc':
        c.put(s, ['x'], 0)
    assert [c.take(0)[0] for _ in range(3)] == ['a', 'b', 'c']  # now all known
    c.put('b', ['y'], 1)
    c.put('a', ['x'], 2)
    c.put('c', ['z'], 3)
    assert [c.take(0)[0] for _ in range(3)] == ['b', 'a', 'c']


def test_known_and_new_sources_take_turns():
    c = PerceptionCoalescer(max_sources=1000)
    for s in ('cam', 'odom'):
        c.put(s, ['x'], 0)
        c.take(0)
    for i in range(500):
        c.put('flood_%d' % i, ['x'], 1)
    c.put('cam', ['x(2)'], 2)
    c.put('odom', ['x(2)'], 3)
    taken = [c.take(0)[0] for _ in range(4)]
    # the robot's own sources do not wait behind hundreds of new names
    assert taken == ['cam', 'flood_0', 'odom', 'flood_1']


def test_a_flooding_known_source_leaves_new_sources_every_other_turn():
    c = PerceptionCoalescer()
    c.put('flood', ['x'], 0)
    c.take(0)
    c.put('new1', ['a'], 1)
    c.put('new2', ['b'], 1)
    order = []
    for i in range(4):
        c.put('flood', ['x(%d)' % i], 2 + i)  # always waiting again
        order.append(c.take(0)[0])
    assert order == ['flood', 'new1', 'flood', 'new2']  # it was new last time


def test_a_source_name_too_long_is_dropped_and_counted():
    c = PerceptionCoalescer(max_source_length=10)
    assert c.put('x' * 11, ['a'], 0) == DROPPED
    assert c.put('x' * 10, ['a'], 0) == ADDED
    assert c.summary() == '1 dropped: source name longer than 10 characters'


def test_a_flood_of_new_sources_is_bounded_and_the_waiting_ones_stay():
    c = PerceptionCoalescer(max_sources=3)
    for s in 'abc':
        assert c.put(s, ['x'], 0) == ADDED
    assert c.put('d', ['x'], 0) == DROPPED
    assert c.put('a', ['x(2)'], 1) == REPLACED  # a waiting source still gets newer messages
    assert c.waiting() == 3
    for i in range(100000):
        c.put('flood_%d' % i, ['x'], i)
    assert c.waiting() == 3
    assert c.take(0) == ('a', ['x(2)'], 1)
    assert c.put('e', ['x'], 2) == ADDED  # room again


def test_a_new_source_waits_for_room_before_it_is_dropped():
    c = PerceptionCoalescer(max_sources=1)
    c.put('a', ['x'], 0)
    outcome = []
    t = threading.Thread(target=lambda: outcome.append(c.put('b', ['y'], 1, wait=10.0)))
    t.start()
    blocked_in_a_wait(t)
    assert outcome == [], 'waiting for room'
    assert c.take(0) == ('a', ['x'], 0)
    t.join(5.0)
    assert outcome == [ADDED]
    assert c.take(0) == ('b', ['y'], 1)
    c.put('a', ['x'], 2)
    t0 = time.monotonic()
    assert c.put('c', ['z'], 3, wait=0.05) == DROPPED
    assert time.monotonic() - t0 >= 0.04


def test_a_waiting_put_joins_its_source_when_another_connection_added_it():
    c = PerceptionCoalescer(max_sources=1)
    c.put('a', ['x'], 0)
    outcome = []
    t = threading.Thread(target=lambda: outcome.append(c.put('b', ['y(2)'], 2, wait=10.0)))
    t.start()
    blocked_in_a_wait(t)
    c.take(0)
    c.put('b', ['y(1)'], 1)  # whichever comes first, the other replaces it: b waits once
    t.join(5.0)
    assert c.waiting() == 1 and c.take(0)[0] == 'b'


def test_closing_releases_a_waiting_put():
    c = PerceptionCoalescer(max_sources=1)
    c.put('a', ['x'], 0)
    outcome = []
    t = threading.Thread(target=lambda: outcome.append(c.put('b', ['y'], 1, wait=10.0)))
    t.start()
    blocked_in_a_wait(t)
    c.close()
    t.join(5.0)
    assert outcome == [DROPPED]


def test_take_waits_for_a_message_and_close_wakes_it():
    c = PerceptionCoalescer()
    got = []
    t = threading.Thread(target=lambda: got.append(c.take(10.0)))
    t.start()
    c.put('a', ['x'], 1)
    t.join(5.0)
    assert got == [('a', ['x'], 1)]
    t = threading.Thread(target=lambda: got.append(c.take(10.0)))
    t.start()
    c.close()
    t.join(5.0)
    assert not t.is_alive() and got[-1] is None
    c.put('b', ['y'], 2)
    assert c.take(0) is None, 'closed: nothing more is handed on'


def test_take_times_out():
    c = PerceptionCoalescer()
    t0 = time.monotonic()
    assert c.take(0.05) is None
    assert time.monotonic() - t0 >= 0.04


def test_the_summary_counts_what_was_overtaken_and_dropped_once():
    c = PerceptionCoalescer(max_sources=2)
    assert c.summary() is None
    for i in range(5):
        c.put('flood', ['x(%d)' % i], i)
    c.put('other', ['y'], 9)
    c.put('third', ['z'], 10)
    line = c.summary()
    assert line.startswith("4 perception messages overtaken by a newer one of their source before the agents "
                           "took them (source 'flood')")
    assert "1 dropped: 2 other sources were waiting (source 'third')" in line
    assert c.summary() is None


def test_the_summary_names_a_few_sources_abbreviated():
    c = PerceptionCoalescer(max_sources=1)
    c.put('x' * 200, [], 0)
    c.put('x' * 200, [], 1)
    for i in range(50):
        c.put('s%d' % i, [], 0)
    line = c.summary()
    assert "(source '%s…')" % ('x' * 60) in line
    assert "'s0', 's1', 's2', 's3', 's4', …" in line
    assert len(line) < 300


@pytest.mark.parametrize('bad', [0, -1])
def test_the_bound_must_be_positive(bad):
    with pytest.raises(ValueError, match='max_sources'):
        PerceptionCoalescer(max_sources=bad)


def test_overtaken_messages_are_counted_for_good():
    c = PerceptionCoalescer()
    for i in range(3):
        c.put('a', [], i)
    c.summary()
    assert c.overtaken() == 2


def test_a_flood_ends_once_after_a_quiet_second():
    end = FloodEnd(quiet=1.0)
    assert not end.ended(0, 0.0), 'nothing overtaken: no flood'
    assert not end.ended(0, 100.0)
    assert not end.ended(50, 100.5)
    assert not end.ended(900, 101.0)  # still overtaking
    assert not end.ended(900, 101.9)
    assert end.ended(900, 102.0)
    assert not end.ended(900, 110.0), 'once per flood'
    assert not end.ended(901, 111.0)
    assert end.ended(901, 112.5)


def test_a_few_overtaken_messages_are_no_flood_when_a_flood_needs_more():
    end = FloodEnd(quiet=1.0, least=100)
    assert not end.ended(30, 10.0)
    assert not end.ended(30, 11.5), 'a node behind for a moment: no flood ended'
    assert not end.ended(31, 20.0)
    assert not end.ended(130, 20.5)  # a hundred more without a quiet second between them
    assert end.ended(130, 21.5)
    assert not end.ended(130, 30.0)
