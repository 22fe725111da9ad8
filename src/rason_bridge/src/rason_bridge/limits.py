"""The ~params that bound hostile or unlucky input (Java's rason.bridge.InputLimits), and
durations given in seconds made Java's nanoseconds; no rospy."""
import math

#: The longest duration a ~param may give (s): about 31 years, far inside Java's long nanoseconds.
MAX_SECONDS = 1e9

#: ~param -> the InputLimits getter and setter; the defaults are the Java object's values.
INPUT_LIMIT_PARAMS = {
    'max_literal_length': ('maxLiteralLength', 'setMaxLiteralLength'),
    'max_content_length': ('maxContentLength', 'setMaxContentLength'),
    'max_nesting': ('maxNesting', 'setMaxNesting'),
    'max_term_depth': ('maxTermDepth', 'setMaxTermDepth'),
    'max_literals': ('maxLiterals', 'setMaxLiterals'),
    'max_sources': ('maxSources', 'setMaxSources'),
}


def apply_input_limits(limits, get_param):
    """Set every limit from ``get_param(name, default)``, the default being the current value.

    :param limits: the Java ``InputLimits`` (``Bridge.get().limits()``)
    :param get_param: e.g. ``lambda n, d: rospy.get_param('~' + n, d)``
    :raises ValueError: a value that is not a positive whole number, naming the parameter
    """
    for name, (getter, setter) in INPUT_LIMIT_PARAMS.items():
        value = get_param(name, int(getattr(limits, getter)()))
        if isinstance(value, bool) or not isinstance(value, int) or value < 1:
            raise ValueError('%s must be a whole number of at least 1, not %r' % (name, value))
        getattr(limits, setter)(value)


def seconds_to_nanos(name, seconds):
    """A duration ~param in seconds as whole nanoseconds for Java.

    :raises ValueError: not a number, not finite or beyond :data:`MAX_SECONDS` either way,
        naming the parameter (``int(inf)`` would raise OverflowError, and a Java long
        cannot hold more than 292 years)
    """
    if isinstance(seconds, bool) or not isinstance(seconds, (int, float)):
        raise ValueError('%s must be a number of seconds, not %r' % (name, seconds))
    if not math.isfinite(seconds) or abs(seconds) > MAX_SECONDS:
        raise ValueError('%s must be a finite number of seconds up to %g, not %r' % (name, MAX_SECONDS, seconds))
    return int(round(seconds * 1e9))
