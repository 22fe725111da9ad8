"""The messages between robots as a sequence diagram: a lane per agent, a row per message in
time order, an arrow from the sender's lane to the receiver's (a broadcast: to every other
lane). Pure layout in SVG user units; the page only draws what it is given."""
from rason_dashboard.dialogue import step

LANE_WIDTH = 170    # between two lanes' centres
ROW_HEIGHT = 26
TOP = 34            # the lanes' names above the first row
LEFT = 56           # the messages' times left of the first lane
CHAR_WIDTH = 6.7    # of the labels' monospace font: a label longer than its arrow is cut
MIN_LABEL_CHARS = 16  # (the whole message is the row's title)
#: How many of the latest messages the diagram draws.
MAX_ROWS = 60


def lanes_of(agents, messages):
    """The lanes' names: the agents in the order given, then anyone else a message names in
    the order met (a robot whose mind is not seen, a receiver that left); 'all' is no lane."""
    lanes = list(dict.fromkeys(agents))
    for m in messages:
        for name in (m['sender'], m['receiver']):
            if name != 'all' and name not in lanes:
                lanes.append(name)
    return lanes


def label(message, width):
    """performative and content, cut to fit width (SVG units) but never below MIN_LABEL_CHARS."""
    text = '%s %s' % (message['performative'], message['content'])
    chars = max(MIN_LABEL_CHARS, int(width / CHAR_WIDTH) - 1)
    return text if len(text) <= chars else text[:chars - 1] + '…'


def sequence_layout(agents, messages):
    """The diagram of messages (records with their time, in time order; the last MAX_ROWS are
    drawn) among agents (names, in lane order). Returns {'width', 'height', 'lanes': [{'name',
    'x'}], 'rows': [{'y', 'time', 'sender', 'receiver', 'step', 'label', 'title', 'label_x',
    'arrows': [{'to', 'x1', 'x2'}]}], 'left_out'}."""
    shown = messages[-MAX_ROWS:]
    names = lanes_of(agents, messages)
    x = {name: LEFT + LANE_WIDTH * (i + 0.5) for i, name in enumerate(names)}
    rows = []
    for i, m in enumerate(shown):
        sender = m['sender']
        targets = [n for n in names if n != sender] if m['receiver'] == 'all' else [m['receiver']]
        arrows = [{'to': t, 'x1': x[sender], 'x2': x[t]} for t in targets]
        ends = [x[sender]] + [a['x2'] for a in arrows]
        if len(arrows) == 1:  # over the middle of its one arrow
            label_x, width = (ends[0] + ends[1]) / 2, abs(ends[1] - ends[0])
        else:  # a broadcast: next to the sender, towards the side most of its arrows go
            right = sum(1 for a in arrows if a['x2'] > a['x1']) >= len(arrows) / 2.0
            label_x, width = x[sender] + (LANE_WIDTH / 2 if right else -LANE_WIDTH / 2), LANE_WIDTH
        text = label(m, width)
        rows.append({'y': TOP + ROW_HEIGHT * (i + 1), 'time': m.get('time'), 'sender': sender,
                     'receiver': m['receiver'], 'step': step(m), 'label': text,
                     'title': m.get('line') or '%s -> %s: %s' % (sender, m['receiver'], text),
                     'label_x': label_x, 'arrows': arrows})
    return {'width': LEFT + LANE_WIDTH * max(1, len(names)), 'height': TOP + ROW_HEIGHT * (len(shown) + 1),
            'lanes': [{'name': n, 'x': x[n]} for n in names], 'rows': rows,
            'left_out': len(messages) - len(shown)}
