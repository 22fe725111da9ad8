"""robot_guide_node's parameters and frame names."""
import pytest

from robot_guide.settings import DEFAULTS, BadSetting, check, default_source, resolve_frame


@pytest.mark.parametrize('frame, ns, want', [
    ('odom', '/helper/', 'helper/odom'), ('odom', '/', 'odom'), ('odom', '/a/b/', 'a/b/odom'),
    ('/odom', '/helper/', 'odom'), ('/world', '/helper/', 'world'), ('', '/helper/', ''),
    ('helper/camera_rgb_optical_frame', '/helper/', 'helper/helper/camera_rgb_optical_frame'),
])
def test_resolve_frame(frame, ns, want):
    assert resolve_frame(frame, ns) == want


def test_defaults_in_the_helpers_namespace():
    out = check({}, '/helper/', '/helper/robot_guide')
    assert out['odom_frame'] == 'helper/odom'
    assert out['camera_frame'] == ''
    assert out['source'] == 'robot_guide_located'
    assert (out['max_rate'], out['centre_deadband'], out['angular_speed'], out['lost_after']) == (
        5.0, 3.0, 0.4, 2.0)
    assert set(out) == set(DEFAULTS)


def test_given_values_are_taken():
    out = check({'odom_frame': '/map', 'camera_frame': 'cam', 'max_rate': 0, 'centre_gain': 3,
                 'source': 'eyes'}, '/helper/', '/helper/robot_guide')
    assert (out['odom_frame'], out['camera_frame'], out['max_rate'], out['centre_gain'],
            out['source']) == ('map', 'helper/cam', 0.0, 3.0, 'eyes')


@pytest.mark.parametrize('values, why', [
    ({'tf_timeout': 0}, 'tf_timeout: must be positive'),
    ({'centre_gain': -1}, 'centre_gain: must be positive'),
    ({'angular_speed': float('inf')}, 'angular_speed: a finite number'),
    ({'lost_after': 'two'}, 'lost_after: a finite number'),
    ({'max_rate': -5}, 'max_rate: must be >= 0'),
    ({'centre_deadband': True}, 'centre_deadband: a finite number'),
    ({'odom_frame': ''}, 'odom_frame: a frame name'),
    ({'odom_frame': 3}, 'odom_frame: a name'),
    ({'source': 'Eyes'}, 'source'),
])
def test_bad_values_say_which_and_why(values, why):
    with pytest.raises(BadSetting, match=why):
        check(values, '/helper/', '/helper/robot_guide')


@pytest.mark.parametrize('name, want', [('/robot_guide', 'robot_guide_located'),
                                        ('/helper/guide', 'guide_located')])
def test_default_source(name, want):
    assert default_source(name) == want
