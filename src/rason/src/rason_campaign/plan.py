"""Run planning: which runs a campaign makes and the launch arguments of each.

Deterministic: the same (faults, runs, seed, options) give the same plan. Each run has its
own seed (``seed * 1000 + run number``) which seeds both the simulator and the run's
jitter of the start poses (about ±5 cm, ±3°) and of the lighting (brightness 0.8-1.2).

``varied`` diagnosis runs (issue 18) are drawn far wider (:func:`varied_args`): any relative
pose 1-3 m apart, Faulty facing away within ±30°, the Helper in any heading, the
camera's depth noise, dropouts, the lighting, the actuator fault's severity and both
robots' wheel slip.

Two scenarios: ``diagnosis`` (the thesis's case study, faulty_helper.launch) and
``fault_tolerance`` (issue 15), where each planned run is made twice with the same seed and
start poses (spread out by :mod:`rason_campaign.poses`): the ``recovery`` arm
(fault_tolerance.launch) and the ``baseline`` arm (faulty_helper.launch: the thesis's
behaviour, diagnose and stop).
"""
import math
import random

from rason_campaign.poses import spread_poses

FAULTS = ('none', 'left_actuator', 'right_actuator', 'both_actuators', 'odometry')

# The nominal poses of faulty_helper.launch (thesis §7: side by side, 1.5 m apart).
NOMINAL = {'helper_x': -1.0, 'helper_y': 0.75, 'helper_yaw': 0.0,
           'faulty_x': -1.0, 'faulty_y': -0.75, 'faulty_yaw': -1.5708}
POSITION_JITTER = 0.05           # metres, uniform ±
YAW_JITTER = math.radians(3.0)   # radians, uniform ±
BRIGHTNESS_RANGE = (0.8, 1.2)

# Varied diagnosis runs (issue 18): ranges of what varied_args draws.
VARIED_DISTANCE = (1.0, 3.0)                 # metres between Helper and Faulty
VARIED_FACING_AWAY = math.radians(30.0)      # Faulty's heading: bearing Helper -> Faulty ± this
VARIED_BRIGHTNESS = (0.6, 1.2)
VARIED_DEPTH_NOISE = (1.0, 2.0)              # times the Kinect's axial noise
VARIED_DEPTH_DROPOUT = (0.0, 0.05)           # probability a depth pixel has no return
# An actuator fault's severity (fault_injector ~severity): 1 the thesis's (the wheel gives
# nothing) down to 0.3, where a 1 m move drifts past bad_move's 8 degrees after ~0.8 m;
# much below it the fault is not noticed within the mission's 1 m moves at all.
VARIED_SEVERITY = (0.3, 1.0)
# Wheel slip (rason_sim <robot>/left_slip, right_slip): each robot's wheels slip by a share
# of their rotation drawn over VARIED_WHEEL_SLIP, the left one up to VARIED_SLIP_DIFFERENCE
# more or less than the right (one floor, two tyres): odometry overestimates the travel by
# up to 5 % and calls straight a path that veers up to 2.5 degrees a metre.
VARIED_WHEEL_SLIP = (0.0, 0.05)
VARIED_SLIP_DIFFERENCE = 0.01

# Interaction faults (thesis §7.5-7.6): faulty_helper.launch's interaction:= argument sets
# them; a jittered argument the interaction sets itself is left out (else it would win).
INTERACTIONS = {
    'none': (),
    'dim': ('brightness',),      # the burnt lamp: a room at 30 % light
    'moved_light': (),           # the light over (2.5, -3) instead of the room's centre
    'occlusion': (),             # Faulty's orange cylinder hidden
    'box': (),                   # a box hides it from Helper's start (occluding_box)
}

# The box of the 'box' interaction stands this far (m) in front of Faulty's orange cylinder,
# on its line of sight from Helper's start: far enough that Faulty, turning on a wheel,
# does not touch it.
BOX_IN_FRONT = 0.5
MARKER_SEPARATION = 0.227   # rason_sim's kMarkerSeparation: between the side cylinders' axes


SCENARIOS = ('diagnosis', 'fault_tolerance', 'fleet')  # fleet: rason_campaign.fleet_plan
# Arm of a fault-tolerance run -> the launch file it runs; a diagnosis run has no arm.
ARMS = ('recovery', 'baseline')
LAUNCHES = {None: 'faulty_helper.launch', 'recovery': 'fault_tolerance.launch',
            'baseline': 'faulty_helper.launch',
            # the fleet campaign's arms (rason_campaign.fleet_plan): how helpers are chosen
            'contract_net': 'fleet_case_study.launch', 'broadcast': 'fleet_case_study.launch'}


class PlanError(ValueError):
    """The campaign's options do not make a plan; the message says why."""


class RunSpec(object):
    """One run: its number (1-based, over the whole campaign; both arms of a fault-tolerance
    run share it), fault, seed, the launch arguments (without record/bag, which the runner
    adds) and, in the fault-tolerance scenario, its arm (``recovery`` or ``baseline``)."""

    def __init__(self, number, fault, seed, args, arm=None):
        self.number = number
        self.fault = fault
        self.seed = seed
        self.args = args
        self.arm = arm

    @property
    def name(self):
        """File-name stem of the run, e.g. ``007_left_actuator_1007`` or
        ``007_left_actuator_1007_baseline``."""
        stem = '%03d_%s_%d' % (self.number, self.fault, self.seed)
        return stem if self.arm is None else '%s_%s' % (stem, self.arm)

    @property
    def launch(self):
        """(package, launch file) the run starts."""
        return ('rason', LAUNCHES[self.arm])

    def to_dict(self):
        d = {'number': self.number, 'fault': self.fault, 'seed': self.seed,
             'args': dict(self.args)}
        if self.arm is not None:  # a diagnosis run's dict stays what it was
            d['arm'] = self.arm
        return d

    @classmethod
    def from_dict(cls, d):
        return cls(d['number'], d['fault'], d['seed'], dict(d['args']), d.get('arm'))

    def __eq__(self, other):
        return isinstance(other, RunSpec) and self.to_dict() == other.to_dict()

    def __repr__(self):
        return 'RunSpec(%r)' % self.to_dict()


def parse_faults(text):
    """``all`` or a comma-separated list of FAULTS -> tuple of faults, in the order given.

    :raises PlanError: on an unknown or repeated fault.
    """
    if text.strip() == 'all':
        return FAULTS
    faults = tuple(f.strip() for f in text.split(',') if f.strip())
    unknown = [f for f in faults if f not in FAULTS]
    if unknown or not faults:
        raise PlanError('unknown fault(s) %s; expected all or some of %s'
                        % (', '.join(unknown) or '(none given)', ', '.join(FAULTS)))
    if len(set(faults)) != len(faults):
        raise PlanError('a fault is repeated in %r' % text)
    return faults


def jittered_args(seed, jitter=True):
    """Start poses and brightness for one run, drawn from ``random.Random(seed)``.

    :rtype: dict of launch argument -> value (floats rounded to what the launch needs)
    """
    args = dict(NOMINAL)
    args['brightness'] = 1.0
    if not jitter:
        return args
    rng = random.Random(seed)
    for robot in ('helper', 'faulty'):
        args[robot + '_x'] = round(NOMINAL[robot + '_x'] + rng.uniform(-1, 1) * POSITION_JITTER, 4)
        args[robot + '_y'] = round(NOMINAL[robot + '_y'] + rng.uniform(-1, 1) * POSITION_JITTER, 4)
        args[robot + '_yaw'] = round(NOMINAL[robot + '_yaw'] + rng.uniform(-1, 1) * YAW_JITTER, 4)
    args['brightness'] = round(rng.uniform(*BRIGHTNESS_RANGE), 3)
    return args


def varied_args(seed):
    """Start poses, lighting, camera noise, fault severity and wheel slip of one varied
    run, a pure function of its seed: poses by :func:`rason_campaign.poses.spread_poses`
    over VARIED_DISTANCE and VARIED_FACING_AWAY (Helper in any heading), the rest uniform
    over its VARIED_ range (the severity matters only to an actuator fault).

    :rtype: dict of launch argument -> value
    """
    args = spread_poses(seed, VARIED_DISTANCE, VARIED_FACING_AWAY)
    rng = random.Random('varied %d' % seed)  # its own stream: the poses stay spread_poses's
    args['brightness'] = round(rng.uniform(*VARIED_BRIGHTNESS), 3)
    args['depth_noise'] = round(rng.uniform(*VARIED_DEPTH_NOISE), 3)
    args['depth_dropout'] = round(rng.uniform(*VARIED_DEPTH_DROPOUT), 4)
    args['severity'] = round(rng.uniform(*VARIED_SEVERITY), 3)
    for robot in ('helper', 'faulty'):
        slip = rng.uniform(*VARIED_WHEEL_SLIP)
        half_difference = rng.uniform(-1, 1) * VARIED_SLIP_DIFFERENCE / 2
        args[robot + '_left_slip'] = round(max(0.0, slip + half_difference), 4)
        args[robot + '_right_slip'] = round(max(0.0, slip - half_difference), 4)
    return args


def occluding_box(args):
    """Where (box_x, box_y) the 'box' interaction puts its box for the start poses in
    ``args``: BOX_IN_FRONT in front of Faulty's orange (right) cylinder on the line from
    Helper's camera to it, so at the start it hides that cylinder from Helper.

    :rtype: dict with box_x, box_y (m, rounded to mm)
    """
    yaw = args['faulty_yaw']
    # the right cylinder: half the separation to the right of Faulty's heading
    rx = args['faulty_x'] + MARKER_SEPARATION / 2.0 * math.sin(yaw)
    ry = args['faulty_y'] - MARKER_SEPARATION / 2.0 * math.cos(yaw)
    dx, dy = rx - args['helper_x'], ry - args['helper_y']
    along = max(0.0, 1.0 - BOX_IN_FRONT / math.hypot(dx, dy))
    return {'box_x': round(args['helper_x'] + along * dx, 3),
            'box_y': round(args['helper_y'] + along * dy, 3)}


def _scene_args(args, interaction, third_marker):
    # what both scenarios add to a run's poses: the box and the third cylinder, left out
    # when not asked for (so such plans are as before)
    if interaction == 'box':
        args.update(occluding_box(args))
    if third_marker:
        args['third_marker'] = 'true'
    return args


def _check_options(runs, interaction, rate):
    # the options both scenarios share; raises PlanError
    if runs < 1:
        raise PlanError('--runs must be at least 1, got %d' % runs)
    if interaction not in INTERACTIONS:
        raise PlanError('unknown interaction fault %r; expected one of %s'
                        % (interaction, ', '.join(INTERACTIONS)))
    if rate < 0:
        raise PlanError('--rate must be >= 0, got %s' % rate)


def make_plan(faults, runs, seed, interaction='none', rate=1.0, images=False, jitter=True,
              varied=False, third_marker=False):
    """The campaign's runs: ``runs`` per fault, faults in the order given, run numbers
    1..len(faults)*runs, run seed ``seed * 1000 + number``; start poses and lighting
    jittered about the thesis's (:func:`jittered_args`), nominal (``jitter`` False) or, with
    ``varied``, drawn by :func:`varied_args`.

    The run's ``interaction`` argument names the interaction fault; ``dim`` drops the
    jittered brightness. ``third_marker`` gives Faulty its third cylinder in every run
    (launch argument ``third_marker:=true``; left out otherwise, so such plans are as
    before).

    :rtype: list of RunSpec
    :raises PlanError: on bad options.
    """
    _check_options(runs, interaction, rate)
    if varied and not jitter:
        raise PlanError('varied runs are not nominal: --varied goes without --no-jitter')
    plan = []
    for fault in faults:
        for _ in range(runs):
            number = len(plan) + 1
            run_seed = seed * 1000 + number
            args = varied_args(run_seed) if varied else jittered_args(run_seed, jitter)
            for name in INTERACTIONS[interaction]:
                del args[name]
            args.update({'fault': fault, 'seed': run_seed, 'rate': rate,
                         'interaction': interaction,
                         'images': 'true' if images else 'false'})
            _scene_args(args, interaction, third_marker)
            plan.append(RunSpec(number, fault, run_seed, args))
    return plan


def make_mission_plan(faults, runs, seed, fault_at=0.0, interaction='none', rate=1.0,
                      images=False, third_marker=False):
    """The fault-tolerance campaign's runs: ``runs`` per fault, each made in both ARMS one
    after the other (recovery first) with the same seed ``seed * 1000 + k`` and the same
    start poses, drawn by :func:`rason_campaign.poses.spread_poses` from that seed.

    :param fault_at: seconds after Faulty first moves at which the fault is injected
        (0: at the start), in both arms
    :param third_marker: Faulty carries its third cylinder in every run
    :rtype: list of RunSpec (2 * len(faults) * runs)
    :raises PlanError: on bad options.
    """
    _check_options(runs, interaction, rate)
    if not fault_at >= 0 or math.isinf(fault_at):  # also refuses NaN
        raise PlanError('--fault-at must be a number of seconds >= 0, got %s' % fault_at)
    plan = []
    number = 0
    for fault in faults:
        for _ in range(runs):
            number += 1
            run_seed = seed * 1000 + number
            args = spread_poses(run_seed)
            args.update({'fault': fault, 'fault_at': fault_at, 'seed': run_seed, 'rate': rate,
                         'interaction': interaction, 'images': 'true' if images else 'false'})
            _scene_args(args, interaction, third_marker)
            plan += [RunSpec(number, fault, run_seed, dict(args), arm) for arm in ARMS]
    return plan


def launch_arguments(spec, bag):
    """roslaunch's ``name:=value`` arguments of the run, recording to ``bag``.

    :rtype: list of str
    """
    args = dict(spec.args, record='true', bag=bag)
    if spec.launch[1] != 'fleet_case_study.launch':  # the fleet's has no dialogue node
        # no dialogue node: the bag holds the messages it would print (saves ~0.4 s CPU a run)
        args['dialogue'] = 'false'
    return ['%s:=%s' % (k, args[k]) for k in sorted(args)]
