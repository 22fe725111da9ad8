"""Message fields by dotted path: checking a path against a message class, fitting a value to
a field's type, filling a message, reading a field. No rospy: it works on any generated ROS
message class (``__slots__`` and ``_slot_types``), which the tests make without a master.
"""
import math

from rason_wiring import terms

_INT_RANGES = {
    'int8': (-2 ** 7, 2 ** 7 - 1), 'uint8': (0, 2 ** 8 - 1),
    'byte': (-2 ** 7, 2 ** 7 - 1), 'char': (0, 2 ** 8 - 1),   # ROS 1's old aliases
    'int16': (-2 ** 15, 2 ** 15 - 1), 'uint16': (0, 2 ** 16 - 1),
    'int32': (-2 ** 31, 2 ** 31 - 1), 'uint32': (0, 2 ** 32 - 1),
    'int64': (-2 ** 63, 2 ** 63 - 1), 'uint64': (0, 2 ** 64 - 1),
}
_FLOAT_MAX = {'float32': 3.4028234663852886e38, 'float64': float('inf')}
#: The ROS types of number fields.
NUMERIC = frozenset(_INT_RANGES) | frozenset(_FLOAT_MAX)
_SCALARS = set(NUMERIC) | {'bool', 'string'}
#: ROS types a path may not end at (they would need conversions of their own).
_UNSUPPORTED = {'time', 'duration'}


class BadPath(ValueError):
    """A field path that the message class does not have, or cannot be filled or read."""


class BadValue(ValueError):
    """A value that does not fit its field; ``path`` names the field."""

    def __init__(self, path, why):
        ValueError.__init__(self, '%s: %s' % (path, why))
        self.path = path


def _split_array(field_type):
    # 'float64[3]' -> ('float64', 3); 'int32[]' -> ('int32', None); 'bool' -> ('bool', False)
    if not field_type.endswith(']'):
        return field_type, False
    base, size = field_type[:-1].split('[')
    return base, int(size) if size else None


def _is_message(field_type):
    base, _ = _split_array(field_type)
    return base not in _SCALARS and base not in _UNSUPPORTED


def field_type(msg_class, path, messages=False):
    """The ROS type of the field at ``path`` (``target_pose.pose.position.x`` -> ``float64``).

    :param messages: True: a path may end at a (non-array) message, whose type is returned
        (``pose.pose.orientation`` -> ``geometry_msgs/Quaternion``): what a conversion such
        as the synthesizer's ``yaw`` reads
    :raises BadPath: a part the message does not have, a part inside a non-message, or a
        path ending at a message (unless ``messages``), an array of messages, a time or a
        duration
    """
    cls, parts = msg_class, path.split('.')
    for i, part in enumerate(parts):
        slots = list(getattr(cls, '__slots__', ()))
        if part not in slots:
            where = '.'.join(parts[:i]) or cls._type
            raise BadPath('%s has no field %r (it has: %s)' % (where, part, ', '.join(slots)))
        ftype = cls._slot_types[slots.index(part)]
        last = i == len(parts) - 1
        base, array = _split_array(ftype)
        if not last:
            if not _is_message(ftype) or array is not False:
                raise BadPath('%s is a %s: it has no fields' % ('.'.join(parts[:i + 1]), ftype))
            cls = type(getattr(cls(), part))
            continue
        if base in _UNSUPPORTED:
            raise BadPath('%s is a %s: time and duration fields are not supported' % (path, ftype))
        if _is_message(ftype):
            if array is not False:
                raise BadPath('%s is an array of messages (%s): not supported' % (path, ftype))
            sub = getattr(cls(), part)
            if messages:
                return sub._type
            raise BadPath('%s is a message (%s): name one of its fields (%s)'
                          % (path, ftype, ', '.join(sub.__slots__)))
        return ftype


def fit(ftype, value, path):
    """The Python value of field type ``ftype`` for ``value`` (a :class:`terms.Value`).

    :raises BadValue: naming ``path`` and what is wrong
    """
    base, array = _split_array(ftype)
    if array is not False:
        if value.kind != 'list':
            raise BadValue(path, 'a list is needed, not %s' % _shown(value))
        if array is not None and len(value.value) != array:
            raise BadValue(path, 'a list of %d is needed, not %d elements' % (array, len(value.value)))
        return [fit(base, v, '%s[%d]' % (path, i)) for i, v in enumerate(value.value)]
    if base == 'string':
        if value.kind in ('string', 'atom', 'term'):
            return value.value
        if value.kind == 'number':
            return terms.term(value.value)
        raise BadValue(path, 'text is needed, not %s' % _shown(value))
    if base == 'bool':
        if value.kind == 'atom' and value.value in ('true', 'false'):
            return value.value == 'true'
        raise BadValue(path, 'true or false is needed, not %s' % _shown(value))
    if value.kind != 'number':
        raise BadValue(path, 'a number is needed, not %s' % _shown(value))
    number = value.value
    if base in _INT_RANGES:
        if isinstance(number, float):
            if not number.is_integer():
                raise BadValue(path, '%s is not a whole number (%s)' % (number, base))
            number = int(number)
        low, high = _INT_RANGES[base]
        if not low <= number <= high:
            raise BadValue(path, '%d is outside %s (%d..%d)' % (number, base, low, high))
        return number
    number = float(number)
    if not math.isfinite(number) or abs(number) > _FLOAT_MAX[base]:
        raise BadValue(path, '%s does not fit a %s' % (number, base))
    return number


def _shown(value):
    if value.kind == 'list':
        return 'a list'
    text = terms.term(value.value) if value.kind in ('number', 'string') else value.value
    return text if len(text) <= 60 else text[:57] + '...'


def fill(msg, path, value):
    """Set the field at ``path`` of the message instance ``msg`` (intermediate messages exist:
    a generated message makes all its sub-messages)."""
    parts = path.split('.')
    for part in parts[:-1]:
        msg = getattr(msg, part)
    setattr(msg, parts[-1], value)


def read(msg, path):
    """The value of the field at ``path`` of ``msg`` (a tuple for a fixed-size array)."""
    for part in path.split('.'):
        msg = getattr(msg, part)
    return msg
