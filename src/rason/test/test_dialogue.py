from rason_tools.dialogue import format_diagnosis, format_message, format_mission


def test_broadcast_is_shown_as_all():
    assert format_message('faulty', '', 'achieve', 'helpme') == 'faulty -> all: achieve helpme'


def test_addressed_message_and_reply():
    assert format_message('helper', 'faulty', 'tell', 'found(faulty)') == \
        'helper -> faulty: tell found(faulty)'
    assert format_message('b', 'a', 'tell', 'x(1)', in_reply_to='7').endswith('x(1) (reply)')


def test_a_receipt_is_not_part_of_the_dialogue():
    # the receiving process's acknowledgement (Java's rason.messaging.Receipts.PERFORMATIVE)
    assert format_message('faulty', 'helper', 'rason_receipt', 'delivered', in_reply_to='12') is None
    assert format_message('faulty', 'helper', 'achieve', 'thanks') == 'faulty -> helper: achieve thanks'


def test_diagnosis_names_agent_component_and_evidence():
    line = format_diagnosis('/faulty', [('agent', 'faulty'), ('component', 'odometry'),
                                        ('evidence', 'seen moving')])
    assert line == 'DIAGNOSIS faulty: odometry (seen moving)'


def test_diagnosis_without_agent_uses_the_namespace():
    assert format_diagnosis('/faulty', [('component', 'none')]) == 'DIAGNOSIS faulty: none'


def test_status_without_component_is_not_a_diagnosis():
    assert format_diagnosis('/faulty', [('agent', 'faulty')]) is None


def test_a_completed_mission_says_by_whom_and_how():
    line = format_mission('/faulty', [('agent', 'faulty'), ('completed', 'true'), ('by', 'helper'),
                                      ('recovery', 'delegate'), ('diagnosis', 'both_actuators')])
    assert line == 'MISSION faulty: completed by helper (recovery delegate after both_actuators)'


def test_a_failed_mission_says_so_and_a_status_without_outcome_prints_nothing():
    line = format_mission('/faulty', [('completed', 'false'), ('recovery', 'none'),
                                      ('diagnosis', 'undiagnosed')])
    assert line == 'MISSION faulty: not completed (recovery none after undiagnosed)'
    assert format_mission('/faulty', [('agent', 'faulty')]) is None
