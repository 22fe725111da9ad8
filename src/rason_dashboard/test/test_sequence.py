"""The messages as a sequence diagram: lanes, rows in time order, arrows, broadcasts (no ROS)."""
from rason_dashboard import sequence as sq
from rason_dashboard.sequence import lanes_of, sequence_layout


def m(sender, receiver, performative, content, time):
    return {'sender': sender, 'receiver': receiver, 'performative': performative, 'content': content,
            'time': time, 'line': '%s -> %s: %s %s' % (sender, receiver, performative, content)}


def test_lanes_are_the_agents_then_anyone_else_named():
    msgs = [m('r9', 'all', 'tell', 'x', 1.0), m('r1', 'gone', 'tell', 'y', 2.0)]
    assert lanes_of(['r1', 'r2'], msgs) == ['r1', 'r2', 'r9', 'gone']
    assert lanes_of(['r1', 'r1'], []) == ['r1']


def test_a_row_per_message_down_the_page_with_its_arrow_between_the_lanes():
    msgs = [m('r4', 'r1', 'achieve', 'callForBids(contract(r4,1),observe(r4))', 1.0),
            m('r1', 'r4', 'tell', 'propose(contract(r4,1),2.1)', 1.2)]
    d = sequence_layout(['r1', 'r2', 'r3', 'r4'], msgs)
    x = {lane['name']: lane['x'] for lane in d['lanes']}
    assert x['r1'] < x['r2'] < x['r3'] < x['r4']
    call, bid = d['rows']
    assert call['y'] < bid['y'] <= d['height']
    assert call['arrows'] == [{'to': 'r1', 'x1': x['r4'], 'x2': x['r1']}] and call['step'] == 'call'
    assert bid['arrows'] == [{'to': 'r4', 'x1': x['r1'], 'x2': x['r4']}] and bid['step'] == 'bid'
    assert call['label'] == 'achieve callForBids(contract(r4,1),observe(r4))'  # fits its arrow: whole
    assert call['title'] == msgs[0]['line'] and call['time'] == 1.0
    assert x['r1'] < bid['label_x'] < x['r4']
    assert d['width'] >= x['r4'] + sq.LANE_WIDTH / 2 and d['left_out'] == 0


def test_a_broadcast_is_one_row_with_an_arrow_to_every_other_lane():
    d = sequence_layout(['faulty', 'helper', 'courier'], [m('faulty', 'all', 'achieve', 'helpme', 0.5)])
    (row,) = d['rows']
    assert [a['to'] for a in row['arrows']] == ['helper', 'courier']
    assert all(a['x1'] == d['lanes'][0]['x'] for a in row['arrows'])
    assert row['label'] == 'achieve helpme' and row['label_x'] > d['lanes'][0]['x']


def test_a_label_between_neighbours_is_cut_shorter_but_stays_readable():
    long = 'callForBids(contract(r4,1),observe(r4))'
    d = sequence_layout(['r1', 'r2', 'r3', 'r4'], [m('r4', 'r3', 'achieve', long, 1.0), m('r4', 'r1', 'achieve', long, 1.0)])
    near, far = d['rows']
    assert sq.MIN_LABEL_CHARS <= len(near['label']) < len(far['label']) and near['label'].endswith('…')
    assert len(near['label']) * sq.CHAR_WIDTH <= sq.LANE_WIDTH


def test_only_the_latest_rows_are_drawn(monkeypatch):
    monkeypatch.setattr(sq, 'MAX_ROWS', 3)
    d = sequence_layout(['a', 'b'], [m('a', 'b', 'tell', 'n(%d)' % i, float(i)) for i in range(5)])
    assert [r['label'] for r in d['rows']] == ['tell n(2)', 'tell n(3)', 'tell n(4)'] and d['left_out'] == 2


def test_one_agent_and_no_message():
    d = sequence_layout(['solo'], [])
    assert d['rows'] == [] and [lane['name'] for lane in d['lanes']] == ['solo'] and d['width'] > 0
