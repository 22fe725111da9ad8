"""Jason term text <-> plain values, for the wiring's arguments and literals. No ROS.

An action's arguments reach a decomposer as text (``rason_msgs/Action``): numbers plainly
(``-0.3``, ``2``), strings without their quotes, other terms in Jason syntax
(``[1,2]``, ``["a","b"]``, ``pos(1,2)``). :func:`parse` reads such text into a
:class:`Value`; :func:`literal` writes plain values (message fields) back as a Jason literal.
"""
import math
import re
from collections import namedtuple

#: A parsed term: ``kind`` is 'number' (value int or float), 'atom' (value the name),
#: 'string' (value the text), 'list' (value a list of Value) or 'term' (any other term;
#: value its text).
Value = namedtuple('Value', 'kind value')

ATOM = re.compile(r'[a-z][A-Za-z0-9_]*\Z')
VARIABLE = re.compile(r'[A-Z][A-Za-z0-9_]*\Z')
_NUMBER = re.compile(r'[+-]?(\d+(\.\d*)?|\.\d+)([eE][+-]?\d+)?\Z')


def is_atom(text):
    """True when ``text`` is a Jason atom as a functor must be (``goto``, ``say_hi``)."""
    return isinstance(text, str) and ATOM.match(text) is not None


def number(text):
    """The int or float that ``text`` spells, or None (not finite numbers are None too)."""
    text = text.strip()
    if not _NUMBER.match(text):
        return None
    if re.match(r'[+-]?\d+\Z', text):
        return int(text)
    value = float(text)
    return value if math.isfinite(value) else None


def parse(text):
    """Read one term of Jason text into a :class:`Value` (never raises: what is not a
    number, atom, string or list of those is a 'term')."""
    text = text.strip()
    found = number(text)
    if found is not None:
        return Value('number', found)
    if ATOM.match(text):
        return Value('atom', text)
    if len(text) >= 2 and text[0] == '"' and text[-1] == '"':
        inner = _unquote(text)
        if inner is not None:
            return Value('string', inner)
    if len(text) >= 2 and text[0] == '[' and text[-1] == ']':
        items = _split_list(text[1:-1])
        if items is not None:
            return Value('list', [parse(item) for item in items])
    return Value('term', text)


def _unquote(text):
    # a whole "..." string with Jason's escapes; None if the quotes do not enclose it all
    out, i = [], 1
    while i < len(text) - 1:
        c = text[i]
        if c == '"':
            return None
        if c == '\\':
            i += 1
            if i >= len(text) - 1:
                return None
            c = {'n': '\n', 't': '\t', 'r': '\r'}.get(text[i], text[i])
        out.append(c)
        i += 1
    return ''.join(out)


def _split_list(body):
    # the elements of a list's body at depth 0, outside strings; None for [H|T] and the like
    if not body.strip():
        return []
    items, depth, start, quoted, i = [], 0, 0, False, 0
    while i < len(body):
        c = body[i]
        if quoted:
            if c == '\\':
                i += 1
            elif c == '"':
                quoted = False
        elif c == '"':
            quoted = True
        elif c in '([{':
            depth += 1
        elif c in ')]}':
            depth -= 1
        elif c == '|' and depth == 0:
            return None
        elif c == ',' and depth == 0:
            items.append(body[start:i])
            start = i + 1
        i += 1
    items.append(body[start:])
    return items if all(item.strip() for item in items) else None


def from_plain(value):
    """A :class:`Value` for a plain Python value as YAML gives it (constants, defaults)."""
    if isinstance(value, bool):
        return Value('atom', 'true' if value else 'false')
    if isinstance(value, (int, float)):
        return Value('number', value)
    if isinstance(value, str):
        return Value('string', value)
    if isinstance(value, (list, tuple)):
        return Value('list', [from_plain(v) for v in value])
    raise ValueError('%r is not a number, string, bool or list' % (value,))


def term(value):
    """Jason text of a plain value read from a message field: bools as ``true``/``false``,
    numbers plainly, text as a quoted string, sequences as lists."""
    if isinstance(value, bool):
        return 'true' if value else 'false'
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        # Jason has no literal for them, and the bridge drops numbers that are not finite
        return repr(value) if math.isfinite(value) else '"%s"' % value
    if isinstance(value, bytes):
        return '[%s]' % ','.join(str(b) for b in value)
    if isinstance(value, (list, tuple)):
        return '[%s]' % ','.join(term(v) for v in value)
    text = str(value)
    return '"%s"' % text.replace('\\', '\\\\').replace('"', '\\"').replace('\n', '\\n')


def literal(functor, values):
    """``functor(v1,...)`` in Jason syntax (just ``functor`` without values)."""
    if not values:
        return functor
    return '%s(%s)' % (functor, ','.join(term(v) for v in values))
