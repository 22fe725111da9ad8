"""The agent's report actions and the harness's percepts."""
import pytest

from rason_bench import protocol


def test_reports_parse_from_action_parameters():
    assert protocol.parse_report('cycle', ['3', '20000', '412.5']) == protocol.Cycle(3, 20000, 412.5)
    assert protocol.parse_report('rtt', ['4', '17', '0.85']) == protocol.RoundTrip(4, 17, 0.85)
    assert protocol.parse_report('seen', ['5', '2', '1.25']) == protocol.Seen(5, 2, 1.25)
    assert protocol.parse_report('took_back', ['6', '3', '8123456.789']) == protocol.TookBack(6, 3, 8123456.789)


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
    assert protocol.go_move('preempt', 7, 0) == 'go_move(preempt,7,0)'
    assert protocol.take_back('preempt', 7, 0) == 'take_back(preempt,7,0)'
