"""Motion decomposition core (thesis §5.3, §6.3; issue 15): plain Python, no rospy (only
the protocol's words from the generated ``rason_msgs.msg.Event``).

Turns the agents' motion actions into velocity commands and decides, from poses, when a
motion has ended and how:

``move(Metres)``, ``turn(Degrees)``
    straight ahead (behind for Metres < 0) and on the spot: :class:`MotionMonitor`;
``goto(X, Y)``
    to the point (X, Y) m of the pose source's frame, any final heading:
    :class:`motion_decomp.goto.GotoController`, OK within ``goto_tolerance``;
``compensate(Side, Gain)``
    a setting: later ``goto`` and ``move`` drive a base whose forward commands pick up the
    curvature ``Gain`` (rad/m; ``left`` counter-clockwise, ``right`` clockwise, ``none``
    normal driving) in planned arcs (:mod:`motion_decomp.arc`); a ``move(D)`` is then a
    goto to the point D m ahead of where it starts, without the ``bad_move`` check;
``pose_source(Name)``, ``pose_source(guided, Topic)``
    a setting: later motions use the odometry (``odom``) or a fresh guided pose
    (``guided``, :mod:`motion_decomp.pose_source`) and, while guided, the guided speeds;
    ``Topic`` names where the guided poses come from (a robot of a fleet guided by whichever
    robot watches it), instead of the node's ``guided_pose``.

All of them wait in one FIFO (:class:`MotionScheduler`): a setting takes effect, and answers
OK, when its turn comes, so the motions queued before it run with the old setting.

SIGN CONVENTION OF ``turn`` -- read this first
    ``turn(D)`` with D > 0 turns the robot RIGHT (clockwise seen from above),
    i.e. it commands a NEGATIVE ``angular.z``; D < 0 turns LEFT (positive
    ``angular.z``). This is the opposite of the ROS convention (REP 103, where a
    positive angle is counter-clockwise) on purpose: the agent programs call
    ``turn(Deg)`` with the angle at which they see the other robot, and that
    angle is negative when the robot is on the left. So ``turn(Deg)`` faces it.

``move(M)`` drives straight ahead for M > 0 and backwards for M < 0.

Poses are ``(x, y, yaw)`` tuples (metres, metres, radians, ROS frame
conventions); times are floats in seconds. The node feeds ROS time, so
simulated time works.

Results (``parameters[0]`` of the ``Event.ACTION_FEEDBACK`` event), spelled by the
constants of ``rason_msgs/Event`` (``Event.OK``, ``Event.NO_PROGRESS``, ...):

``OK``
    the travelled distance (straight line from the start pose) or the turned
    angle (unwrapped, so ``turn(360)`` works) reached the request; a ``goto`` (or a
    compensated ``move``) is within ``goto_tolerance`` of its point; a setting took effect.
``no_progress``
    the pose has not changed (< 1 mm and < 0.1 degree) for more than
    ``no_progress_time`` seconds while motion was wanted. This also covers "no
    odometry at all": without a start pose no motion is commanded (we could not
    tell how far the robot went) and the action fails ``no_progress`` after
    ``no_progress_time``.
``bad_move``
    during a move (not a compensated one), the cosine between the planned direction (start heading,
    reversed for a backward move) and the displacement start->current fell
    below ``bad_move_min_cos``; checked once the robot moved at least
    ``bad_move_min_distance`` metres, before which the direction is noise.
``bad_parameters``
    missing, extra, non-numeric or non-finite parameter (``move``, ``turn``: one number;
    ``goto``: two), a side other than ``left``, ``right``, ``none``, a gain below 0 or above
    ``MAX_GAIN``, a pose source other than ``odom``, ``guided``; fails at once.
``timeout``
    the motion ran ``max_duration`` seconds without another result.
``shutdown``
    the node stopped before the motion ended.
``cancelled``
    the motion was taken back (``Action.CANCEL``, or the agent's link is gone) while queued
    or running: :meth:`MotionScheduler.cancel`; a running motion is commanded zero at once.
"""
import math
import re
from collections import deque, namedtuple

# Only the generated message class (genpy), for the protocol's words: no rospy here.
from rason_msgs.msg import Event

from motion_decomp import goto
from motion_decomp.arc import ArcSteering
from motion_decomp.geometry import (PROGRESS_ANGLE, PROGRESS_DISTANCE,  # noqa: F401 (API)
                                    is_finite_pose, wrap_angle, yaw_from_quaternion)
from motion_decomp.pose_source import GUIDED, ODOM, POSE_SOURCES, select_pose

MOVE = 'move'
TURN = 'turn'
GOTO = 'goto'
COMPENSATE = 'compensate'
POSE_SOURCE = 'pose_source'
#: The action functors this decomposer executes; all others belong to other decomposers.
MOTION_ACTIONS = (MOVE, TURN, GOTO, COMPENSATE, POSE_SOURCE)
#: The actions that change how later motions run instead of moving the robot.
SETTINGS = (COMPENSATE, POSE_SOURCE)

#: ``compensate``'s sides: the sign of the curvature (REP 103: counter-clockwise positive).
SIDES = {'left': 1.0, 'right': -1.0, 'none': 0.0}
#: The largest accepted gain (rad/m): a 5 cm turning radius. A Kobuki with one wheel
#: stopped turns about it, at half its 0.23 m wheel base: 8.7 rad/m; the thesis's model 2.
MAX_GAIN = 20.0

#: Turn rate per radian still to turn (1/s) over a turn's last degrees, down to
#: ``goto.MIN_ANGULAR``: at full speed to the end, odometry or a control cycle that comes
#: late overshoots by angular_speed times the delay (at real-time factor 0 on a loaded CPU,
#: 3–9 degrees of a 10-degree turn, so a robot the helper turned to centre was off-centre
#: the other way again). From 7 degrees before the end at 0.5 rad/s.
TURN_GAIN = 4.0

#: Default tuning; speeds like a TurtleBot 2 (Kobuki max 0.7 m/s, comfortable 0.2 m/s).
DEFAULTS = dict(
    linear_speed=0.2,           # m/s
    angular_speed=0.5,          # rad/s
    no_progress_time=1.0,       # s
    bad_move_min_distance=0.05,  # m
    bad_move_min_cos=0.99,      # cos(8.1 degrees)
    max_duration=50.0,          # s; below the bridge's 60 s action timeout, so the agent gets this reason
    goto_tolerance=0.05,        # m: goto (and a compensated move) is OK this close to its point
    segment_length=0.3,         # m: the longest arc of compensated driving (see arc.py)
    guided_linear_speed=0.1,    # m/s and rad/s while the pose source is guided: the guided
    guided_angular_speed=0.3,   # pose comes ~0.2 s late at ~10 Hz, slower is more precise
    guided_max_age=0.5,         # s: an older guided pose is no pose
)

#: A requested motion: ``kind`` is MOVE (``amount`` in metres) or TURN (``amount`` in degrees).
Motion = namedtuple('Motion', 'kind amount')


class Goto(namedtuple('Goto', 'x y')):
    """``goto(X, Y)``: the point, metres in the pose source's frame."""
    __slots__ = ()
    kind = GOTO


class Compensation(namedtuple('Compensation', 'side gain')):
    """``compensate(Side, Gain)``: ``side`` one of :data:`SIDES`, ``gain`` rad/m >= 0."""
    __slots__ = ()
    kind = COMPENSATE

    @property
    def curvature(self):
        """Signed rad/m, counter-clockwise positive; 0 means normal driving."""
        return SIDES[self.side] * self.gain


class PoseSourceSetting(namedtuple('PoseSourceSetting', 'name topic')):
    """``pose_source(Name)``: ``name`` one of :data:`POSE_SOURCES`; ``topic`` the guided
    poses' topic of ``pose_source(guided, Topic)``, ``None`` for the node's own."""
    __slots__ = ()
    kind = POSE_SOURCE

    def __new__(cls, name, topic=None):
        return super(PoseSourceSetting, cls).__new__(cls, name, topic)


#: Normal driving: what ``compensate(none, 0)`` sets.
NO_COMPENSATION = Compensation('none', 0.0)

#: What to publish on jason/event: parameters are ``[result, str(action_id)]``.
Feedback = namedtuple('Feedback', 'agent action_id result')

# A plain decimal number, as Jason prints it ("1", "-0.3", "1.0E-4"); float()
# alone would also take "nan", "inf", "1_0" and surrounding blanks.
_NUMBER = re.compile(r'[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?\Z')
# A ROS topic name, global or relative (no ~: a private name would be the decomposer's own).
_TOPIC = re.compile(r'/?[A-Za-z][A-Za-z0-9_]*(?:/[A-Za-z][A-Za-z0-9_]*)*\Z')


class UnknownAction(ValueError):
    """The action is not a motion; another decomposer may handle it."""


class BadParameters(ValueError):
    """The parameters of a motion action are unusable; the message says why."""


def is_motion(action):
    """True for the action functors this decomposer handles.

    :param action: action functor, e.g. ``move``
    """
    return action in MOTION_ACTIONS


def _number(action, text):
    # one parameter as a finite float, or BadParameters
    if not isinstance(text, str) or not _NUMBER.match(text):
        raise BadParameters('%s(%r): the parameter is not a number' % (action, text))
    value = float(text)
    if not math.isfinite(value):  # e.g. "1e999"
        raise BadParameters('%s(%r): the parameter is not finite' % (action, text))
    return value


def parse_motion(action, parameters):
    """Read a motion action (any of :data:`MOTION_ACTIONS`).

    :param action: the functor
    :param parameters: the action's arguments as text (numbers as Jason prints them, atoms bare)
    :returns: a :class:`Motion` (``move``, ``turn``), :class:`Goto`, :class:`Compensation` or
        :class:`PoseSourceSetting`; each has a ``kind``, the functor
    :raises UnknownAction: the functor is not a motion
    :raises BadParameters: wrong arity, not a number, NaN or infinite, an unknown side or pose
        source, a gain out of [0, MAX_GAIN]
    """
    if not is_motion(action):
        raise UnknownAction('%r is not a motion action (only %s)' % (action, ', '.join(MOTION_ACTIONS)))
    parameters = list(parameters)
    arity = 2 if action in (GOTO, COMPENSATE) else 1
    if action == POSE_SOURCE and len(parameters) == 2 and parameters[0] == GUIDED:
        if not isinstance(parameters[1], str) or not _TOPIC.match(parameters[1]):
            raise BadParameters('pose_source(guided, %r): not a topic name' % (parameters[1],))
        return PoseSourceSetting(GUIDED, parameters[1])
    if len(parameters) != arity:
        raise BadParameters('%s needs exactly %d parameter(s), got %d: %r'
                            % (action, arity, len(parameters), parameters))
    if action == GOTO:
        return Goto(_number(action, parameters[0]), _number(action, parameters[1]))
    if action == COMPENSATE:
        side, gain = parameters[0], _number(action, parameters[1])
        if side not in SIDES:
            raise BadParameters('compensate(%r, ...): the side is not one of %s'
                                % (side, ', '.join(sorted(SIDES))))
        if not 0 <= gain <= MAX_GAIN:
            raise BadParameters('compensate(..., %r): the gain (rad/m) is not in [0, %g]'
                                % (parameters[1], MAX_GAIN))
        return Compensation(side, gain)
    if action == POSE_SOURCE:
        if parameters[0] not in POSE_SOURCES:
            raise BadParameters('pose_source(%r): not one of %s'
                                % (parameters[0], ', '.join(POSE_SOURCES)))
        return PoseSourceSetting(parameters[0])
    return Motion(action, _number(action, parameters[0]))


def check_options(options):
    """Validate monitor tuning; returns the full option dict (defaults filled in).

    :param options: dict with keys of :data:`DEFAULTS`
    :raises ValueError: unknown key or out-of-range value
    """
    unknown = set(options) - set(DEFAULTS)
    if unknown:
        raise ValueError('unknown motion option(s): %s' % ', '.join(sorted(unknown)))
    full = dict(DEFAULTS)
    full.update((k, float(v)) for k, v in options.items())
    for key in ('linear_speed', 'angular_speed', 'no_progress_time', 'max_duration', 'goto_tolerance',
                'segment_length', 'guided_linear_speed', 'guided_angular_speed', 'guided_max_age'):
        if not (full[key] > 0 and math.isfinite(full[key])):
            raise ValueError('%s must be a positive number, got %r' % (key, full[key]))
    if not 0 <= full['bad_move_min_distance'] < float('inf'):
        raise ValueError('bad_move_min_distance must be >= 0, got %r' % full['bad_move_min_distance'])
    if not -1 <= full['bad_move_min_cos'] <= 1:
        raise ValueError('bad_move_min_cos must be in [-1, 1], got %r' % full['bad_move_min_cos'])
    return full


class MotionMonitor(object):
    """Runs one motion: what to command, and when and how it ends.

    Call :meth:`update` on every control cycle with the latest pose (the same
    pose again when no new odometry came, ``None`` while there is none), then
    publish :meth:`command`.

    :param motion: the :class:`Motion` to perform
    :param start_pose: ``(x, y, yaw)`` when the motion starts, or ``None`` when
        no odometry was received yet (the first pose given to :meth:`update`
        then becomes the start pose)
    :param now: start time, seconds
    :param options: tuning, keys of :data:`DEFAULTS` (speeds, thresholds, ``max_duration``)
    """

    def __init__(self, motion, start_pose, now, **options):
        opts = check_options(options)
        self.motion = motion
        self.linear_speed = opts['linear_speed']
        self.angular_speed = opts['angular_speed']
        self.no_progress_time = opts['no_progress_time']
        self.bad_move_min_distance = opts['bad_move_min_distance']
        self.bad_move_min_cos = opts['bad_move_min_cos']
        self.max_duration = opts['max_duration']
        self.started = float(now)
        self.start_pose = None
        #: distance start->current (move) or signed unwrapped yaw change (turn, radians)
        self.travelled = 0.0
        self.turned = 0.0
        self.result = None
        self._prev_yaw = None
        self._still_pose = None
        self._still_since = self.started
        self._has_pose = False      # the last update had a pose: only then is a command given
        if start_pose is not None and is_finite_pose(start_pose):
            self._begin(start_pose, now)

    @property
    def done(self):
        """True once a result is known."""
        return self.result is not None

    def _begin(self, pose, now):
        self.start_pose = tuple(float(v) for v in pose)
        self._has_pose = True
        self._prev_yaw = self.start_pose[2]
        self._still_pose = self.start_pose
        # The robot is only commanded from now on, so progress is expected from now.
        self._still_since = now

    def _direction(self):
        # +1/-1: sign of the wanted speed; a positive turn is clockwise (negative yaw rate).
        sign = 1.0 if self.motion.amount >= 0 else -1.0
        return sign if self.motion.kind == MOVE else -sign

    def update(self, pose, now):
        """Take the latest odometry pose; returns ``None`` while running, else the result.

        Once ended, the same result is returned again.

        :param pose: ``(x, y, yaw)``, or ``None`` (no odometry yet); non-finite poses are ignored
        :param now: current time, seconds
        :returns: ``None``, ``OK``, ``no_progress``, ``bad_move`` or ``timeout``
        """
        if self.result is not None:
            return self.result
        if self.motion.amount == 0:  # nothing to do, with or without odometry
            return self._end(Event.OK)
        if pose is not None and not is_finite_pose(pose):
            pose = None
        self._has_pose = pose is not None
        if pose is not None:
            if self.start_pose is None:
                self._begin(pose, now)
            result = self._track(pose, now)
            if result is not None:
                return self._end(result)
        if now - self._still_since > self.no_progress_time:
            return self._end(Event.NO_PROGRESS)
        if now - self.started >= self.max_duration:
            return self._end(Event.TIMEOUT)
        return None

    def _track(self, pose, now):
        x, y, yaw = pose
        sx, sy, syaw = self._still_pose
        if (math.hypot(x - sx, y - sy) >= PROGRESS_DISTANCE
                or abs(wrap_angle(yaw - syaw)) >= PROGRESS_ANGLE):
            self._still_pose = (x, y, yaw)
            self._still_since = now
        # Summing small wrapped steps unwraps the yaw (needs < 180 degrees per odometry step).
        self.turned += wrap_angle(yaw - self._prev_yaw)
        self._prev_yaw = yaw

        x0, y0, yaw0 = self.start_pose
        dx, dy = x - x0, y - y0
        self.travelled = math.hypot(dx, dy)
        if self.motion.kind == MOVE:
            if self.travelled >= max(self.bad_move_min_distance, 1e-9):
                d = self._direction()
                cos = d * (dx * math.cos(yaw0) + dy * math.sin(yaw0)) / self.travelled
                if cos < self.bad_move_min_cos:
                    return Event.BAD_MOVE
            if self.travelled >= abs(self.motion.amount):
                return Event.OK
        else:
            if self.turned * self._direction() >= math.radians(abs(self.motion.amount)):
                return Event.OK
        return None

    def _end(self, result):
        self.result = result
        return result

    def command(self):
        """The velocity to command now: ``(linear_x, angular_z)`` in m/s and rad/s.

        Zero before the start pose is known, after an update without a pose (no odometry, a
        stale guided pose: no driving blind) and after the end.
        """
        if self.result is not None or not self._has_pose or self.motion.amount == 0:
            return (0.0, 0.0)
        if self.motion.kind == MOVE:
            return (self._direction() * self.linear_speed, 0.0)
        left = max(math.radians(abs(self.motion.amount)) - self.turned * self._direction(), 0.0)
        return (0.0, self._direction() * goto.toward(left, TURN_GAIN, goto.MIN_ANGULAR, self.angular_speed))


#: goto's words -> the protocol's
_GOTO_RESULTS = {goto.SUCCEEDED: Event.OK, goto.NO_PROGRESS: Event.NO_PROGRESS,
                 goto.TIMEOUT: Event.TIMEOUT}


class GotoMotion(object):
    """A ``goto`` (or a compensated ``move``) run by a :class:`~motion_decomp.goto.GotoController`,
    answered in the protocol's words: the same ``update``/``command`` as :class:`MotionMonitor`.

    :param controller: the :class:`~motion_decomp.goto.GotoController`
    """

    def __init__(self, controller):
        self.controller = controller

    @property
    def done(self):
        return self.controller.done

    def update(self, pose, now):
        """As :meth:`MotionMonitor.update`: ``None`` while driving, else ``OK``,
        ``no_progress`` or ``timeout``."""
        result = self.controller.update(pose, now)
        return None if result is None else _GOTO_RESULTS[result]

    def command(self):
        """``(linear_x, angular_z)``: zero without a pose and after the end."""
        return self.controller.command()


def point_ahead(metres):
    """A goal function for :class:`~motion_decomp.goto.GotoController`: the point ``metres``
    ahead of the first pose (behind for a negative distance), any final heading."""
    def goal(pose):
        x, y, yaw = pose
        return goto.Goal(x + metres * math.cos(yaw), y + metres * math.sin(yaw), None)
    return goal


_Request = namedtuple('_Request', 'agent action_id motion')


class MotionScheduler(object):
    """One motion at a time per robot; later motions, and settings, wait in a FIFO queue.

    The settings (``compensate``, ``pose_source``) apply when their turn comes, in the
    :meth:`step` that takes them from the queue, and are answered OK there.

    :param options: tuning, keys of :data:`DEFAULTS`
    :raises ValueError: bad options
    """

    def __init__(self, **options):
        self.options = check_options(options)
        self._queue = deque()
        self.current = None     # (request, MotionMonitor or GotoMotion) or None
        self.compensation = NO_COMPENSATION
        self.pose_source = ODOM
        self.guided_topic = None    # pose_source(guided, Topic)'s topic; None: the node's own

    @property
    def pending(self):
        """Number of motions waiting behind the running one."""
        return len(self._queue)

    def submit(self, agent, action_id, action, parameters):
        """Queue a motion action.

        :param agent: the acting agent, echoed in the feedback
        :param action_id: echoed in the feedback
        :param action: one of :data:`MOTION_ACTIONS`
        :param parameters: the action's arguments as text
        :returns: a :class:`Feedback` to publish at once (``bad_parameters``), or ``None`` when queued
        :raises UnknownAction: not a motion action (the caller should ignore it)
        """
        try:
            motion = parse_motion(action, parameters)
        except BadParameters:
            return Feedback(agent, action_id, Event.BAD_PARAMETERS)
        self._queue.append(_Request(agent, action_id, motion))
        return None

    def pose(self, odom, guided, now):
        """The pose the motions use now, from the present pose source.

        :param odom: the latest odometry ``(x, y, yaw)`` or ``None``
        :param guided: the latest guided :class:`~motion_decomp.pose_source.StampedPose` or ``None``
        :param now: seconds
        """
        return select_pose(self.pose_source, odom, guided, now, self.options['guided_max_age'])

    def step(self, pose, now, guided=None):
        """One control cycle.

        Starts the next queued motion when idle (or applies the next setting); at most one
        motion ends per cycle, so the stop command of an end is never skipped.

        :param pose: latest odometry ``(x, y, yaw)`` or ``None``
        :param now: current time, seconds
        :param guided: the latest guided :class:`~motion_decomp.pose_source.StampedPose` or
            ``None``; used instead of ``pose`` while the pose source is ``guided``
        :returns: ``(command, feedback)``: ``command`` is ``(linear_x, angular_z)`` to
            publish, ``(0.0, 0.0)`` when a motion just ended, ``None`` when idle or when a
            setting took effect (publish nothing, other nodes may drive); ``feedback`` is a
            :class:`Feedback` or ``None``
        """
        pose = self.pose(pose, guided, now)
        if self.current is None:
            if not self._queue:
                return None, None
            request = self._queue.popleft()
            if request.motion.kind in SETTINGS:
                self._apply(request.motion)
                return None, Feedback(request.agent, request.action_id, Event.OK)
            self.current = (request, self._start(request.motion, pose, now))
        request, monitor = self.current
        result = monitor.update(pose, now)
        if result is None:
            return monitor.command(), None
        self.current = None
        return (0.0, 0.0), Feedback(request.agent, request.action_id, result)

    def _apply(self, setting):
        if setting.kind == COMPENSATE:
            self.compensation = setting
        else:
            self.pose_source = setting.name
            self.guided_topic = setting.topic

    def motion_options(self):
        """The tuning of a motion starting now: :data:`DEFAULTS` keys, with the guided speeds
        as ``linear_speed``/``angular_speed`` while the pose source is guided."""
        options = dict(self.options)
        if self.pose_source == GUIDED:
            options.update(linear_speed=options['guided_linear_speed'],
                           angular_speed=options['guided_angular_speed'])
        return options

    def _start(self, motion, pose, now):
        # the runner of a motion, under the settings in effect now
        options = self.motion_options()
        curvature = self.compensation.curvature
        if motion.kind == TURN or (motion.kind == MOVE and (curvature == 0 or motion.amount == 0)):
            return MotionMonitor(motion, pose, now, **options)
        goal = (goto.Goal(motion.x, motion.y, None) if motion.kind == GOTO
                else point_ahead(motion.amount))
        steering = ArcSteering(curvature, options['segment_length']) if curvature != 0 else None
        return GotoMotion(goto.GotoController(
            goal, now, steering, linear_speed=options['linear_speed'],
            angular_speed=options['angular_speed'], xy_tolerance=options['goto_tolerance'],
            no_progress_time=options['no_progress_time'], max_duration=options['max_duration']))

    def cancel(self, agent, action_id):
        """Take back motions (an ``Action.CANCEL``): a queued one leaves the queue, the
        running one ends now; the next queued motion starts at the next :meth:`step`.

        :param agent: whose motions
        :param action_id: the motion's id, or 0: every motion of ``agent``
        :returns: ``(command, feedbacks)``: ``command`` is ``(0.0, 0.0)`` when the running
            motion was stopped (publish it at once), else ``None``; ``feedbacks`` are the
            :class:`Feedback` ``Event.CANCELLED`` of the cancelled motions, the running one
            first, then the queued ones in order (empty for an unknown or finished id)
        """
        def named(request):
            return request.agent == agent and (action_id == 0 or request.action_id == action_id)

        cancelled = []
        command = None
        if self.current is not None and named(self.current[0]):
            cancelled.append(self.current[0])
            self.current = None
            command = (0.0, 0.0)
        kept = deque()
        for request in self._queue:
            (cancelled if named(request) else kept).append(request)
        self._queue = kept
        return command, [Feedback(r.agent, r.action_id, Event.CANCELLED) for r in cancelled]

    def cancel_all(self, reason=Event.SHUTDOWN):
        """End the running and all queued motions; returns their feedback, oldest first.

        :param reason: the failure reason to report
        """
        requests = [self.current[0]] if self.current is not None else []
        requests.extend(self._queue)
        self.current = None
        self._queue.clear()
        return [Feedback(r.agent, r.action_id, reason) for r in requests]
