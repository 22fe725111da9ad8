"""Hostile input for a rason_mas, the same on every run (seeded): what the ``hostile_input``
rostest and the ``hostile`` part of ``make bench`` send. Pure: text and tuples, no rospy.

A :class:`Case` is one kind of hostile input: perception messages ``(source, literals)``, events
``(agent, event_type, parameters)`` (agent ``None``: the agent under test) and the
literals among its perceptions that are good and must be believed, sent alongside the bad ones.
``reasons`` are patterns of the bridge's log lines that say why the bad ones were refused.
"""
import random
import string
from collections import namedtuple

from rason_msgs.msg import Event

FEEDBACK, STARTED = Event.ACTION_FEEDBACK, Event.ACTION_STARTED

Case = namedtuple('Case', 'name perceptions events good reasons')

#: What the bridge refuses by default (rason.bridge.InputLimits).
MAX_LITERAL_LENGTH = 4096
MAX_NESTING = 32
MAX_LITERALS = 1000
MAX_TERM_DEPTH = 512
MAX_SOURCES = 100


def kept(name):
    """The good literal of a case: the agent must believe it however bad its neighbours."""
    return 'kept(%s)' % name


def deep_term(depth):
    """``f(f(...f(a)...))``, ``depth`` brackets deep."""
    return 'f(' * depth + 'a' + ')' * depth


def deep_list(depth):
    """``l([[[...]]])``: nested lists ``depth`` deep."""
    return 'l(' + '[' * depth + ']' * depth + ')'


def long_list(elements):
    """``l([1,2,...])``: shallow text, but Jason's term is one level deeper per element."""
    return 'l([' + ','.join(str(i) for i in range(elements)) + '])'


def long_sum(operands):
    """``s(1+1+...+1)``: one level deeper per operator."""
    return 's(' + '+'.join(['1'] * operands) + ')'


def huge_string(chars):
    return 'big("' + 'x' * chars + '")'


def garbage(rng, count, max_len=60):
    """``count`` random strings of printable characters (seeded: the same every run), each
    after a ``)``, which no literal starts with: random letters alone can be an atom."""
    alphabet = string.ascii_letters + string.digits + string.punctuation + ' '
    return [')' + ''.join(rng.choice(alphabet) for _ in range(rng.randint(0, max_len))) for _ in range(count)]


def names(rng, count, chars):
    """``count`` distinct agent names of ``chars`` characters each: a random start, the
    rest padding (cheap to make: 200 names of 1 MB in well under a second)."""
    out = set()
    head = min(chars, 16)
    while len(out) < count:
        out.add(''.join(rng.choice(string.ascii_lowercase) for _ in range(head)) + 'x' * (chars - head))
    return sorted(out)


#: Event ids the bridge cannot take: past 32 bits, negative, zero, not integers.
BAD_IDS = [str(2 ** 31), str(2 ** 32 + 5), str(2 ** 63), '9' * 40, '-1', '0', str(-2 ** 31 - 1), 'abc', '1e3',
           '1.5', '', ' ', 'NaN', '0x10']


#: The cases' names, in the order :func:`cases` gives them.
NAMES = ('deep', 'huge', 'many_literals', 'non_finite', 'reserved', 'malformed', 'bad_events', 'huge_agent_names',
         'many_sources')


def cases(seed=13, huge_names=200, huge_name_chars=1 << 20):
    """Every case, in a fixed order; ``huge_names`` agent names of ``huge_name_chars``
    characters each in ``huge_agent_names`` (the issue's 200 x 1 MB by default). The good
    literals are all ``kept(Name)``, some with annotations; what the reasons name is among
    the first ten bad inputs of a case (the bridge logs only the first lines of a kind)."""
    return [case(name, seed, huge_names, huge_name_chars) for name in NAMES]


def case(name, seed=13, huge_names=200, huge_name_chars=1 << 20):
    """One case by name (see :func:`cases`); each has its own random generator, seeded
    with ``seed`` and its name, so it is the same alone or among the others."""
    if name not in NAMES:
        raise KeyError(name)
    rng = random.Random('%s/%d' % (name, seed))
    if name == 'deep':
        return Case('deep', [('hostile_deep', [deep_term(100000), deep_term(1200), deep_list(1200),
                                               deep_term(MAX_NESTING + 1), kept('deep')])],
                    [], [kept('deep')], [r'nesting deeper than %d' % MAX_NESTING])
    if name == 'huge':
        return Case('huge', [('hostile_huge', [huge_string(1 << 20), 'a' * (1 << 20), long_list(1000), long_sum(1000),
                                               kept('huge')])],
                    [], [kept('huge')], [r'longer than %d characters' % MAX_LITERAL_LENGTH,
                                         r'term deeper than %d levels' % MAX_TERM_DEPTH])
    if name == 'many_literals':
        return Case('many_literals', [('hostile_many', ['m(%d)' % i for i in range(MAX_LITERALS + 1)]),
                                      ('hostile_many_ok', ['m(%d)' % i for i in range(MAX_LITERALS - 1)]
                                       + [kept('many')])],
                    [], [kept('many')],
                    [r"source 'hostile_many': %d literals, more than %d" % (MAX_LITERALS + 1, MAX_LITERALS)])
    if name == 'non_finite':
        return Case('non_finite', [('hostile_numbers', ['n(1e999)', 'n(-1e999)', 'n(1/0)', 'n(0 mod 0)', 'n(1e308*10)',
                                                        'n([1,2,1e999])', 'n(ok)[w(1e999)]',
                                                        'kept(finite)[value(1.5e300)]', kept('non_finite')])],
                    [], [kept('finite'), kept('non_finite')], [r'not a finite number'])
    if name == 'reserved':
        return Case('reserved', [('hostile_reserved', ['said(1)[source(alice)]', '~said(2)[source(bob)]',
                                                       'said(3)[source(percept)]', 'said(4)[certainty(0.9),source(self)]',
                                                       'said(5)[source]', 'kept(reserved)[certainty(0.9)]'])],
                    [], [kept('reserved')], [r'annotation source\(\.\.\.\) is reserved'])
    if name == 'malformed':
        return Case('malformed', [('hostile_malformed', ['temp(', 'temp(c,X)', 'a :- b', '.print(x)', '"unterminated',
                                                         "'q", '/* x', ')(', '', '   ', '\x00\x01', '\u00e9t\u00e9(',
                                                         'f(1)[', 'p(1) & q(2)', 'not p'] + garbage(rng, 200)
                                   + [kept('malformed')])],
                    [], [kept('malformed')], [r"dropped perception 'temp\(' from source 'hostile_malformed'"])
    if name == 'bad_events':
        return Case('bad_events', [], [('nobody', FEEDBACK, ['OK', '1']),
                                       (None, FEEDBACK, ['OK', str(2 ** 31)]),
                                       (None, FEEDBACK, ['OK', '1e3']),
                                       (None, STARTED, ['-1'])]
                    + [(None, FEEDBACK, ['OK', i]) for i in BAD_IDS]
                    + [(None, STARTED, [i]) for i in BAD_IDS]
                    + [(None, FEEDBACK, []), (None, FEEDBACK, ['OK']), (None, 'explode', ['OK', '1']),
                       (None, '', []), (None, FEEDBACK, ['', '5']),
                       (None, FEEDBACK, ['x' * 100000, '7']), ('', FEEDBACK, ['OK', '1'])],
                    [], [r"ignoring events for agent 'nobody'", r'action id %d outside 1\.\.%d' % (2 ** 31, 2 ** 31 - 1),
                         r"non-integer action id '1e3'", r'action_started with action id -1 outside'])
    if name == 'huge_agent_names':
        return Case('huge_agent_names', [], [(n, FEEDBACK, ['OK', '1'])
                                             for n in names(rng, huge_names, huge_name_chars)],
                    [], [r'ignoring events for agent .*not hosted here'])
    # many_sources: a source heard before a flood of new source names keeps being heard
    return Case('many_sources', [('hostile_sources_ok', [kept('early')])]
                + [('hostile_source_%d' % i, ['s(%d)' % i]) for i in range(3 * MAX_SOURCES)]
                + [('hostile_sources_ok', [kept('early'), kept('many_sources')])],
                [], [kept('early'), kept('many_sources')], [r'more than %d sources' % MAX_SOURCES])
