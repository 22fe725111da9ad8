"""rason_mas exits with an error when another node takes its name, not for an ordinary shutdown."""
from rason_bridge.exits import exit_for_shutdown


def test_a_node_that_took_our_name_is_an_error_saying_so():
    code, why = exit_for_shutdown('external shutdown request from [/master]: '
                                  '[[/robot1/rason_mas] Reason: new node registered with same name]')
    assert code == 1
    assert 'another node registered' in why and '/robot1/rason_mas' in why


def test_ordinary_shutdowns_are_not_errors():
    for reason in ['signal-2', 'external shutdown request from [/rosnode]: user request', '', None,
                   'an agent ran .stopMAS']:
        assert exit_for_shutdown(reason) == (0, '')
