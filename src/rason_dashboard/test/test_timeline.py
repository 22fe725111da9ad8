"""The dashboard's timeline: the view at any time, out-of-order input, bounds (no ROS)."""
from rason_dashboard import timeline as tl
from rason_dashboard.timeline import Timeline


def robot(mas_id, stamp, belief, started=None):
    actions = [] if started is None else [{'id': 1, 'action': 'turn(10)', 'started': started, 'held': False}]
    return {'mas_id': mas_id, 'stamp': stamp, 'agents': [{
        'name': 'a', 'cycle': 1, 'stamp': stamp, 'beliefs': [belief], 'goals': [], 'intentions': [],
        'actions': actions, 'events': [], 'messages': [], 'omitted': 0}]}


def msg(line):
    return {'sender': 'a', 'receiver': 'b', 'performative': 'tell', 'content': line, 'sender_mas': '/a/m',
            'line': line}


def test_view_at_a_time_shows_each_robot_as_it_was_then():
    t = Timeline('replay')
    t.add_mind(10.0, robot('/r1', 10.0, 'early'))
    t.add_mind(20.0, robot('/r1', 20.0, 'late'))
    t.add_mind(15.0, robot('/r2', 15.0, 'r2'))
    assert [r['mas_id'] for r in t.view(12.0)['robots']] == ['/r1']
    assert t.view(12.0)['robots'][0]['agents'][0]['beliefs'] == ['early']
    assert t.view(19.9)['robots'][1]['agents'][0]['beliefs'] == ['r2']
    assert t.view(None)['robots'][0]['agents'][0]['beliefs'] == ['late']
    assert t.view(5.0)['robots'] == []
    assert t.view()['span'] == [10.0, 20.0] and t.view()['time'] == 20.0


def test_input_out_of_order_is_put_in_time_order():
    t = Timeline()
    t.add_message(3.0, msg('c'))
    t.add_message(1.0, msg('a'))
    t.add_message(2.0, msg('b'))
    assert [m['line'] for m in t.view()['messages']] == ['a', 'b', 'c']
    assert [m['line'] for m in t.view(2.5)['messages']] == ['a', 'b']
    assert t.view(2.5)['messages'][-1]['time'] == 2.0


def test_statuses_by_name_the_newest_at_the_time():
    t = Timeline()
    t.add_status(1.0, {'name': 'rason/diagnosis', 'level': 'OK', 'message': 'none'})
    t.add_status(4.0, {'name': 'rason/diagnosis', 'level': 'WARN', 'message': 'left'})
    t.add_status(2.0, {'name': 'rason/mission', 'level': 'OK', 'message': 'completed'})
    assert [s['message'] for s in t.view(3.0)['statuses']] == ['none', 'completed']
    assert [s['message'] for s in t.view()['statuses']] == ['left', 'completed']


def test_pending_action_age_at_the_time_viewed():
    t = Timeline()
    t.add_mind(10.0, robot('/r', 10.0, 'x', started=9.0))
    assert t.view(12.5)['robots'][0]['agents'][0]['actions'][0]['age'] == 3.5
    assert t.view()['robots'][0]['agents'][0]['actions'][0]['age'] == 1.0  # at its own stamp


def test_bounded_oldest_dropped(monkeypatch):
    monkeypatch.setattr(tl, 'MAX_MESSAGES', 3)
    monkeypatch.setattr(tl, 'VIEW_MESSAGES', 2)
    t = Timeline()
    for i in range(5):
        t.add_message(float(i), msg(str(i)))
    assert [m['line'] for m in t.view()['messages']] == ['3', '4']
    assert t.span() == (2.0, 4.0)


def test_empty():
    v = Timeline().view()
    assert (v['robots'], v['messages'], v['statuses'], v['span'], v['time']) == ([], [], [], None, None)
