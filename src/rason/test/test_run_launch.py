"""rason_tools.run_launch's pure parts: which node a roslaunch process is, and the exit status
a process's exit code gives (no ROS master needed)."""
import pytest

pytest.importorskip('roslaunch')
from rason_tools.run_launch import exit_status, node_key, process_base_name  # noqa: E402


def test_a_process_name_is_its_node_and_a_counter():
    assert process_base_name('faulty/rason_mas-7') == 'faulty/rason_mas'
    assert process_base_name('rason_sim-1') == 'rason_sim'
    assert process_base_name('my-node-12') == 'my-node'


def test_node_keys_are_the_process_names_without_counter():
    assert node_key('/faulty/', 'rason_mas') == 'faulty/rason_mas'
    assert node_key('/', 'rason_sim') == 'rason_sim'
    assert node_key('', 'demo') == 'demo'


def test_exit_status_follows_the_shell():
    assert exit_status(0) == 0
    assert exit_status(1) == 1
    assert exit_status(-2) == 130     # killed by SIGINT
    assert exit_status(-9) == 137     # by SIGKILL
    assert exit_status(None) == 1     # not known
