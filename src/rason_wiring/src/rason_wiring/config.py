"""The generic decomposer's configuration: each entry of ``~actions`` checked once, at
start-up, into a :class:`Mapping` that builds messages from an action's arguments and reads
outcomes and feedback from replies. No rospy.

``~actions`` is a dict from an action's signature to what it does::

    goto(X, Y):                         # functor (a Jason atom) and argument names (variables)
      kind: actionlib                   # topic | service | actionlib
      name: move_base                   # the topic, service or action server (relative names)
      type: move_base_msgs/MoveBase     # message, service or action type
      fields:                           # field path -> argument, or a constant
        target_pose.header.frame_id: odom
        target_pose.pose.position.x: X
        target_pose.pose.position.y: Y
        target_pose.pose.orientation.w: 1.0
      feedback: {at: [base_position.pose.position.x, base_position.pose.position.y]}

Every error names the entry and says what is wrong (:class:`ConfigError`).
"""
import re

from rason_wiring import fields, terms

KINDS = ('topic', 'service', 'actionlib')
_KEYS = {
    'topic': {'kind', 'name', 'type', 'fields', 'defaults'},
    'service': {'kind', 'name', 'type', 'fields', 'defaults', 'ok_when', 'reason'},
    'actionlib': {'kind', 'name', 'type', 'fields', 'defaults', 'ok_when', 'reason', 'feedback',
                  'feedback_source'},
}
#: Words YAML 1.1 (rosparam's) reads as bools when unquoted: an argument named so is lost.
_YAML_BOOLS = {'y', 'yes', 'n', 'no', 'on', 'off', 'true', 'false'}
_SIGNATURE = re.compile(r'\s*([^\s()]+)\s*(?:\((.*)\))?\s*\Z', re.S)

#: Results the generic decomposer answers with besides Event.OK and a reason read from a field.
SERVICE_UNAVAILABLE = 'service_unavailable'   # no such service within ~server_wait
SERVICE_ERROR = 'service_error'               # the call raised (the server failed, the link broke)
SERVER_UNAVAILABLE = 'server_unavailable'     # no such action server within ~server_wait
FAILED = 'failed'                             # ok_when false and no reason in the reply
ABORTED = 'aborted'
REJECTED = 'rejected'
PREEMPTED = 'preempted'                       # by someone else: the server, or another goal
SERVER_LOST = 'server_lost'


class ConfigError(ValueError):
    """A configuration that cannot run as written; the text names the entry."""


class _Field(object):
    """One field of the message built: from argument ``arg`` (its index) or a constant."""

    def __init__(self, path, ftype, arg=None, constant=None):
        self.path, self.ftype, self.arg, self.constant = path, ftype, arg, constant


class Mapping(object):
    """One checked entry: an action functor/arity and what it does on the robot.

    :ivar functor: the action's name
    :ivar arities: the numbers of arguments accepted (fewer than declared when trailing
        arguments have defaults)
    :ivar kind: 'topic', 'service' or 'actionlib'
    :ivar name: the topic, service or action server
    :ivar type_name: as configured
    :ivar ros_class: the message class (topic), service class or action class (actionlib)
    :ivar feedback_source: the perception source of the feedback literals (actionlib), or None
    """

    def __init__(self, entry, functor, arg_names, kind, name, type_name, ros_class, fill_class,
                 reply_class):
        self.entry = entry
        self.functor = functor
        self.arg_names = arg_names
        self.kind = kind
        self.name = name
        self.type_name = type_name
        self.ros_class = ros_class
        self._fill_class = fill_class
        self._reply_class = reply_class
        self._fields = []
        self._defaults = {}       # argument index -> Value
        self._ok_path = None      # (path, expected value or None: the bool itself)
        self._reason_path = None
        self._feedback = []       # (functor, [paths])
        self.feedback_source = None

    @property
    def has_feedback(self):
        """True when goal feedback becomes perceptions."""
        return bool(self._feedback)

    @property
    def arities(self):
        return set(range(len(self.arg_names) - len(self._defaults), len(self.arg_names) + 1))

    def __repr__(self):
        return self.entry

    # ------------------------------------------------------------------ at run time

    def build(self, parameters):
        """The message (request, goal) for an action's arguments (text, as the bridge sends them).

        :raises fields.BadValue: an argument does not fit its field
        """
        values = [terms.parse(p) for p in parameters]
        for i in range(len(parameters), len(self.arg_names)):
            values.append(self._defaults[i])
        msg = self._fill_class()
        for f in self._fields:
            if f.arg is None:
                value = f.constant
            elif f.ftype == 'string' and f.arg < len(parameters):
                value = parameters[f.arg]      # strings arrive without their quotes: as they are
            else:
                value = fields.fit(f.ftype, values[f.arg], f.path)
            fields.fill(msg, f.path, value)
        return msg

    def outcome(self, reply):
        """Event.OK's text ``OK`` or the failure reason for a service's response or a
        succeeded goal's result."""
        if self._ok_path is None:
            return 'OK'
        if reply is None:
            return FAILED
        path, expected = self._ok_path
        value = fields.read(reply, path)
        if (value if expected is None else value == expected):
            return 'OK'
        return self.reason(reply, FAILED)

    def reason(self, reply, default):
        """The failure reason read from ``reply`` (the ``reason`` field), or ``default`` when
        none is configured or the field is empty."""
        if self._reason_path is None or reply is None:
            return default
        value = fields.read(reply, self._reason_path)
        text = value if isinstance(value, str) else terms.term(value)
        return text.strip() or default

    def goal_outcome(self, status, result):
        """The answer for a goal that ended in ``status`` (an actionlib_msgs/GoalStatus
        constant's name: SUCCEEDED, ABORTED, REJECTED, PREEMPTED, RECALLED, LOST) with
        ``result`` (None when the server sent none)."""
        if status == 'SUCCEEDED':
            return 'OK' if result is None and self._ok_path is None else self.outcome(result)
        if status == 'ABORTED':
            return self.reason(result, ABORTED)
        if status == 'REJECTED':
            return REJECTED
        if status in ('PREEMPTED', 'RECALLED'):
            return PREEMPTED
        return SERVER_LOST

    def feedback_literals(self, feedback):
        """The literals of one feedback message (actionlib)."""
        return [terms.literal(functor, [fields.read(feedback, p) for p in paths])
                for functor, paths in self._feedback]


def _fail(entry, what, *args):
    raise ConfigError('%s: %s' % (entry, what % args if args else what))


def parse_signature(entry, what='an action signature such as goto(X, Y)'):
    """``'goto(X, Y)'`` -> ``('goto', ['X', 'Y'])``.

    :param what: what ``entry`` should have been, for the error (the synthesizer's literals
        are written the same way)

    :raises ConfigError: a functor that is not a Jason atom, an argument name that is not a
        Jason variable, or a name used twice
    """
    m = _SIGNATURE.match(entry) if isinstance(entry, str) else None
    if m is None:
        _fail(entry, 'not %s', what)
    functor, body = m.group(1), m.group(2)
    if not terms.is_atom(functor):
        _fail(entry, 'functor %r is not a Jason atom (a lower-case letter, then letters, digits, _)',
              functor)
    names = [a.strip() for a in body.split(',')] if body is not None and body.strip() else []
    for name in names:
        if not terms.VARIABLE.match(name):
            _fail(entry, 'argument %r is not a Jason variable name (an upper-case letter, then '
                  'letters, digits, _)', name)
        if names.count(name) > 1:
            _fail(entry, 'argument %s is named twice', name)
    return functor, names


def parse(actions, resolver, default_source=None):
    """Check every entry of ``~actions``.

    :param actions: dict signature -> entry dict, as YAML loaded it
    :param resolver: finds ROS types: ``message(name)``, ``service(name)``, ``action(name)``
        (see :mod:`rason_wiring.ros_types`), each a class or None
    :param default_source: ``default_source(functor)`` names the feedback source of an entry
        without ``feedback_source``
    :returns: the list of :class:`Mapping`
    :raises ConfigError: for the first entry that is wrong
    """
    if not isinstance(actions, dict) or not actions:
        raise ConfigError('~actions: a dict from action signatures (e.g. goto(X, Y)) to what '
                          'they do is needed, not %r' % (actions,))
    mappings = []
    for entry, spec in actions.items():
        mapping = _parse_entry(str(entry), spec, resolver, default_source)
        for other in mappings:
            both = mapping.arities & other.arities
            if other.functor == mapping.functor and both:
                _fail(mapping.entry, '%s/%d is also mapped by %s', mapping.functor, min(both),
                      other.entry)
        mappings.append(mapping)
    return mappings


def _parse_entry(entry, spec, resolver, default_source):
    functor, arg_names = parse_signature(entry)
    if not isinstance(spec, dict):
        _fail(entry, 'a dict with kind, name, type and fields is needed, not %r', spec)
    kind = spec.get('kind')
    if kind not in KINDS:
        _fail(entry, 'unknown kind %r (one of: %s)', kind, ', '.join(KINDS))
    unknown = sorted(set(map(str, spec)) - _KEYS[kind])
    if unknown:
        _fail(entry, 'unknown key %s for kind %s (known: %s)', ', '.join(unknown), kind,
              ', '.join(sorted(_KEYS[kind])))
    for key in ('name', 'type'):
        if not isinstance(spec.get(key), str) or not spec[key].strip():
            _fail(entry, '%s is missing', key)
    type_name = spec['type'].strip()
    ros_class, fill_class, reply_class = _resolve(entry, kind, type_name, resolver)
    mapping = Mapping(entry, functor, arg_names, kind, spec['name'].strip(), type_name, ros_class,
                      fill_class, reply_class)
    _parse_fields(mapping, spec.get('fields', {}), spec.get('defaults', {}))
    _parse_outcome(mapping, spec)
    if kind == 'actionlib':
        _parse_feedback(mapping, spec.get('feedback', {}), resolver.action_feedback(type_name))
        source = spec.get('feedback_source')
        if source is not None and not terms.is_atom(source):
            _fail(entry, 'feedback_source %r is not a Jason atom', source)
        mapping.feedback_source = source or (default_source(functor) if default_source else functor)
    return mapping


def _resolve(entry, kind, type_name, resolver):
    # -> (ros_class, class filled from the arguments, class of the reply read by ok_when/reason)
    if kind == 'topic':
        cls = resolver.message(type_name)
        if cls is None:
            _fail(entry, 'unknown message type %r', type_name)
        return cls, cls, None
    if kind == 'service':
        cls = resolver.service(type_name)
        if cls is None:
            _fail(entry, 'unknown service type %r', type_name)
        return cls, cls._request_class, cls._response_class
    cls = resolver.action(type_name)
    if cls is None:
        _fail(entry, 'unknown action type %r (its %sAction message was not found)', type_name,
              type_name)
    return cls, resolver.action_goal(type_name), resolver.action_result(type_name)


def _parse_fields(mapping, spec, defaults):
    entry, names = mapping.entry, mapping.arg_names
    if not isinstance(spec, dict):
        _fail(entry, 'fields: a dict from field paths to arguments or constants is needed')
    if not isinstance(defaults, dict):
        _fail(entry, 'defaults: a dict from argument names to values is needed')
    used = set()
    for path, source in spec.items():
        path = str(path)
        try:
            ftype = fields.field_type(mapping._fill_class, path)
        except fields.BadPath as e:
            _fail(entry, 'bad field path %s: %s', path, e)
        arg, constant = _source(entry, path, source, names)
        if arg is None:
            try:
                constant = fields.fit(ftype, terms.from_plain(constant), path)
            except ValueError as e:
                _fail(entry, 'constant for %s does not fit: %s', path, e)
        else:
            used.add(arg)
        mapping._fields.append(_Field(path, ftype, arg, constant))
    for i, name in enumerate(names):
        if i not in used:
            hint = ''
            if name.lower() in _YAML_BOOLS:
                hint = " (YAML reads an unquoted %s as a bool: write '%s' in quotes)" % (name, name)
            _fail(entry, 'argument %s is used by no field%s', name, hint)
    for name, value in defaults.items():
        if name not in names:
            _fail(entry, 'default for %s, which is not an argument (arguments: %s)', name,
                  ', '.join(names) or 'none')
        try:
            mapping._defaults[names.index(name)] = terms.from_plain(value)
        except ValueError as e:
            _fail(entry, 'default for %s: %s', name, e)
    optional = sorted(mapping._defaults)
    if optional and optional != list(range(len(names) - len(optional), len(names))):
        _fail(entry, 'only the last arguments can have defaults (an action cannot leave out one '
              'in the middle)')
    for f in mapping._fields:    # defaults must fit every field they fill
        if f.arg in mapping._defaults:
            try:
                fields.fit(f.ftype, mapping._defaults[f.arg], f.path)
            except fields.BadValue as e:
                _fail(entry, 'default for %s does not fit: %s', names[f.arg], e)


def _source(entry, path, source, names):
    # -> (argument index, None) or (None, constant)
    if isinstance(source, dict):
        if set(source) == {'value'}:
            return None, source['value']
        if set(source) == {'arg'}:
            arg = source['arg']
            if isinstance(arg, int) and not isinstance(arg, bool):
                if not 0 <= arg < len(names):
                    _fail(entry, 'field %s: missing argument: position %d (the action has %d '
                          'argument%s, from position 0)', path, arg, len(names),
                          '' if len(names) == 1 else 's')
                return arg, None
            if arg in names:
                return names.index(arg), None
            _fail(entry, 'field %s: missing argument %s (arguments: %s)', path, arg,
                  ', '.join(names) or 'none')
        _fail(entry, 'field %s: {arg: Name or position} or {value: constant} is needed, not %r',
              path, source)
    if isinstance(source, str) and source in names:
        return names.index(source), None
    if isinstance(source, str) and terms.VARIABLE.match(source):
        _fail(entry, 'field %s: missing argument %s (arguments: %s; write {value: %s} for the '
              'text)', path, source, ', '.join(names) or 'none', source)
    return None, source


def _parse_outcome(mapping, spec):
    entry = mapping.entry
    ok_when, reason = spec.get('ok_when'), spec.get('reason')
    reply = mapping._reply_class
    if ok_when is not None:
        if isinstance(ok_when, str):
            ok_when = {'field': ok_when}
        if not isinstance(ok_when, dict) or 'field' not in ok_when or set(ok_when) - {'field', 'equals'}:
            _fail(entry, 'ok_when: a bool field, or {field: path, equals: value}, is needed')
        path = str(ok_when['field'])
        try:
            ftype = fields.field_type(reply, path)
        except fields.BadPath as e:
            _fail(entry, 'bad field path %s in ok_when: %s', path, e)
        if 'equals' in ok_when:
            try:
                expected = fields.fit(ftype, terms.from_plain(ok_when['equals']), path)
            except ValueError as e:
                _fail(entry, 'ok_when equals: %s', e)
            mapping._ok_path = (path, expected)
        elif ftype != 'bool':
            _fail(entry, 'ok_when %s is a %s: give {field: %s, equals: value}', path, ftype, path)
        else:
            mapping._ok_path = (path, None)
    if reason is not None:
        if mapping.kind == 'service' and ok_when is None:
            _fail(entry, 'reason needs ok_when (when is the call a failure?)')
        try:
            fields.field_type(reply, str(reason))
        except fields.BadPath as e:
            _fail(entry, 'bad field path %s in reason: %s', reason, e)
        mapping._reason_path = str(reason)


def _parse_feedback(mapping, spec, feedback_class):
    entry = mapping.entry
    if not isinstance(spec, dict):
        _fail(entry, 'feedback: a dict from functors to field paths is needed')
    for functor, paths in spec.items():
        if not terms.is_atom(functor):
            _fail(entry, 'feedback functor %r is not a Jason atom', functor)
        paths = [paths] if isinstance(paths, str) else paths
        if not isinstance(paths, list) or not all(isinstance(p, str) for p in paths):
            _fail(entry, 'feedback %s: a field path or a list of them is needed', functor)
        for path in paths:
            try:
                fields.field_type(feedback_class, path)
            except fields.BadPath as e:
                _fail(entry, 'bad field path %s in feedback %s: %s', path, functor, e)
        mapping._feedback.append((functor, list(paths)))
