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


def run_end(*required):
    from rason_tools.run_launch import RunEnd
    end = RunEnd()
    end.nodes.update(required)
    return end


def test_a_required_node_ends_the_run_whatever_its_status():
    end = run_end('faulty/rason_mas')
    end.process_died('helper/vision_synth-3', 0)          # another node finishing cleanly: runs on
    end.process_died('helper/vision_synth-4', -9)         # killed by a signal: runs on
    assert not end.done.is_set()
    end.process_died('faulty/rason_mas-7', 0)
    assert (end.done.is_set(), end.ended_by, end.process, end.exit_code) == (
        True, 'faulty/rason_mas', 'faulty/rason_mas-7', 0)


def test_any_node_that_fails_while_the_launch_runs_ends_it_but_not_during_shutdown():
    end = run_end('faulty/rason_mas')
    end.process_died('helper/rason_mas-5', 1)
    assert (end.done.is_set(), end.ended_by, end.exit_code) == (True, 'helper/rason_mas', 1)
    end.process_died('faulty/rason_mas-7', 0)
    assert end.ended_by == 'helper/rason_mas', 'the first end is kept'
    stopping = run_end('faulty/rason_mas')
    stopping.stopping = lambda: True
    stopping.process_died('helper/rason_mas-5', 1)
    assert not stopping.done.is_set()
