"""The robots table of a simulated world: which robot carries which coloured cylinders,
read from rason_sim's world file (its parameters ``robots``, and per robot ``markers:
{left: colour, right: colour, back: colour}`` or the flags ``left_marker``,
``right_marker``, ``back_marker``, whose cylinders are then the simulator's default green,
orange and blue). No ROS.

A camera tells two robots apart only if no pair of one's cylinders has the colours of a
pair of the other's: a robot seen from the front shows its left/right pair swapped, so
red/yellow and yellow/red are the same robot to it.
"""
import itertools

from vision_synth.detector import ConfigError

SIDES = ('left', 'right', 'back')

#: The colour of each cylinder a world file puts on without naming it (rason_sim's).
SIM_DEFAULT_COLORS = {'left': 'green', 'right': 'orange', 'back': 'blue'}


def _cylinders(name, spec):
    """side -> colour of the cylinders robot ``name`` of a world file carries."""
    if spec is None:
        spec = {}
    if not isinstance(spec, dict):
        raise ConfigError('world robot %s must be a dictionary, got %r' % (name, spec))
    named = spec.get('markers', {})
    if not isinstance(named, dict) or set(named) - set(SIDES):
        raise ConfigError('world robot %s: markers must be {left: colour, right: colour, '
                          'back: colour}, got %r' % (name, named))
    cylinders = {}
    for side in SIDES:
        on = spec.get(side + '_marker', side in named)
        if not isinstance(on, bool):
            raise ConfigError('world robot %s: %s_marker must be true or false, got %r'
                              % (name, side, on))
        colour = named.get(side, SIM_DEFAULT_COLORS[side])
        if not isinstance(colour, str):
            raise ConfigError('world robot %s: markers/%s must name a colour, got %r'
                              % (name, side, colour))
        if on:
            cylinders[side] = colour
    return cylinders


def robots_from_world(world, exclude=()):
    """``{name: {left: colour, right: colour[, back: colour]}}`` (the detector's ``robots``
    table) of every robot of ``world`` that carries a left and a right cylinder, but those
    named in ``exclude`` (the camera's own robot).

    :param world: a world file's parameters, as loaded (``robots`` list, one dictionary per
        robot)
    :raises ConfigError: a malformed world
    """
    if not isinstance(world, dict) or not isinstance(world.get('robots'), list):
        raise ConfigError('the world needs robots: [names], got %r' % (world,))
    table = {}
    for name in world['robots']:
        if not isinstance(name, str):
            raise ConfigError('world robot names must be strings, got %r' % (name,))
        cylinders = _cylinders(name, world.get(name))
        if name not in exclude and 'left' in cylinders and 'right' in cylinders:
            table[name] = cylinders
    return table


def confusable(robots):
    """Pairs ``(a, b)`` (sorted) of robots a camera cannot tell apart: some two cylinders of
    a have the colours of some two of b's, in either order.

    :param robots: a robots table, ``{name: {left: colour, right: colour[, back: colour]}}``
    """
    pairs = {name: {frozenset(p) for p in itertools.combinations(spec.values(), 2)}
             for name, spec in robots.items()}
    return [(a, b) for a, b in itertools.combinations(sorted(robots), 2) if pairs[a] & pairs[b]]


def world_robots(world, exclude=()):
    """:func:`robots_from_world`, refused when two of its robots are :func:`confusable`
    or none is left.

    :raises ConfigError: a malformed world, robots the camera could take for each other, or
        no robot with two cylinders
    """
    table = robots_from_world(world, exclude)
    if not table:
        raise ConfigError('the world has no robot with a left and a right cylinder to look for')
    clashes = confusable(table)
    if clashes:
        raise ConfigError('the camera cannot tell %s apart: they share two cylinder colours '
                          '(give each robot its own pair in the world file\'s markers)'
                          % ', '.join('%s and %s' % pair for pair in clashes))
    return table


def robot_of_namespace(namespace):
    """The robot a node runs for, from its namespace: ``/r1/`` -> ``r1``; '' at the root."""
    return namespace.strip('/').rsplit('/', 1)[-1]
