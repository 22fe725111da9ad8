"""The robots table from a simulator world file (vision_synth.world_markers), the fleet
world's colours under the detector's HSV ranges, and the detector naming fleet robots."""
import os

import cv2
import numpy as np
import pytest
import yaml

import vision_scene as vs
from vision_synth import detector as det
from vision_synth import world_markers as wm

HERE = os.path.dirname(os.path.abspath(__file__))
FLEET = os.path.join(HERE, '..', '..', 'rason_sim', 'config', 'fleet.yaml')
TWO_ROBOTS = os.path.join(HERE, '..', '..', 'rason_sim', 'config', 'two_robots.yaml')
CONFIG = os.path.join(HERE, '..', 'config', 'vision_synth.yaml')
#: rason_sim's own palette (src/markers.cpp), which a world file's marker_colors extends
SIM_PALETTE = {'green': vs.GREEN, 'orange': vs.ORANGE, 'blue': vs.BLUE}


def load(path):
    with open(path) as f:
        return yaml.safe_load(f)


def fleet_palette(world):
    palette = dict(SIM_PALETTE)
    palette.update({name: tuple(rgb) for name, rgb in world.get('marker_colors', {}).items()})
    return palette


def test_the_fleet_world_gives_every_robot_but_the_cameras_own_its_pair():
    world = load(FLEET)
    table = wm.world_robots(world, exclude={'r1'})
    assert sorted(table) == ['r2', 'r3', 'r4', 'r5', 'r6', 'r7', 'r8']
    assert table['r4'] == {'left': 'yellow', 'right': 'green'}
    assert table['r5'] == {'left': 'blue', 'right': 'magenta'}
    assert sorted(wm.world_robots(world)) == ['r%d' % k for k in range(1, 9)]
    assert wm.confusable(wm.robots_from_world(world)) == []


def test_the_case_study_world_gives_faulty_green_and_orange():
    assert wm.world_robots(load(TWO_ROBOTS), exclude={'helper'}) == {
        'faulty': {'left': 'green', 'right': 'orange'}}


def test_every_fleet_colour_is_found_by_its_own_range_only_lit_or_dimmed():
    world = load(FLEET)
    palette = fleet_palette(world)
    colors = det.parse_colors(load(CONFIG)['colors'])
    used = sorted({c for spec in wm.robots_from_world(world).values() for c in spec.values()})
    assert len(used) == 5
    for name in used:
        for scale in (1.0, 0.6, 0.3, 0.3 * vs.AMBIENT, 0.25 * 0.3):  # to 25 % of 30 % ambient
            pixel = np.array([[[round(c * scale * 255) for c in palette[name]]]], np.uint8)
            hsv = cv2.cvtColor(pixel, cv2.COLOR_RGB2HSV)
            assert colors[name].mask(hsv)[0, 0] == 255, (name, scale, pixel, hsv)
            for other in set(used) - {name}:
                assert colors[other].mask(hsv)[0, 0] == 0, (name, other, scale, hsv)


def test_flags_put_cylinders_on_and_off_with_the_simulators_default_colours():
    world = {'robots': ['a', 'b', 'c', 'd', 'cam'],
             'a': {'left_marker': True, 'right_marker': True, 'back_marker': True},
             'b': {'markers': {'left': 'red', 'right': 'yellow'}, 'right_marker': False},
             'c': {'markers': {'left': 'red', 'back': 'blue'}, 'right_marker': True},
             'd': {'x': 1.0},
             'cam': {'camera': True, 'markers': {'left': 'magenta', 'right': 'blue'}}}
    assert wm.robots_from_world(world, exclude={'cam'}) == {
        'a': {'left': 'green', 'right': 'orange', 'back': 'blue'},
        'c': {'left': 'red', 'right': 'orange', 'back': 'blue'}}


def test_robots_sharing_two_colours_in_either_order_are_confusable_and_refused():
    robots = {'a': {'left': 'red', 'right': 'yellow'}, 'b': {'left': 'yellow', 'right': 'red'},
              'c': {'left': 'red', 'right': 'green'},
              'd': {'left': 'blue', 'right': 'magenta', 'back': 'green'},
              'e': {'left': 'green', 'right': 'blue'}}
    assert wm.confusable(robots) == [('a', 'b'), ('d', 'e')]
    world = {'robots': ['r4', 'r5', 'r6'],
             'r4': {'left_marker': True, 'right_marker': True},
             'r5': {'left_marker': True, 'right_marker': True},
             'r6': {'markers': {'left': 'red', 'right': 'green'}}}
    with pytest.raises(det.ConfigError, match='cannot tell r4 and r5 apart'):
        wm.world_robots(world)
    with pytest.raises(det.ConfigError, match='no robot with a left and a right cylinder'):
        wm.world_robots({'robots': ['cam'], 'cam': {'camera': True}})


@pytest.mark.parametrize('world, message', [
    ('robots: r1', 'needs robots'),
    ('robots: [r1]\nr1: [1, 2]', 'must be a dictionary'),
    ('robots: [r1]\nr1: {markers: {top: red}}', 'markers must be'),
    ('robots: [r1]\nr1: {markers: red}', 'markers must be'),
    ('robots: [r1]\nr1: {markers: {left: 3}}', 'markers/left must name a colour'),
    ('robots: [r1]\nr1: {left_marker: yes please}', 'left_marker must be true or false'),
    ('robots: [1]', 'names must be strings'),
])
def test_a_malformed_world_says_what_is_wrong(world, message):
    with pytest.raises(det.ConfigError, match=message):
        wm.robots_from_world(yaml.safe_load(world))


def test_the_namespace_names_the_robot():
    assert wm.robot_of_namespace('/r1/') == 'r1'
    assert wm.robot_of_namespace('/fleet/r2') == 'r2'
    assert wm.robot_of_namespace('/') == ''


def test_the_detector_names_two_fleet_robots_in_one_frame():
    world = load(FLEET)
    palette = fleet_palette(world)
    table = wm.world_robots(world, exclude={'r1'})
    detector = det.Detector(load(CONFIG)['colors'], table)

    def colours(robot):
        return tuple(palette[table[robot][side]] for side in ('left', 'right')) + (vs.BLUE,)

    # r4 facing a little to the right; r6 (which shares green with r4) facing the camera,
    # so its green cylinder is on the image's left
    r6_x, r6_z = vs.robot_centre(-15.0, 2.5)
    scene = vs.Scene(robot=(10.0, 2.0, 30.0), colors=colours('r4'),
                     extra_pairs=[(r6_x, r6_z, 170.0, vs.SEPARATION, {'left', 'right'},
                                   colours('r6'))])
    rgb, xyz = scene.render(noise=1.0, seed=3)
    found = {d.name: d.pose for d in detector.detect(rgb, xyz)}
    assert sorted(found) == ['r4', 'r6']
    assert found['r4'].angle == pytest.approx(10.0, abs=0.5)
    assert found['r4'].depth == pytest.approx(2.0, abs=0.03)
    assert found['r4'].yaw == pytest.approx(40.0, abs=3.0)
    assert found['r6'].angle == pytest.approx(-15.0, abs=0.5)
    assert found['r6'].depth == pytest.approx(2.5, abs=0.03)
    assert found['r6'].yaw == pytest.approx(155.0, abs=3.0)
