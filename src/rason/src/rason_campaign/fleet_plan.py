"""The fleet campaign's runs (issue 34): ``rosrun rason campaign --scenario fleet``.

Each planned run is a fleet of N robots of rason_sim's fleet.yaml (r1, r2, r3 with the camera)
running fleet_case_study.launch with recovery, one or two of them faulty, from start poses
drawn for it; it is made twice with the same seed, poses and faults: robots choosing their
helpers by contract net (the lowest bid) and by the thesis's broadcast (the first to offer).

Deterministic: the same (sizes, runs, seed) give the same plan. Run k (from 1, over the whole
campaign) has seed ``seed * 1000 + k``; its first fault is the four faults in turn, so each
comes up equally often; a second robot is faulty in about half the runs, its fault drawn.
"""
import math
import random

from rason_campaign.plan import PlanError, RunSpec
from rason_campaign.poses import DIGITS, wrap

FLEET_ARMS = ('contract_net', 'broadcast')
FLEET_FAULTS = ('left_actuator', 'right_actuator', 'both_actuators', 'odometry')
SIZES = (4, 6)
MAX_SIZE = 8                  # robots of fleet.yaml
CAMERAS = 3                   # r1, r2 and r3 carry the camera
TWO_FAULTS = 0.5              # share of runs with a second faulty robot
# fleet.yaml puts its robots on a ring round the room's centre, each facing it; a run draws
# where on that ring: one of eight slots 45 degrees apart (which robot stands where), moved
# along the ring by up to SLOT_JITTER, at a radius in RADIUS, facing the centre within
# HEADING_JITTER. Slots at least 29 degrees apart at 2.2 m keep the robots 1.1 m apart.
SLOTS = 8
SLOT_JITTER = math.radians(8.0)
RADIUS = (2.2, 2.7)           # metres: the 8 m room's walls stay 1.3 m behind any robot
HEADING_JITTER = math.radians(15.0)


def robots_of(size):
    """The robots of a fleet of ``size``: r1 ... r<size>."""
    return ['r%d' % k for k in range(1, size + 1)]


def fleet_poses(seed, robots):
    """Start poses of the robots, drawn from the run's seed (see SLOTS).

    :rtype: dict robot -> (x, y, yaw), metres and radians in (-pi, pi], rounded to DIGITS
    """
    rng = random.Random('fleet poses %d' % seed)
    slots = rng.sample(range(SLOTS), len(robots))
    poses = {}
    for robot, slot in zip(robots, slots):
        around = 2 * math.pi * slot / SLOTS + rng.uniform(-SLOT_JITTER, SLOT_JITTER)
        radius = rng.uniform(*RADIUS)
        heading = wrap(around + math.pi + rng.uniform(-HEADING_JITTER, HEADING_JITTER))
        poses[robot] = tuple(round(v, DIGITS) for v in
                             (radius * math.cos(around), radius * math.sin(around), heading))
    return poses


def fleet_faults(seed, robots, index):
    """The faulty robots of run ``index`` (from 0) and their faults.

    :rtype: dict robot -> fault, one or two robots
    """
    rng = random.Random('fleet faults %d' % seed)
    faults = [FLEET_FAULTS[index % len(FLEET_FAULTS)]]
    if rng.random() < TWO_FAULTS:
        faults.append(rng.choice(FLEET_FAULTS))
    return dict(zip(rng.sample(robots, len(faults)), faults))


def poses_argument(poses):
    """fleet_case_study.launch's ``poses`` argument: ``r1:x,y,yaw r2:...``."""
    return ' '.join('%s:%s' % (robot, ','.join('%.*f' % (DIGITS, v) for v in pose))
                    for robot, pose in sorted(poses.items()))


def faults_argument(faults):
    """fleet_case_study.launch's ``faults`` argument: ``r3:left_actuator r5:odometry``."""
    return ' '.join('%s:%s' % pair for pair in sorted(faults.items()))


def fault_label(faults):
    """A run's faults in one word for its name: ``left_actuator+odometry``."""
    return '+'.join(faults[robot] for robot in sorted(faults))


def make_fleet_plan(sizes, runs, seed, rate=0.0):
    """``runs`` runs per fleet size, sizes in the order given, each in both FLEET_ARMS.

    :param rate: the simulator's real-time factor (0: as fast as the lockstep lets it)
    :rtype: list of RunSpec (2 * len(sizes) * runs)
    :raises PlanError: on bad options
    """
    if runs < 1:
        raise PlanError('--runs must be at least 1, got %d' % runs)
    if rate < 0:
        raise PlanError('--rate must be >= 0, got %s' % rate)
    bad = [n for n in sizes if not CAMERAS < n <= MAX_SIZE]
    if bad or not sizes:
        raise PlanError('fleet sizes must be %d to %d robots (fleet.yaml has %d, %d with a '
                        'camera), got %s' % (CAMERAS + 1, MAX_SIZE, MAX_SIZE, CAMERAS,
                                             ', '.join(map(str, bad)) or 'none'))
    plan = []
    number = 0
    for size in sizes:
        robots = robots_of(size)
        for index in range(runs):
            number += 1
            run_seed = seed * 1000 + number
            faults = fleet_faults(run_seed, robots, index)
            args = {'robots': ' '.join(robots), 'faults': faults_argument(faults),
                    'poses': poses_argument(fleet_poses(run_seed, robots)),
                    'seed': run_seed, 'rate': rate, 'recovery': 'true',
                    'end_when_done': 'true'}
            plan += [RunSpec(number, fault_label(faults), run_seed, dict(args, helpers=arm), arm)
                     for arm in FLEET_ARMS]
    return plan


def parse_sizes(text):
    """``4,6`` -> (4, 6).

    :raises PlanError: not a comma-separated list of whole numbers
    """
    try:
        sizes = tuple(int(s) for s in text.split(',') if s.strip())
    except ValueError:
        raise PlanError('--sizes: whole numbers separated by commas, e.g. 4,6; got %r' % text)
    if len(set(sizes)) != len(sizes):
        raise PlanError('--sizes: a size is repeated in %r' % text)
    return sizes
