"""Unit tests of rason_decomposer.book (no ROS master needed)."""
import pytest

from rason_decomposer.book import ActionBook, Feedback, HeldAction
from rason_msgs.msg import Event


def link():
    """A requester: like rospy's connection header, a fresh dict per connection."""
    return {'callerid': '/bridge'}


def test_take_holds_the_action_with_its_fields():
    book, req = ActionBook(), link()
    held = book.take('a', 7, 'move', ['1'], req)
    assert isinstance(held, HeldAction)
    assert (held.agent, held.action_id, held.name, held.parameters) == ('a', 7, 'move', ['1'])
    assert held.requester is req and held.key == ('a', 7)
    assert ('a', 7) in book and ('a', 8) not in book and ('b', 7) not in book
    assert book.get('a', 7) is held and book.get('a', 8) is None
    assert book.holds(held) and len(book) == 1


def test_the_same_id_of_the_same_agent_is_not_taken_twice_but_other_agents_may_use_it():
    book = ActionBook()
    book.take('a', 1, 'move', ['1'])
    with pytest.raises(ValueError):
        book.take('a', 1, 'turn', ['9'])
    book.take('b', 1, 'move', ['1'])
    assert [h.key for h in book.actions()] == [('a', 1), ('b', 1)]


def test_id_zero_is_not_an_action():
    with pytest.raises(ValueError):
        ActionBook().take('a', 0, 'move', ['1'])


def test_finish_answers_exactly_once():
    book = ActionBook()
    held = book.take('a', 3, 'move', ['1'])
    assert book.finish('a', 3, Event.OK) == Feedback('a', 3, Event.OK)
    assert book.finish('a', 3, Event.OK) is None
    assert book.finish('a', 3, Event.NO_PROGRESS) is None
    assert not book.holds(held) and len(book) == 0


def test_finish_of_an_unknown_id_answers_nothing():
    book = ActionBook()
    book.take('a', 3, 'move', ['1'])
    assert book.finish('a', 4, Event.OK) is None
    assert book.finish('b', 3, Event.OK) is None
    assert ('a', 3) in book


def test_finish_of_an_old_action_does_not_end_a_new_one_with_the_same_id():
    book = ActionBook()
    old = book.take('a', 1, 'move', ['1'])
    assert book.cancel('a', 1) == [old]
    new = book.take('a', 1, 'move', ['2'])       # e.g. a restarted agent counts from 1 again
    assert book.finish('a', 1, Event.OK, held=old) is None
    assert book.holds(new)
    assert book.finish('a', 1, Event.OK, held=new) == Feedback('a', 1, Event.OK)


def test_cancel_one_id_takes_out_only_that_action():
    book = ActionBook()
    one = book.take('a', 1, 'move', ['1'])
    two = book.take('a', 2, 'turn', ['90'])
    other = book.take('b', 2, 'move', ['1'])
    assert book.cancel('a', 2) == [two]
    assert book.actions() == [one, other]
    # a cancelled action is answered by the canceller, not by a late finish
    assert book.finish('a', 2, Event.OK) is None


def test_cancel_zero_takes_out_every_action_of_the_agent_oldest_first():
    book = ActionBook()
    a1 = book.take('a', 5, 'move', ['1'])
    b1 = book.take('b', 1, 'move', ['1'])
    a2 = book.take('a', 2, 'turn', ['90'])
    assert book.cancel('a', 0) == [a1, a2]
    assert book.actions() == [b1]
    assert book.cancel('a', 0) == []


def test_cancel_of_an_unknown_or_finished_id_stops_nothing():
    book = ActionBook()
    book.take('a', 1, 'move', ['1'])
    book.finish('a', 1, Event.OK)
    assert book.cancel('a', 1) == []
    assert book.cancel('a', 99) == []
    assert book.cancel('nobody', 0) == []


def test_lost_compares_requesters_by_identity_not_equality():
    book = ActionBook()
    first, second = link(), link()
    assert first == second and first is not second
    a = book.take('a', 1, 'move', ['1'], first)
    b = book.take('b', 1, 'move', ['1'], second)
    # only an equal copy of the first link is live: its own object is gone
    assert book.lost([second, dict(first)]) == [a]
    assert book.actions() == [b]
    assert book.lost([second]) == []
    assert book.lost([]) == [b]
    assert len(book) == 0


def test_lost_keeps_actions_that_cannot_be_watched_and_ends_each_only_once():
    book = ActionBook()
    unwatched = book.take('a', 1, 'move', ['1'], None)
    gone = book.take('a', 2, 'move', ['1'], link())
    assert book.lost([]) == [gone]
    assert book.lost([]) == []
    assert book.actions() == [unwatched]
    assert book.finish('a', 2, Event.OK) is None


def test_actions_filters_by_agent_and_clear_empties_the_book():
    book = ActionBook()
    a = book.take('a', 1, 'move', ['1'])
    b = book.take('b', 1, 'move', ['1'])
    assert book.actions('a') == [a] and book.actions('c') == []
    assert book.clear() == [a, b]
    assert len(book) == 0 and book.finish('a', 1, Event.OK) is None


def test_action_ids_given_as_text_are_the_same_action():
    book = ActionBook()
    held = book.take('a', '4', 'move', ['1'])
    assert held.action_id == 4 and ('a', '4') in book
    assert book.cancel('a', '4') == [held]
