"""The agent's report actions and the harness's percepts."""
import pytest

from rason_bench import protocol


def test_reports_parse_from_action_parameters():
    assert protocol.parse_report('cycle', ['3', '20000', '412.5']) == protocol.Cycle(3, 20000, 412.5)
    assert protocol.parse_report('rtt', ['4', '17', '0.85']) == protocol.RoundTrip(4, 17, 0.85)
    assert protocol.parse_report('seen', ['5', '2', '1.25']) == protocol.Seen(5, 2, 1.25)
    assert protocol.parse_report('took_back', ['6', '3', '8123456.789']) == protocol.TookBack(6, 3, 8123456.789)


def test_new_reports_parse_with_their_types():
    assert protocol.parse_report('react', ['2', '7', '1.2345678912E7']) == protocol.Reacted(2, 7, 12345678.912)
    assert protocol.parse_report('spinning', ['3', '50']) == protocol.Spinning(3, 50)
    assert protocol.parse_report('spun', ['3', '12', '4017']) == protocol.Spun(3, 12, 4017)
    assert protocol.parse_report('ticked', ['4', 'limited', '9', '55.5']) == protocol.Ticked(4, 'limited', 9, 55.5)


@pytest.mark.parametrize('action, parameters', [('spun', ['3', '12', '4017.5']), ('spinning', ['1', 'inf']),
                                                ('ticked', ['4', 'limited', 'x', '1'])])
def test_counts_must_be_whole_numbers(action, parameters):
    with pytest.raises(protocol.BadReport):
        protocol.parse_report(action, parameters)


def test_a_reaction_is_timed_on_the_stamps_clock():
    r = protocol.reaction(protocol.Reacted(2, 7, 1000.0), 1012.5)
    assert r == protocol.Reaction(2, 7, 12.5)


def test_triggers_take_the_sources_in_turn():
    sources = [protocol.trigger_source(seq) for seq in range(2 * protocol.TRIGGER_SOURCES)]
    assert len(set(sources)) == protocol.TRIGGER_SOURCES
    assert sources[:protocol.TRIGGER_SOURCES] == sources[protocol.TRIGGER_SOURCES:]
    assert protocol.CONTROL_SOURCE not in sources


def test_other_actions_are_not_reports():
    assert protocol.parse_report('ping', ['1']) is None
    assert protocol.parse_report('move', ['0.3']) is None
    assert protocol.parse_report('.cancel', ['dropped']) is None


@pytest.mark.parametrize('parameters', [['1', '2'], ['1', '2', '3', '4'], ['a', '2', '3.0']])
def test_malformed_reports_are_refused(parameters):
    with pytest.raises(protocol.BadReport):
        protocol.parse_report('cycle', parameters)


def test_burst_literals_are_new_in_every_message():
    assert protocol.burst(3, 7) == ['perception1(7)', 'perception2(7)', 'perception3(7)']
    assert set(protocol.burst(10, 1)).isdisjoint(protocol.burst(10, 2))


def test_control_percepts_name_agent_run_and_size():
    assert protocol.go_cycle('bench', 4, 20000) == 'go_cycle(bench,4,20000)'
    assert protocol.go_ping('bench2', 5, 100) == 'go_ping(bench2,5,100)'
    assert protocol.stamp(6, 3, 12345.6789) == 'stamp(6,3,12345.679)'
    assert protocol.trigger(6, 3, 12345.6789) == 'trigger(6,3,12345.679)'
    assert protocol.go_spin('bench', 7, 50) == 'go_spin(bench,7,50)'
    assert protocol.stop_spin('bench', 7) == 'stop_spin(bench,7)'
    assert protocol.tick(8, 2) == 'tick(8,2)'
    assert protocol.go_move('preempt', 7, 0) == 'go_move(preempt,7,0)'
    assert protocol.take_back('preempt', 7, 0) == 'take_back(preempt,7,0)'


def test_flood_marks_are_timed_on_the_stamps_clock():
    assert protocol.flood_mark(3, 7, 1234.5) == 'flood_mark(3,7,1234.500)'
    marked = protocol.parse_report('marked', ['3', '7', '1234.5'])
    assert marked == protocol.Marked(3, 7, 1234.5)
    assert protocol.mark_seen(marked, 1240.0) == protocol.MarkSeen(3, 7, 5.5)
    assert protocol.FINAL_MARK == 0  # the marks during a flood count from 1


def test_a_flood_has_a_new_mark_each_period_and_a_final_one():
    from rason_bench.synth import Marks
    marks = Marks(run=4, period=1.0)
    assert marks.current(10.0) == 'flood_mark(4,1,10000.000)'
    assert marks.current(10.9) == 'flood_mark(4,1,10000.000)'  # the same mark for a period
    assert marks.current(11.0) == 'flood_mark(4,2,11000.000)'
    assert marks.final(11.5) == 'flood_mark(4,0,11500.000)'
