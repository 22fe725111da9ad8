"""rason_rospy.quick_start: rospy.init_node's registration checks made often, and rosgraph's
logging configuration named where rosgraph would find it first. No master."""
import time

import rospy.impl.init as init

from rason_rospy.quick_start import LOG_CONFIG, PollingTime, logging_config, name_logging_config, \
    poll_registration_every


def test_a_sleep_lasts_the_period_at_most_and_the_rest_of_time_is_times():
    slept = []
    polling = PollingTime(0.005, sleep=slept.append)
    polling.sleep(0.1)
    polling.sleep(0.00001)
    assert slept == [0.005, 0.00001]
    assert polling.monotonic is time.monotonic


def test_rospy_init_waits_for_its_registration_in_polls_of_the_period(monkeypatch):
    monkeypatch.setattr(init, 'time', time)
    poll_registration_every(0.002)
    assert isinstance(init.time, PollingTime) and init.time.period == 0.002


def _config(folder, extension):
    folder.mkdir(parents=True, exist_ok=True)
    path = folder / ('python_logging.' + extension)
    path.write_text('')
    return str(path)


def test_the_configuration_is_looked_for_in_ros_home_then_etc_ros(tmp_path):
    home, etc = tmp_path / 'home', tmp_path / 'etc'
    assert logging_config(str(home), str(etc)) is None
    in_etc = _config(etc, 'conf')
    assert logging_config(str(home), str(etc)) == in_etc
    in_home = _config(home / 'config', 'yaml')
    assert logging_config(str(home), str(etc)) == in_home


def test_the_conf_file_comes_before_the_yaml_file_of_a_folder(tmp_path):
    etc = tmp_path / 'etc'
    _config(etc, 'yaml')
    conf = _config(etc, 'conf')
    assert logging_config(str(tmp_path / 'home'), str(etc)) == conf


def test_a_configuration_named_already_is_kept_and_none_found_leaves_rosgraphs_search(tmp_path):
    home, etc = tmp_path / 'home', tmp_path / 'etc'
    environ = {'ROS_HOME': str(home), 'ROS_ETC_DIR': str(etc), LOG_CONFIG: '/mine.conf'}
    _config(etc, 'conf')
    name_logging_config(environ)
    assert environ[LOG_CONFIG] == '/mine.conf'
    del environ[LOG_CONFIG]
    name_logging_config(environ)
    assert environ[LOG_CONFIG] == str(etc / 'python_logging.conf')
    empty = {'ROS_HOME': str(home), 'ROS_ETC_DIR': str(tmp_path / 'nowhere')}
    name_logging_config(empty)
    assert LOG_CONFIG not in empty
