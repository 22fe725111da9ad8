from rason_tools.dialogue import format_diagnosis, format_message


def test_broadcast_is_shown_as_all():
    assert format_message('faulty', '', 'achieve', 'helpme') == 'faulty -> all: achieve helpme'


def test_addressed_message_and_reply():
    assert format_message('helper', 'faulty', 'tell', 'found(faulty)') == \
        'helper -> faulty: tell found(faulty)'
    assert format_message('b', 'a', 'tell', 'x(1)', in_reply_to='7').endswith('x(1) (reply)')


def test_diagnosis_names_agent_component_and_evidence():
    line = format_diagnosis('/faulty', [('agent', 'faulty'), ('component', 'odometry'),
                                        ('evidence', 'seen moving')])
    assert line == 'DIAGNOSIS faulty: odometry (seen moving)'


def test_diagnosis_without_agent_uses_the_namespace():
    assert format_diagnosis('/faulty', [('component', 'none')]) == 'DIAGNOSIS faulty: none'


def test_status_without_component_is_not_a_diagnosis():
    assert format_diagnosis('/faulty', [('agent', 'faulty')]) is None
