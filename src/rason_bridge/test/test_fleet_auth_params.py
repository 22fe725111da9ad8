"""rason_mas's fleet authentication ~params: defaults, what is refused (naming the parameter), the
uint64 <-> Java long conversion."""
import pytest

from rason_bridge.fleet_auth import OFF, REQUIRED, default_key_file, no_key_help, to_int64, to_uint64
from rason_bridge.params import read_settings

ROS_HOME = '/home/robot/.ros'


def settings(**given):
    return read_settings(lambda name, default: given.get(name, default), ROS_HOME)


def test_defaults_require_the_key_file_under_ros_home():
    s = settings()
    assert s.fleet_auth == REQUIRED
    assert s.fleet_key_file == '/home/robot/.ros/rason/fleet.key' == default_key_file(ROS_HOME)
    assert s.fleet_key is None
    assert s.auth_window == 60.0


def test_off_also_as_yaml_reads_it():
    assert settings(fleet_auth='off').fleet_auth == OFF
    assert settings(fleet_auth=False).fleet_auth == OFF  # _fleet_auth:=off on the command line
    assert settings(fleet_auth=True).fleet_auth == REQUIRED
    assert settings(fleet_auth='required').fleet_auth == REQUIRED


@pytest.mark.parametrize('bad', ['yes', 'Required', '', 0, None])
def test_an_unknown_mode_is_refused(bad):
    with pytest.raises(ValueError, match="fleet_auth must be 'required' or 'off'"):
        settings(fleet_auth=bad)


def test_the_key_file_parameter_and_home_expansion(monkeypatch):
    monkeypatch.setenv('HOME', '/home/op')
    assert settings(fleet_key_file='/etc/rason/fleet.key').fleet_key_file == '/etc/rason/fleet.key'
    assert settings(fleet_key_file='~/fleet.key').fleet_key_file == '/home/op/fleet.key'
    assert settings(fleet_key_file='').fleet_key_file == default_key_file(ROS_HOME), 'a launch arg left empty'


def test_the_key_parameter():
    s = settings(fleet_key='k' * 40)
    assert s.fleet_key == 'k' * 40
    assert settings(fleet_key='').fleet_key is None
    with pytest.raises(ValueError, match='fleet_key must be a string'):
        settings(fleet_key=1234567890123456789012345678901234567890)
    with pytest.raises(ValueError, match='not both'):
        settings(fleet_key='k' * 40, fleet_key_file='/etc/fleet.key')


@pytest.mark.parametrize('window', [0, 0.5, 10, 3600.0])
def test_windows(window):
    assert settings(auth_window=window).auth_window == float(window)


@pytest.mark.parametrize('bad', [-1, 'long', True, None, float('nan'), float('inf'), 1e300])
def test_a_bad_window_is_refused(bad):
    with pytest.raises(ValueError, match='auth_window'):
        settings(auth_window=bad)


def test_the_help_names_the_file_and_the_tool():
    text = no_key_help(settings(fleet_key_file='/etc/fleet.key'))
    assert 'rosrun rason_bridge fleet_key /etc/fleet.key' in text
    assert '~fleet_auth to off' in text
    assert '~fleet_key' in no_key_help(settings(fleet_key='short'))


@pytest.mark.parametrize('u64, i64', [(0, 0), (1, 1), (2 ** 63 - 1, 2 ** 63 - 1), (2 ** 63, -2 ** 63),
                                      (2 ** 64 - 1, -1)])
def test_uint64_fields_keep_their_bits_as_java_longs(u64, i64):
    assert to_int64(u64) == i64
    assert to_uint64(i64) == u64


def first_run(tmp_path, **given):
    from rason_bridge.fleet_auth import first_run_key
    from rason_bridge.fleet_key import make_new_key
    s = read_settings(lambda name, default: given.get(name, default), str(tmp_path))
    return first_run_key(s, default_key_file(str(tmp_path)), make_new_key), s.fleet_key_file


def test_a_robot_started_with_no_fleet_makes_its_key_and_says_where_and_how_to_share_it(tmp_path):
    line, path = first_run(tmp_path)
    assert (tmp_path / 'rason' / 'fleet.key').stat().st_mode & 0o777 == 0o600
    assert line.startswith('no fleet key yet: made a new one at %s (mode 0600)' % path)
    assert 'copy this file to the same place on each of them' in line
    again, _ = first_run(tmp_path)
    assert again is None, 'an existing key is used as it is'


def test_no_key_is_made_for_another_file_a_key_text_or_authentication_off(tmp_path):
    given = str(tmp_path / 'fleet.key')
    assert first_run(tmp_path, fleet_key_file=given)[0] is None   # a given missing file stays an error
    assert first_run(tmp_path, fleet_key='k' * 32)[0] is None
    assert first_run(tmp_path, fleet_auth='off')[0] is None
    assert not (tmp_path / 'rason').exists() and not (tmp_path / 'fleet.key').exists()
