"""Randomised start poses of the fault-tolerance campaign (issue 15), a pure function of
the run's seed.

The thesis's set-up (Helper and Faulty side by side 1.5 m apart, Faulty facing away) is
spread out so that each run is a new case: the Helper–Faulty distance is uniform in
1.2–2.2 m, Faulty faces away from the Helper within ±25° (its heading is the bearing from
Helper to Faulty plus up to ±25°), and the Helper's heading is uniform over the circle, so
it has to search for Faulty. Both robots start inside the simulator's 8 × 8 m room, at
least 1.5 m from its walls, so that Faulty's 1 m mission and the Helper's drive past
Faulty to the goal stay off the walls.
"""
import math
import random

ROOM_HALF = 4.0                       # metres: the room of rason_sim's two_robots.yaml, centred
WALL_MARGIN = 1.5                     # metres from any wall, for both robots' starts
DISTANCE_RANGE = (1.2, 2.2)           # metres between Helper and Faulty
FACING_AWAY = math.radians(25.0)      # Faulty's heading: the bearing Helper -> Faulty ± this
DIGITS = 4                            # launch arguments are rounded to 0.1 mm / 0.1 mrad


def wrap(angle):
    """``angle`` (radians) brought into (-pi, pi]."""
    wrapped = math.atan2(math.sin(angle), math.cos(angle))
    return math.pi if wrapped <= -math.pi else wrapped


def spread_poses(seed, distance_range=DISTANCE_RANGE, facing_away=FACING_AWAY):
    """Start poses of one run, drawn from ``random.Random(seed)``.

    The distance and the bearing are drawn first; then the Helper's position is drawn
    uniformly among those that keep both robots inside the margin (for any offset of at
    most 2.2 m that range is not empty), so the distance stays exactly uniform, with no
    rejected draws.

    :param distance_range: (low, high) metres between the robots, high at most 5 m
        (twice the 2.5 m that the margin leaves on each side of the room's centre)
    :param facing_away: radians: Faulty's heading is the bearing Helper -> Faulty ± this
    :rtype: dict with helper_x, helper_y, helper_yaw, faulty_x, faulty_y, faulty_yaw
        (metres, radians in (-pi, pi]), rounded to DIGITS
    """
    rng = random.Random(seed)
    distance = rng.uniform(*distance_range)
    bearing = math.pi - 2 * math.pi * rng.random()          # (-pi, pi]
    dx, dy = distance * math.cos(bearing), distance * math.sin(bearing)
    limit = ROOM_HALF - WALL_MARGIN
    # Helper's coordinate h must satisfy |h| <= limit and |h + d| <= limit.
    hx = rng.uniform(max(-limit, -limit - dx), min(limit, limit - dx))
    hy = rng.uniform(max(-limit, -limit - dy), min(limit, limit - dy))
    faulty_yaw = wrap(bearing + rng.uniform(-facing_away, facing_away))
    helper_yaw = math.pi - 2 * math.pi * rng.random()       # (-pi, pi]: it must search
    poses = {'helper_x': hx, 'helper_y': hy, 'helper_yaw': helper_yaw,
             'faulty_x': hx + dx, 'faulty_y': hy + dy, 'faulty_yaw': faulty_yaw}
    return {k: round(v, DIGITS) for k, v in poses.items()}


def bearing(poses):
    """Bearing (radians) from the Helper to Faulty of a dict like spread_poses returns."""
    return math.atan2(poses['faulty_y'] - poses['helper_y'], poses['faulty_x'] - poses['helper_x'])


def distance(poses):
    """Helper–Faulty distance (metres) of a dict like spread_poses returns."""
    return math.hypot(poses['faulty_x'] - poses['helper_x'], poses['faulty_y'] - poses['helper_y'])
