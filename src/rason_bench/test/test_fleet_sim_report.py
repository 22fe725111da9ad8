"""The fleet_sim part's goal, table and CPU arithmetic, from made-up measurements."""
import os

from rason_bench import fleet_sim, fleet_sim_report


def size(n, rtf):
    return {'robots': n, 'cameras': min(n, 3), 'window_s': 20.0, 'real_time_factor': rtf, 'sim_cpu_pct': 30.0,
            'total_cpu_pct': 90.0, 'processes': 10 + 4 * n, 'machine_cpu_pct': 120.0,
            'frames_per_sim_s': {'r1': 10.0}, 'turns_ended_early': {}}


def test_the_goal_is_real_time_with_six_robots():
    assert fleet_sim_report.goals({}) == []
    met = fleet_sim_report.goals({'sizes': [size(2, 2.5), size(6, 1.0), size(8, 0.7)]})
    assert len(met) == 1 and met[0][1:] == ('1.00', True)
    missed = fleet_sim_report.goals({'sizes': [size(6, 0.93)]})
    assert missed[0][1:] == ('0.93', False)
    assert fleet_sim_report.goals({'sizes': [size(4, 2.0)]})[0][1:] == ('not measured', False)


def test_the_table_has_a_row_per_size_and_names_turns_that_ended():
    sizes = [size(2, 2.5), size(4, 1.8)]
    sizes[1]['turns_ended_early'] = {'r4': 'no_progress'}
    text = fleet_sim_report.text({'window_s': 20.0, 'sizes': sizes})
    rows = [line for line in text.splitlines() if line.startswith('| ') and line[2].isdigit()]
    assert [r.split(' | ')[2] for r in rows] == ['2.50', '1.80']
    assert [r.split(' | ')[5] for r in rows] == ['36', '50']  # 90 % over the factor
    assert 'r4 with 4 robots: no_progress' in text


def test_the_cpu_by_process_table_leaves_the_idle_ones_out():
    sizes = [size(2, 2.5)]
    sizes[0]['cpu_by_process_pct'] = {'rason_sim_node': 40.0, 'vision_synth_no': 20.0, 'sleep': 0.0}
    text = fleet_sim_report.text({'window_s': 20.0, 'sizes': sizes})
    assert '| robots | rason_sim_node | vision_synth_no |' in text and '| 2 | 40 | 20 |' in text


def test_cpu_is_the_ticks_used_in_the_window_over_its_length_by_command():
    hz = os.sysconf('SC_CLK_TCK')
    before = {10: ('rason_sim_node', 0), 11: ('python3', hz)}
    after = {10: ('rason_sim_node', hz), 11: ('python3', 2 * hz), 12: ('python3', hz)}  # 12 started since
    assert fleet_sim.cpu_percent(before, after, 2.0) == {'rason_sim_node': 50.0, 'python3': 100.0}


def test_the_process_tree_is_the_launch_and_what_it_started():
    tree = fleet_sim._ticks_by_pid(os.getpid())
    assert os.getpid() in tree and os.getppid() not in tree


def test_the_fleets_are_the_first_robots_of_the_world():
    assert fleet_sim.robots_of(4) == ['r1', 'r2', 'r3', 'r4']
    assert fleet_sim.SIZES == (2, 4, 6, 8)
