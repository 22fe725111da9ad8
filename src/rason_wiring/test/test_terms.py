"""Unit tests of rason_wiring.terms: Jason text <-> values (no ROS)."""
import pytest

from rason_wiring import terms
from rason_wiring.terms import Value


@pytest.mark.parametrize('text, value', [
    ('3', Value('number', 3)), ('-3', Value('number', -3)), ('0.25', Value('number', 0.25)),
    ('-1.5E-3', Value('number', -0.0015)), ('.5', Value('number', 0.5)),
    ('odom', Value('atom', 'odom')), ('true', Value('atom', 'true')),
    ('"a \\"b\\""', Value('string', 'a "b"')), ('"x\\ny"', Value('string', 'x\ny')),
    ('pos(1,2)', Value('term', 'pos(1,2)')), ('Hello world', Value('term', 'Hello world')),
    ('[]', Value('list', [])),
    ('[1, 2.5, a, "b,c"]', Value('list', [Value('number', 1), Value('number', 2.5),
                                           Value('atom', 'a'), Value('string', 'b,c')])),
    ('[[1,2],[3]]', Value('list', [Value('list', [Value('number', 1), Value('number', 2)]),
                                   Value('list', [Value('number', 3)])])),
    ('[p(1,2),x]', Value('list', [Value('term', 'p(1,2)'), Value('atom', 'x')])),
])
def test_parse_reads_numbers_atoms_strings_lists_and_keeps_other_terms(text, value):
    assert terms.parse(text) == value


@pytest.mark.parametrize('text', ['[H|T]', '[1,,2]', '"a"b"', '1e999', 'nan', '[1,2'])
def test_parse_keeps_what_is_no_number_string_or_proper_list_as_a_term_or_atom(text):
    assert terms.parse(text).kind in ('term', 'atom')


def test_is_atom_accepts_jason_atoms_only():
    assert terms.is_atom('goto') and terms.is_atom('say_hi2')
    for bad in ('Goto', '_x', '2go', 'go-to', '', 'go to', None, 3):
        assert not terms.is_atom(bad)


@pytest.mark.parametrize('value, text', [
    (True, 'true'), (False, 'false'), (3, '3'), (-0.5, '-0.5'), ('a "q"\n', '"a \\"q\\"\\n"'),
    ([1, 2], '[1,2]'), ((0.5, 'x'), '[0.5,"x"]'), (b'\x01\x02', '[1,2]'), (float('inf'), '"inf"'),
])
def test_term_writes_field_values_as_jason_text(value, text):
    assert terms.term(value) == text


def test_literal_writes_functor_and_arguments():
    assert terms.literal('at', [1.5, -2]) == 'at(1.5,-2)'
    assert terms.literal('arrived', []) == 'arrived'


def test_from_plain_tags_yaml_values():
    assert terms.from_plain(True) == Value('atom', 'true')
    assert terms.from_plain(2) == Value('number', 2)
    assert terms.from_plain('odom') == Value('string', 'odom')
    assert terms.from_plain([1, 'a']) == Value('list', [Value('number', 1), Value('string', 'a')])
    with pytest.raises(ValueError):
        terms.from_plain({'a': 1})
