"""docs/reference/wiring-files.md lists exactly the keys generic_decomposer and
generic_synthesizer accept, each action key for the kinds that take it. No ROS master."""
import os
import re

from rason_wiring import config, synth

PAGE = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', '..', 'docs', 'reference',
                    'wiring-files.md')


def _section(title):
    with open(PAGE, encoding='utf-8') as f:
        text = f.read()
    start = text.index('## ' + title)
    end = text.find('\n## ', start + 1)
    return text[start:end if end > 0 else len(text)]


def _rows(section):
    """The first table of section: [cells] of each row under its header."""
    rows = []
    for line in section.splitlines():
        if line.startswith('|'):
            rows.append([c.strip() for c in line.strip().strip('|').split('|')])
        elif rows:
            break
    return rows[2:]


def test_the_action_keys_and_the_kinds_that_take_them():
    rows = _rows(_section('`~actions`'))
    listed = {kind: {re.sub('`', '', r[0]) for r in rows if r[1 + i] == '✓'} for i, kind in enumerate(config.KINDS)}
    assert listed == config._KEYS


def test_the_perception_entry_keys():
    rows = _rows(_section('`~perceptions`'))
    assert {re.sub('`', '', r[0]) for r in rows} == synth._KEYS
