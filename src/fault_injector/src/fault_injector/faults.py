"""Fault models of the fault injector (thesis §6.3), free of ROS.

Everything here works on plain numbers and tuples so it can be unit-tested
without a ROS master; :mod:`fault_injector.node` converts messages.

Faults:

``left_actuator`` / ``right_actuator``
    Thesis Eq. 6.2 (angular velocity) and Eq. 6.3 (linear velocity) at severity 1 (the
    wheel gives nothing); a weaker fault (severity s in (0, 1)) gives the command
    blended: (1 - s) * commanded + s * Eq. 6.2/6.3.
``both_actuators``
    Every twist component is zero: the robot cannot move.
``odometry``
    The odometry passed on is frozen at the last value received before the
    fault was injected.
``none``
    Pass-through. Requested as ``cancel`` (or ``none``).
"""
import math

LEFT_ACTUATOR = 'left_actuator'
RIGHT_ACTUATOR = 'right_actuator'
BOTH_ACTUATORS = 'both_actuators'
ODOMETRY = 'odometry'
NONE = 'none'
CANCEL = 'cancel'

#: Faults that can be active, in the order they are listed to users.
FAULTS = (LEFT_ACTUATOR, RIGHT_ACTUATOR, BOTH_ACTUATORS, ODOMETRY)
#: Every string accepted by the ``inject_fault`` service.
VALID_REQUESTS = FAULTS + (CANCEL, NONE)


class UnknownFaultError(ValueError):
    """Raised by :func:`parse_fault` for a request that names no fault."""


def valid_requests_text():
    """Human-readable list of what the service accepts.

    :return: e.g. ``"left_actuator, ..., odometry, cancel (alias: none)"``
    """
    return '%s, %s (alias: %s)' % (', '.join(FAULTS), CANCEL, NONE)


def parse_fault(request):
    """Validate a fault request and return the fault it makes active.

    Surrounding blanks and letter case are ignored, since the request is often
    typed by hand.

    :param request: the ``fault`` field of the service request
    :return: one of :data:`FAULTS`, or :data:`NONE` for ``cancel``/``none``
    :raises UnknownFaultError: if ``request`` is not in :data:`VALID_REQUESTS`
    """
    name = str(request).strip().lower()
    if name in (CANCEL, NONE):
        return NONE
    if name in FAULTS:
        return name
    raise UnknownFaultError('unknown fault %r; valid faults: %s'
                            % (request, valid_requests_text()))


def has_nan(values):
    """Tell whether any of the numbers is NaN.

    :param values: iterable of floats
    :return: True if at least one is NaN
    """
    return any(math.isnan(v) for v in values)


def check_severity(severity):
    """The severity as a float in (0, 1].

    :raises ValueError: for anything else (NaN included)
    """
    try:
        value = float(severity)
    except (TypeError, ValueError):
        raise ValueError('severity must be a number in (0, 1], got %r' % (severity,))
    if not 0.0 < value <= 1.0:  # also refuses NaN
        raise ValueError('severity must be in (0, 1], got %r' % (severity,))
    return value


def transform_twist(fault, linear, angular, severity=1.0):
    """Apply an actuator fault to a velocity command.

    For ``left_actuator``/``right_actuator``, with ``x_lin = linear[0]``:

    * Eq. 6.2: ``angular.z = x_lin`` if (left and x_lin > 0) or (right and
      x_lin < 0); ``angular.z = -x_lin`` if (right and x_lin > 0) or (left and
      x_lin < 0). So a left fault always yaws positive (left) and a right fault
      negative, by ``|x_lin|``, replacing the commanded yaw rate.
    * Eq. 6.3: ``linear.x = x_lin / 2`` (only one wheel pushes).

    With ``x_lin == 0`` neither case of Eq. 6.2 applies, so the commanded
    ``angular.z`` is left unchanged (a turn on the spot stays a turn on the
    spot). NaN compares false too, so it behaves the same way and is passed on.
    The other components (unused by a differential drive) are left unchanged.

    A weaker actuator fault (``severity`` below 1) passes on
    ``(1 - severity) * commanded + severity * (the above)`` for ``linear.x`` and
    ``angular.z``: from a healthy base near 0 to the thesis's fault at 1.

    :param fault: the active fault (one of :data:`FAULTS` or :data:`NONE`)
    :param linear: ``(x, y, z)`` linear velocity commanded
    :param angular: ``(x, y, z)`` angular velocity commanded
    :param severity: in (0, 1] (see :func:`check_severity`); only actuator faults use it
    :return: ``(linear, angular)``, each a 3-tuple of floats, to send to the base
    """
    linear = tuple(float(v) for v in linear)
    angular = tuple(float(v) for v in angular)
    if fault == BOTH_ACTUATORS:
        return (0.0, 0.0, 0.0), (0.0, 0.0, 0.0)
    if fault not in (LEFT_ACTUATOR, RIGHT_ACTUATOR):
        return linear, angular  # none and odometry: commands are untouched
    x_lin = linear[0]
    left = fault == LEFT_ACTUATOR
    right = not left
    yaw = angular[2]
    if (left and x_lin > 0) or (right and x_lin < 0):
        yaw = x_lin
    elif (right and x_lin > 0) or (left and x_lin < 0):
        yaw = -x_lin
    if severity >= 1.0:
        return (x_lin / 2.0, linear[1], linear[2]), (angular[0], angular[1], yaw)
    kept = 1.0 - severity
    return ((kept * x_lin + severity * x_lin / 2.0, linear[1], linear[2]),
            (angular[0], angular[1], kept * angular[2] + severity * yaw))


class OdometryFreezer(object):
    """Remembers the last odometry and, while frozen, keeps returning it.

    Values are opaque (a message, a tuple...): the freezer only stores them.
    """

    def __init__(self):
        self._last = None
        self._frozen = None
        self._active = False

    @property
    def active(self):
        """True while freezing."""
        return self._active

    @property
    def last(self):
        """The last value received, or None."""
        return self._last

    @property
    def frozen(self):
        """The value being repeated, or None (not freezing, or nothing received yet)."""
        return self._frozen

    def freeze(self):
        """Start freezing at the last value received.

        Freezing again while already frozen keeps the original value, so a
        repeated request does not "refresh" the stuck odometry.
        """
        if not self._active:
            self._active = True
            self._frozen = self._last

    def release(self):
        """Stop freezing: values pass through again."""
        self._active = False
        self._frozen = None

    def filter(self, value):
        """Record a new value and return the one to pass on.

        :param value: the odometry just received
        :return: ``value`` when not freezing; otherwise the frozen value (the
            first value received after the fault if none had arrived before)
        """
        self._last = value
        if not self._active:
            return value
        if self._frozen is None:
            self._frozen = value
        return self._frozen


class FaultState(object):
    """The active fault and what it does to commands and odometry.

    Not thread-safe: the node serialises calls with a lock.

    :param initial: the fault active at start-up (any of :data:`VALID_REQUESTS`)
    :param severity: of the actuator faults, in (0, 1] (1: the thesis's)
    :raises UnknownFaultError: if ``initial`` is not valid
    :raises ValueError: if ``severity`` is not in (0, 1]
    """

    def __init__(self, initial=NONE, severity=1.0):
        self._fault = NONE
        self.severity = check_severity(severity)
        self.odometry = OdometryFreezer()
        parse_fault(initial)  # raises, where request() would only report
        self.request(initial)

    @property
    def fault(self):
        """The active fault: one of :data:`FAULTS` or :data:`NONE`."""
        return self._fault

    def request(self, name):
        """Handle a service request.

        :param name: the requested fault, ``cancel`` or ``none``
        :return: ``(ok, message)``; on failure the state is unchanged
        """
        try:
            fault = parse_fault(name)
        except UnknownFaultError as e:
            return False, '%s; active fault unchanged: %s' % (e, self._fault)
        self._fault = fault
        if fault == ODOMETRY:
            self.odometry.freeze()
        else:
            self.odometry.release()
        if fault == NONE:
            return True, 'no active fault (pass-through)'
        return True, 'active fault: %s' % fault

    def twist(self, linear, angular):
        """Transform a velocity command under the active fault.

        :param linear: ``(x, y, z)`` commanded linear velocity
        :param angular: ``(x, y, z)`` commanded angular velocity
        :return: ``(linear, angular)`` for the base
        """
        return transform_twist(self._fault, linear, angular, self.severity)

    def odom(self, value):
        """Pass an odometry value through the freezer.

        :param value: the odometry just received (opaque)
        :return: the value to publish
        """
        return self.odometry.filter(value)


def is_motion_command(linear, angular):
    """True when a velocity command asks the base to move (a non-zero speed).

    NaN is not a motion: it compares false, like in :func:`transform_twist`.

    :param linear: ``(x, y, z)``
    :param angular: ``(x, y, z)``
    """
    return any(v != 0.0 and not math.isnan(v) for v in tuple(linear) + tuple(angular))


_TIME_EPSILON = 1e-6  # s: far below any clock step


class MidMissionFault(object):
    """A fault injected some time after the mission starts (``fault_at``), rather than at
    start-up: the mission starts with the first command that moves the robot.

    :param fault: the fault to inject later (one of :data:`FAULTS`)
    :param delay: seconds after the first motion command (> 0, finite)
    :raises UnknownFaultError: an unknown fault, or ``none``
    :raises ValueError: a delay that is not a positive finite number
    """

    def __init__(self, fault, delay):
        self.fault = parse_fault(fault)
        if self.fault == NONE:
            raise UnknownFaultError('a fault to inject mid-mission must be one of %s'
                                    % ', '.join(FAULTS))
        delay = float(delay)
        if not (delay > 0 and math.isfinite(delay)):
            raise ValueError('fault_at must be a positive number of seconds, got %r' % delay)
        self.delay = delay
        self.started = None     # time of the first motion command
        self.injected = False

    def on_command(self, linear, angular, now):
        """Note a velocity command; returns the time at which to inject when this command
        starts the mission, else None.

        :param now: seconds
        """
        if self.started is not None or not is_motion_command(linear, angular):
            return None
        self.started = float(now)
        return self.started + self.delay

    def due(self, now):
        """The fault to inject now, once (None before its time and after). A clock in float
        seconds read at the very step the fault is due may come out a hair short of
        started + delay (3.31 + 2.0 is 5.3100000000000005): that counts as due."""
        if self.injected or self.started is None or now + _TIME_EPSILON < self.started + self.delay:
            return None
        self.injected = True
        return self.fault

    def waiting(self, now):
        """Seconds until the fault is due (> 0), or None when there is nothing to wait for
        (no mission yet, due now, or injected)."""
        if self.injected or self.started is None:
            return None
        left = self.started + self.delay - now
        return left if left > _TIME_EPSILON else None
