"""The fleet's map: where robots are drawn, their headings, who helps whom (no ROS)."""
import math

import pytest

from rason_dashboard import fleet_map as fm
from rason_dashboard.fleet_map import agent_robots, map_layout


def pose(x, y, yaw=0.0):
    return {'x': x, 'y': y, 'yaw': yaw}


def test_robots_placed_north_up_with_their_headings():
    poses = {'r1': {'true': pose(2, 0, math.pi / 2), 'believed': pose(2.5, 0)},
             'r2': {'true': pose(-2, 0), 'believed': None}}
    m = map_layout(poses, [-3, -3, 3, 3], [], {})
    r1, r2 = m['robots']
    assert (r1['name'], r2['name']) == ('r1', 'r2')
    assert r1['true']['x'] > r2['true']['x'] and r1['true']['y'] == pytest.approx(r2['true']['y'])
    assert r1['true']['hy'] < r1['true']['y'] and r1['true']['hx'] == pytest.approx(r1['true']['x'])  # north: up
    assert r2['true']['hx'] > r2['true']['x']  # east: right
    assert r1['believed']['x'] - r1['true']['x'] == pytest.approx(0.5 * m['metre'])
    assert r2['believed'] is None
    assert m['width'] == pytest.approx(fm.SIZE) and m['height'] == pytest.approx(fm.SIZE)
    assert len(m['grid']) == 14  # -3 ... 3 m both ways
    for r in (r1, r2):
        assert 0 < r['true']['x'] < m['width'] and 0 < r['true']['y'] < m['height']


def test_who_helps_whom_goes_from_the_helpers_robot_to_the_helped():
    poses = {'r1': {'true': pose(1, 0), 'believed': None}, 'r4': {'true': pose(0, -1), 'believed': None},
             'r2': {'true': None, 'believed': pose(0, 1)}}
    helps = [{'helper': 'r1', 'helped': 'r4'}, {'helper': 'nobody', 'helped': 'r4'}, {'helper': 'r2', 'helped': 'r4'}]
    m = map_layout(poses, None, helps, {'r1': 'r1', 'r4': 'r4', 'r2': 'r2'})
    at = {r['name']: r['true'] or r['believed'] for r in m['robots']}
    first, second = m['helps']  # a helper with no pose on the map has no arrow
    assert (first['x1'], first['y1'], first['x2'], first['y2']) == (at['r1']['x'], at['r1']['y'], at['r4']['x'], at['r4']['y'])
    assert (second['helper'], second['x1']) == ('r2', at['r2']['x'])  # drawn from its believed pose


def test_agents_named_otherwise_than_their_robots():
    robots = [{'mas_id': '/faulty/rason_mas', 'agents': [{'name': 'faulty'}]},
              {'mas_id': '/r2/rason_mas', 'agents': [{'name': 'observer2'}, {'name': 'courier'}]}]
    messages = [{'sender': 'scout', 'sender_mas': '/r3/rason_mas'}]
    where = agent_robots(robots, messages)
    assert where == {'faulty': 'faulty', 'observer2': 'r2', 'courier': 'r2', 'scout': 'r3'}
    poses = {'r2': {'true': pose(0, 0), 'believed': None}, 'r3': {'true': pose(1, 1), 'believed': None}}
    assert len(map_layout(poses, None, [{'helper': 'scout', 'helped': 'courier'}], where)['helps']) == 1


def test_one_robot_at_rest_and_no_robot():
    m = map_layout({'solo': {'true': None, 'believed': dict(pose(0, 0), frame='odom')}}, None, [], {})
    (solo,) = m['robots']
    assert solo['believed']['frame'] == 'odom'
    assert solo['believed']['x'] == pytest.approx(m['width'] / 2) and m['width'] > 2 * fm.PAD
    assert map_layout({}, None, [], {}) is None
