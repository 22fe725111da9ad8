"""The generic synthesizer's configuration and logic: each entry of ``~perceptions`` checked
once, at start-up, into a :class:`Synthesis` that turns one message of a topic into literals,
and a :class:`Gate` that decides when a list of literals is published (rate limit, only
when changed, refresh). No rospy.

``~perceptions`` is a dict from entry names to what they perceive::

    odometry:                              # the entry's name (errors name it)
      topic: odom                          # a relative name: the node's namespace
      type: nav_msgs/Odometry              # the message type, resolved at start-up
      source: odom                         # the perception source; default <node name>_<entry>
      max_rate: 5                          # Hz at most (ROS time); 0: as often as messages come
      only_changed: true                   # a list equal to the last one published is not sent again
      refresh: 1.0                         # s: ... except this often, while the topic goes on (TTL)
      literals:
        pos(X, Y, Yaw):                    # functor (a Jason atom) and argument names
          X: pose.pose.position.x          # an argument from a field path
          Y: {field: pose.pose.position.y, round: 2}
          Yaw: {field: pose.pose.orientation, convert: yaw_deg, round: 1}
        moving:                            # a literal only while its condition holds
          when: {field: twist.twist.linear.x, gt: 0.01}

An argument is a field path, ``{field: path, convert: name, scale: k, offset: c, round: n}``
(applied in that order) or ``{value: constant}``. A condition (``when``, one or a list that
must all hold) reads a field the same way and compares it with one of ``eq ne lt le gt ge``.
Every error names the entry and says what is wrong (:class:`ConfigError`).
"""
import math
import operator

from rason_wiring import fields, terms
from rason_wiring.config import ConfigError, parse_signature

_KEYS = {'topic', 'type', 'source', 'max_rate', 'only_changed', 'refresh', 'literals'}
_NUMERIC = fields.NUMERIC
_QUATERNION = 'geometry_msgs/Quaternion'
_OPS = {'eq': operator.eq, 'ne': operator.ne, 'lt': operator.lt, 'le': operator.le,
        'gt': operator.gt, 'ge': operator.ge}
_ORDERED_OPS = {'lt', 'le', 'gt', 'ge'}
DEFAULT_MAX_RATE = 10.0
DEFAULT_REFRESH = 1.0     # half rason_mas's default ~perception_ttl (2 s)


def _yaw(q):
    # heading (rad, counter-clockwise) of a quaternion: its rotation about z
    return math.atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z))


#: Named conversions: name -> (what they read: 'number' or a message type, function).
CONVERSIONS = {
    'rad_to_deg': ('number', math.degrees),
    'deg_to_rad': ('number', math.radians),
    'yaw': (_QUATERNION, _yaw),
    'yaw_deg': (_QUATERNION, lambda q: math.degrees(_yaw(q))),
}


def _fail(entry, what, *args):
    raise ConfigError('%s: %s' % (entry, what % args if args else what))


class _Reader(object):
    """One value read from a message: a field, converted, scaled, offset, rounded; or a
    constant."""

    def __init__(self, path=None, convert=None, scale=None, offset=None, digits=None,
                 constant=None):
        self.path, self.convert, self.scale, self.offset = path, convert, scale, offset
        self.digits, self.constant = digits, constant

    def read(self, msg):
        if self.path is None:
            return self.constant
        value = fields.read(msg, self.path)
        if isinstance(value, tuple):    # a fixed-size array: compared and written as a list
            value = list(value)
        if self.convert is not None:
            value = CONVERSIONS[self.convert][1](value)
        if self.scale is not None:
            value = value * self.scale
        if self.offset is not None:
            value = value + self.offset
        if self.digits is not None and isinstance(value, float) and math.isfinite(value):
            value = round(value, self.digits) if self.digits else int(round(value))
        return value


class _Condition(object):

    def __init__(self, reader, op, constant):
        self.reader, self.op, self.constant = reader, op, constant

    def holds(self, msg):
        value = self.reader.read(msg)
        try:
            return bool(_OPS[self.op](value, self.constant))
        except TypeError:
            return False


class _Template(object):
    """One literal: functor, an argument reader per argument, conditions."""

    def __init__(self, functor, readers, conditions):
        self.functor, self.readers, self.conditions = functor, readers, conditions

    def literal(self, msg):
        """The literal for ``msg``, or None when a condition does not hold."""
        if not all(c.holds(msg) for c in self.conditions):
            return None
        return terms.literal(self.functor, [r.read(msg) for r in self.readers])


class Synthesis(object):
    """One checked entry: a topic, its message class and the literals made of each message.

    :ivar entry: the entry's name
    :ivar topic: the topic (as configured: relative to the node's namespace)
    :ivar type_name: the message type's name
    :ivar msg_class: the message class
    :ivar source: the perception source
    :ivar max_rate, only_changed, refresh: for the entry's :class:`Gate`
    """

    def __init__(self, entry, topic, type_name, msg_class, source, max_rate, only_changed,
                 refresh, templates):
        self.entry, self.topic, self.type_name, self.msg_class = entry, topic, type_name, msg_class
        self.source, self.max_rate, self.only_changed, self.refresh = (source, max_rate,
                                                                       only_changed, refresh)
        self._templates = templates

    def __repr__(self):
        return self.entry

    def literals(self, msg):
        """The literals (Jason text) of one message, in the configured order: those whose
        conditions hold."""
        out = []
        for template in self._templates:
            literal = template.literal(msg)
            if literal is not None:
                out.append(literal)
        return out

    def gate(self):
        """A new :class:`Gate` with this entry's rate limit, only-when-changed and refresh."""
        return Gate(self.max_rate, self.only_changed, self.refresh)


class Gate(object):
    """When the lists of literals made from a topic's messages are published.

    - at most ``max_rate`` lists a second (0: no limit): a list made before the interval is
      over is held, and the newest held one is published once it is over (so the last state
      is never lost);
    - ``only_changed``: a list equal to the last one published is not published again...
    - ... except every ``refresh`` seconds (0: never) while the topic goes on, so that the
      agents' ``~perception_ttl`` does not forget a state that merely stays the same (a topic
      that falls silent is not refreshed: its percepts expire, as they should).

    Times are seconds of one clock (the node gives ROS time, the agents' TTL's clock); a clock
    that jumps back (a restarted simulation) counts as every interval over.
    """

    def __init__(self, max_rate, only_changed, refresh):
        self.interval = 1.0 / max_rate if max_rate else 0.0
        self.only_changed = only_changed
        self.refresh = refresh
        self._last = None        # the list published last
        self._last_time = None
        self._held = None        # a newer list waiting for the interval to be over
        self._heard = False      # a message came since the last publication

    def _over(self, now, interval):
        return self._last_time is None or now < self._last_time or now - self._last_time >= interval

    def _publish(self, literals, now):
        self._last, self._last_time, self._held, self._heard = literals, now, None, False
        return literals

    def offer(self, literals, now):
        """The list of a new message; returns it when it is to be published now, else None."""
        self._heard = True
        if self.only_changed and literals == self._last:
            self._held = None    # back to what the agents already have
            return None
        if self._over(now, self.interval):
            return self._publish(literals, now)
        self._held = literals
        return None

    def poll(self, now):
        """Call often: a held list whose interval is over, or the refresh of the last one;
        else None."""
        if self._held is not None:
            return self._publish(self._held, now) if self._over(now, self.interval) else None
        if (self.refresh and self._heard and self._last is not None
                and self._over(now, self.refresh)):
            return self._publish(self._last, now)
        return None


def parse(perceptions, resolver, default_source=None):
    """Check every entry of ``~perceptions``.

    :param perceptions: dict entry name -> entry dict, as YAML loaded it
    :param resolver: finds message classes: ``message(name)`` (see :mod:`rason_wiring.ros_types`)
    :param default_source: ``default_source(entry)`` names the source of an entry without
        ``source``
    :returns: the list of :class:`Synthesis`
    :raises ConfigError: for the first entry that is wrong
    """
    if not isinstance(perceptions, dict) or not perceptions:
        raise ConfigError('~perceptions: a dict from entry names to a topic, its type and the '
                          'literals made of its messages is needed, not %r' % (perceptions,))
    syntheses = []
    for entry, spec in perceptions.items():
        synthesis = _parse_entry(str(entry), spec, resolver, default_source)
        for other in syntheses:
            if other.source == synthesis.source:
                _fail(synthesis.entry, 'source %s is also the source of %s (each source\'s list '
                      'replaces the previous one: give each entry its own)', synthesis.source,
                      other.entry)
        syntheses.append(synthesis)
    return syntheses


def _parse_entry(entry, spec, resolver, default_source):
    if not isinstance(spec, dict):
        _fail(entry, 'a dict with topic, type and literals is needed, not %r', spec)
    unknown = sorted(set(map(str, spec)) - _KEYS)
    if unknown:
        _fail(entry, 'unknown key %s (known: %s)', ', '.join(unknown), ', '.join(sorted(_KEYS)))
    for key in ('topic', 'type'):
        if not isinstance(spec.get(key), str) or not spec[key].strip():
            _fail(entry, '%s is missing', key)
    type_name = spec['type'].strip()
    msg_class = resolver.message(type_name)
    if msg_class is None:
        _fail(entry, 'unknown message type %r', type_name)
    source = spec.get('source')
    if source is None:
        source = default_source(entry) if default_source else entry
    if not terms.is_atom(source):
        _fail(entry, 'source %r is not a Jason atom', source)
    max_rate = _number(entry, spec, 'max_rate', DEFAULT_MAX_RATE)
    refresh = _number(entry, spec, 'refresh', DEFAULT_REFRESH)
    only_changed = spec.get('only_changed', True)
    if not isinstance(only_changed, bool):
        _fail(entry, 'only_changed: true or false is needed, not %r', only_changed)
    literals = spec.get('literals')
    if not isinstance(literals, dict) or not literals:
        _fail(entry, 'literals: a dict from literals such as pos(X, Y) to the fields of their '
              'arguments is needed')
    templates = [_parse_template(entry, str(signature), body, msg_class)
                 for signature, body in literals.items()]
    return Synthesis(entry, spec['topic'].strip(), type_name, msg_class, source, max_rate,
                     only_changed, refresh, templates)


def _number(entry, spec, key, default):
    value = spec.get(key, default)
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not (
            0 <= value < float('inf')):
        _fail(entry, '%s: a number >= 0 is needed, not %r', key, value)
    return float(value)


def _parse_template(entry, signature, body, msg_class):
    where = '%s: literal %s' % (entry, signature)
    try:
        functor, names = parse_signature(signature, 'a literal such as pos(X, Y)')
    except ConfigError as e:
        raise ConfigError('%s: literal %s' % (entry, e))
    if body is None:
        body = {}
    if not isinstance(body, dict):
        _fail(where, 'a dict from its arguments to fields (and an optional when) is needed')
    for key in body:
        if isinstance(key, bool):
            _fail(where, 'a key YAML read as %s: quote an argument named On, Off, Yes or No', key)
        if key != 'when' and key not in names:
            _fail(where, 'unknown key %s (arguments: %s; and when)', key, ', '.join(names) or 'none')
    readers = []
    for name in names:
        if name not in body:
            _fail(where, 'argument %s is read from no field', name)
        readers.append(_parse_reader('%s: argument %s' % (where, name), body[name], msg_class)[0])
    conditions = body.get('when', [])
    conditions = conditions if isinstance(conditions, list) else [conditions]
    return _Template(functor, readers, [_parse_condition(where, c, msg_class) for c in conditions])


def _parse_reader(where, spec, msg_class, extra=()):
    # a field path, {field, convert, scale, offset, round}, or {value}; -> (_Reader, its type)
    if isinstance(spec, str):
        spec = {'field': spec}
    if not isinstance(spec, dict):
        _fail(where, 'a field path, {field: path, ...} or {value: constant} is needed, not %r',
              spec)
    if 'value' in spec:
        if set(spec) - {'value'} - set(extra):
            _fail(where, '{value: constant} takes no other key')
        try:
            terms.from_plain(spec['value'])
        except ValueError as e:
            _fail(where, '%s', e)
        return _Reader(constant=spec['value']), None
    unknown = sorted(set(spec) - {'field', 'convert', 'scale', 'offset', 'round'} - set(extra))
    if unknown:
        _fail(where, 'unknown key %s (known: field, convert, scale, offset, round; or value)',
              ', '.join(map(str, unknown)))
    path = spec.get('field')
    if not isinstance(path, str) or not path.strip():
        _fail(where, 'field (a path) is missing')
    convert = spec.get('convert')
    try:
        ftype = fields.field_type(msg_class, path, messages=convert is not None)
    except fields.BadPath as e:
        _fail(where, 'bad field path %s: %s', path, e)
    if convert is not None:
        if convert not in CONVERSIONS:
            _fail(where, 'unknown conversion %r (known: %s)', convert, ', '.join(sorted(CONVERSIONS)))
        reads = CONVERSIONS[convert][0]
        if reads == 'number' and ftype not in _NUMERIC or reads != 'number' and ftype != reads:
            _fail(where, 'conversion %s reads a %s, and %s is a %s', convert,
                  'number' if reads == 'number' else reads, path, ftype)
        ftype = 'float64'
    digits = spec.get('round')
    for key in ('scale', 'offset'):
        value = spec.get(key)
        if value is not None and (isinstance(value, bool) or not isinstance(value, (int, float))
                                  or not math.isfinite(value)):
            _fail(where, '%s: a number is needed, not %r', key, value)
    if digits is not None and (isinstance(digits, bool) or not isinstance(digits, int)
                               or not 0 <= digits <= 15):
        _fail(where, 'round: a number of decimals from 0 to 15 is needed, not %r', digits)
    arithmetic = spec.get('scale') is not None or spec.get('offset') is not None
    if (arithmetic or digits is not None) and ftype not in _NUMERIC:
        _fail(where, 'scale, offset and round need a number, and %s is a %s', path, ftype)
    reader = _Reader(path, convert, spec.get('scale'), spec.get('offset'), digits)
    return reader, 'float64' if arithmetic else ftype


def _parse_condition(where, spec, msg_class):
    ops = sorted(set(spec) & set(_OPS)) if isinstance(spec, dict) else []
    if len(ops) != 1:
        _fail(where, 'when: {field: path, OP: constant} with one OP of %s is needed, not %r',
              ', '.join(sorted(_OPS)), spec)
    op = ops[0]
    reader, ftype = _parse_reader('%s: when' % where, spec, msg_class, extra=(op,))
    if reader.path is None:
        _fail(where, 'when: a field to compare is needed')
    constant = spec[op]
    if ftype in _NUMERIC:    # compared as numbers: 0.5 with an int field is fine
        if isinstance(constant, bool) or not isinstance(constant, (int, float)) or not (
                math.isfinite(constant)):
            _fail(where, 'when: %s: a number is needed, not %r', op, constant)
        return _Condition(reader, op, constant)
    if op in _ORDERED_OPS:
        _fail(where, 'when: %s compares numbers, and %s is a %s', op, reader.path, ftype)
    try:
        fitted = fields.fit(ftype, terms.from_plain(constant), reader.path)
    except ValueError as e:
        _fail(where, 'when: %s %r does not fit: %s', op, constant, e)
    return _Condition(reader, op, fitted)
