"""Jason syntax of the robot(Name, Angle, Depth, Yaw) perception."""
import math
import re

import pytest

from vision_synth import literals as lit

# A ground Jason literal robot(atom, number, number, number) with plain decimal numbers.
NUMBER = r'-?(0|[1-9]\d*)(\.\d*[1-9])?'
SHAPE = re.compile(r'robot\([a-z]\w*,%s,%s,%s\)\Z' % (NUMBER, NUMBER, NUMBER))


@pytest.mark.parametrize('value, decimals, text', [
    (1.5, 3, '1.5'), (1.5004, 3, '1.5'), (1.5006, 3, '1.501'), (-3.514, 2, '-3.51'),
    (12.0, 2, '12'), (0.0, 2, '0'), (-0.0001, 2, '0'), (-0.004, 2, '0'), (180.0, 2, '180'),
    (-179.999, 2, '-180'), (1e-9, 3, '0'), (2.25, 0, '2'), (123456.789, 2, '123456.79')])
def test_format_number(value, decimals, text):
    assert lit.format_number(value, decimals) == text


@pytest.mark.parametrize('bad', [float('nan'), float('inf'), -float('inf')])
def test_format_number_refuses_non_finite(bad):
    with pytest.raises(ValueError):
        lit.format_number(bad, 2)


def test_robot_literal_matches_the_thesis_shape():
    text = lit.robot_literal('faulty', -3.5234, 1.50349, 12.4)
    assert text == 'robot(faulty,-3.52,1.503,12.4)'
    assert SHAPE.match(text)


@pytest.mark.parametrize('angle, depth, yaw', [
    (0.0, 1.0, 180.0), (-28.49, 2.9999, -179.995), (28.5, 0.5, 0.001), (-0.0, 3.0, -0.0)])
def test_robot_literal_is_always_parseable_and_round_trips(angle, depth, yaw):
    text = lit.robot_literal('robot_2', angle, depth, yaw)
    assert SHAPE.match(text), text
    a, d, y = (float(v) for v in text[len('robot(robot_2,'):-1].split(','))
    assert a == pytest.approx(angle, abs=0.005)
    assert d == pytest.approx(depth, abs=0.0005)
    assert (y - yaw + 180.0) % 360.0 - 180.0 == pytest.approx(0.0, abs=0.005)
    assert -180.0 < y <= 180.0


@pytest.mark.parametrize('name', ['Faulty', '_x', '2robot', 'fau lty', 'a-b', '', 'a,b', None])
def test_robot_literal_refuses_names_that_are_not_atoms(name):
    assert not lit.is_atom(name)
    with pytest.raises(ValueError):
        lit.robot_literal(name, 0.0, 1.0, 0.0)


def test_yaw_rounded_to_minus_180_is_written_180():
    assert lit.robot_literal('faulty', -1.0, 2.0, -179.999) == 'robot(faulty,-1,2,180)'
    assert lit.robot_literal('faulty', -179.999, 2.0, 0.0) == 'robot(faulty,-180,2,0)'


def test_robot_literal_refuses_nan_values():
    with pytest.raises(ValueError):
        lit.robot_literal('faulty', 0.0, math.nan, 0.0)


def test_frame_literal_counts_from_one_and_carries_the_stamp():
    assert lit.frame_literal(1, 0) == 'cameraFrame(1,0)'
    assert lit.frame_literal(123456, 1795516398965) == 'cameraFrame(123456,1795516398965)'


@pytest.mark.parametrize('bad', [0, -1, 1.5, True, '3', None])
def test_frame_literal_rejects_what_is_not_a_count(bad):
    with pytest.raises(ValueError):
        lit.frame_literal(bad, 10)


@pytest.mark.parametrize('bad', [-1, 1.5, True, '3', None])
def test_frame_literal_rejects_what_is_not_a_stamp(bad):
    with pytest.raises(ValueError):
        lit.frame_literal(1, bad)
