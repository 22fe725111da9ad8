"""The hostile input of rason_tools.hostile (what the hostile_input rostest and the bench's
hostile part send): the same every run, exceeding the limits it aims at, good literals
that the test agent reports."""
import re

import pytest

from rason_tools import hostile

SMALL = dict(huge_names=5, huge_name_chars=2000)


def test_the_same_seed_gives_the_same_input_and_another_seed_other_garbage():
    assert hostile.cases(**SMALL) == hostile.cases(**SMALL)
    assert hostile.case('malformed', seed=1) != hostile.case('malformed', seed=2)
    assert [c.name for c in hostile.cases(**SMALL)] == list(hostile.NAMES)


def test_a_case_alone_is_the_case_among_the_others():
    assert hostile.case('huge_agent_names', **SMALL) == hostile.cases(**SMALL)[hostile.NAMES.index('huge_agent_names')]
    with pytest.raises(KeyError):
        hostile.case('nice')


def test_good_literals_are_kept_atoms_sent_in_the_case():
    for c in hostile.cases(**SMALL):
        sent = [l for _, literals in c.perceptions for l in literals]
        for good in c.good:
            assert re.match(r'kept\(\w+\)$', good), good
            assert any(l == good or l.startswith(good + '[') for l in sent), (c.name, good)


def test_the_bad_input_exceeds_the_default_limits():
    deep = hostile.case('deep').perceptions[0][1]
    assert deep[0].count('(') == 100000 and deep[3].count('(') == hostile.MAX_NESTING + 1
    huge = hostile.case('huge').perceptions[0][1]
    assert len(huge[0]) > 1 << 20 > hostile.MAX_LITERAL_LENGTH
    assert len(huge[2]) <= hostile.MAX_LITERAL_LENGTH and huge[2].count(',') > hostile.MAX_TERM_DEPTH
    many = hostile.case('many_literals').perceptions
    assert len(many[0][1]) == hostile.MAX_LITERALS + 1 and len(many[1][1]) == hostile.MAX_LITERALS
    sources = {s for s, _ in hostile.case('many_sources').perceptions}
    assert len(sources) > 2 * hostile.MAX_SOURCES


def test_garbage_never_starts_like_a_literal():
    import random
    assert all(g.startswith(')') for g in hostile.garbage(random.Random(1), 500))


def test_huge_names_are_distinct_and_as_long_as_asked():
    names = [e[0] for e in hostile.case('huge_agent_names', **SMALL).events]
    assert len(set(names)) == 5 and {len(n) for n in names} == {2000}


def test_bad_ids_are_outside_32_bits_or_not_integers():
    for i in hostile.BAD_IDS:
        try:
            value = int(i)
        except ValueError:
            continue
        assert not 1 <= value < 2 ** 31, i
