"""The fleet seen from above: each robot's true pose and believed pose, and an arrow from
each helper to the robot it helps. Pure layout in SVG user units (y down, north up); the page
only draws what it is given."""
import math

from rason_dashboard.poses import robot_of

#: The longer side of the map (SVG units).
SIZE = 440
PAD = 24            # round the world's bounds (SVG units), for the robots' names
HEADING = 0.3       # m: the length of a robot's heading tick
#: A map of one robot at rest still shows this much room (m).
MIN_SPAN = 2.0


def agent_robots(robots, messages):
    """{agent: robot} from the view's robots (an agent runs on the robot its process's
    namespace names: /r1/rason_mas -> r1) and the messages' senders (sender_mas)."""
    where = {}
    for m in messages:
        where.setdefault(m['sender'], robot_of(m.get('sender_mas', '')))
    for r in robots:
        for a in r['agents']:
            where[a['name']] = robot_of(r['mas_id'])
    return where


def _scale(bounds):
    x0, y0, x1, y1 = bounds
    cx, cy = (x0 + x1) / 2.0, (y0 + y1) / 2.0
    w, h = max(x1 - x0, MIN_SPAN), max(y1 - y0, MIN_SPAN)
    k = (SIZE - 2 * PAD) / max(w, h)
    return cx - w / 2.0, cy + h / 2.0, k, w, h


def _line(a, b):
    return {'x1': a[0], 'y1': a[1], 'x2': b[0], 'y2': b[1]}


def map_layout(poses, bounds, helps, where):
    """The map of poses ({robot: {'true', 'believed'}}, either None; a pose {'x', 'y', 'yaw'},
    a believed one with frame 'odom' when its frame is not known in the world) within bounds
    ([min x, min y, max x, max y] m, None: round the poses), with helps ([{'helper', 'helped'}],
    agents) placed by where ({agent: robot}). Returns {'width', 'height', 'metre', 'grid':
    [{'x1', 'y1', 'x2', 'y2'}], 'robots': [{'name', 'true', 'believed'}] (each None or {'x',
    'y', 'hx', 'hy'}: the centre and the heading tick's end; a believed pose also 'frame'),
    'helps': [{'helper', 'helped', 'x1', 'y1', 'x2', 'y2'}]} or None with no pose at all."""
    placed = [p for r in poses.values() for p in (r['true'], r['believed']) if p]
    if not placed:
        return None
    if bounds is None:
        xs, ys = [p['x'] for p in placed], [p['y'] for p in placed]
        bounds = [min(xs) - 1, min(ys) - 1, max(xs) + 1, max(ys) + 1]
    left, top, k, w, h = _scale(bounds)

    def point(x, y):
        return PAD + (x - left) * k, PAD + (top - y) * k

    def mark(p):
        if p is None:
            return None
        x, y = point(p['x'], p['y'])
        hx, hy = point(p['x'] + HEADING * math.cos(p['yaw']), p['y'] + HEADING * math.sin(p['yaw']))
        m = {'x': x, 'y': y, 'hx': hx, 'hy': hy}
        if 'frame' in p:
            m['frame'] = p['frame']
        return m

    robots = [{'name': name, 'true': mark(r['true']), 'believed': mark(r['believed'])}
              for name, r in sorted(poses.items())]
    at = {r['name']: r['true'] or r['believed'] for r in robots}
    arrows = []
    for help_ in helps:
        helper, helped = help_['helper'], help_['helped']
        a, b = at.get(where.get(helper, helper)), at.get(where.get(helped, helped))
        if a and b and a is not b:
            arrows.append({'helper': helper, 'helped': helped, 'x1': a['x'], 'y1': a['y'],
                           'x2': b['x'], 'y2': b['y']})
    grid = []  # a line every metre
    for gx in range(int(math.ceil(left)), int(math.floor(left + w)) + 1):
        grid.append(_line(point(gx, top), point(gx, top - h)))
    for gy in range(int(math.ceil(top - h)), int(math.floor(top)) + 1):
        grid.append(_line(point(left, gy), point(left + w, gy)))
    return {'width': 2 * PAD + w * k, 'height': 2 * PAD + h * k, 'metre': k, 'grid': grid,
            'robots': robots, 'helps': arrows}
