"""The view's pictures: the messages as a sequence diagram and the fleet's map, laid out from
the view (:mod:`rason_dashboard.sequence`, :mod:`rason_dashboard.fleet_map`)."""
from rason_dashboard.fleet_map import agent_robots, map_layout
from rason_dashboard.sequence import sequence_layout


def with_pictures(view):
    """view with 'sequence' (a lane per agent, in the robots' order) and 'map' (None with no pose)."""
    agents = [a['name'] for r in view['robots'] for a in r['agents']]
    where = agent_robots(view['robots'], view['messages'])
    return dict(view, sequence=sequence_layout(agents, view['messages']),
                map=map_layout(view['poses'], view['bounds'], view['helps'], where))
