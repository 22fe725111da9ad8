"""rason_budget pieces that need no cgroup: mounts, /proc parsing, process names, the summary."""
import pytest

from rason_budget import cgroups, cli, meter, procstat

V1_APART = """cgroup /sys/fs/cgroup/cpu cgroup rw,relatime,cpu 0 0
cgroup /sys/fs/cgroup/cpuacct cgroup rw,relatime,cpuacct 0 0
cgroup /sys/fs/cgroup/memory cgroup rw,relatime,memory 0 0
cgroup2 /sys/fs/cgroup/unified cgroup2 rw,relatime 0 0
"""
V1_TOGETHER = "cgroup /sys/fs/cgroup/cpu,cpuacct cgroup rw,nosuid,nodev,noexec,relatime,cpu,cpuacct 0 0\n"
V2_ONLY = "cgroup2 /sys/fs/cgroup cgroup2 rw,nosuid,nodev,noexec,relatime,nsdelegate 0 0\n"


def test_v1_controllers_are_found_mounted_apart_or_together():
    assert cgroups.parse_mounts(V1_APART) == ({'cpu': '/sys/fs/cgroup/cpu', 'cpuacct': '/sys/fs/cgroup/cpuacct',
                                               'memory': '/sys/fs/cgroup/memory'}, '/sys/fs/cgroup/unified')
    v1, v2 = cgroups.parse_mounts(V1_TOGETHER)
    assert v1 == {'cpu': '/sys/fs/cgroup/cpu,cpuacct', 'cpuacct': '/sys/fs/cgroup/cpu,cpuacct'} and v2 is None
    assert cgroups.Hierarchy(1, v1['cpu'], v1['cpuacct']).roots == ['/sys/fs/cgroup/cpu,cpuacct']


def test_v2_without_the_cpu_controller_is_refused_with_the_reason(tmp_path):
    (tmp_path / 'cgroup.controllers').write_text('memory pids\n')
    mounts = tmp_path / 'mounts'
    mounts.write_text('cgroup2 %s cgroup2 rw 0 0\n' % tmp_path)
    with pytest.raises(cgroups.BudgetError, match='without the cpu controller.*memory pids'):
        cgroups.detect(str(mounts))


def test_v2_with_the_cpu_controller_is_used(tmp_path):
    (tmp_path / 'cgroup.controllers').write_text('cpu memory\n')
    (tmp_path / 'cgroup.subtree_control').write_text('')
    mounts = tmp_path / 'mounts'
    mounts.write_text('cgroup2 %s cgroup2 rw 0 0\n' % tmp_path)
    h = cgroups.detect(str(mounts))
    assert (h.version, h.roots) == (2, [str(tmp_path)])


def test_no_cgroup_mounted_says_so(tmp_path):
    mounts = tmp_path / 'mounts'
    mounts.write_text('proc /proc proc rw 0 0\n')
    with pytest.raises(cgroups.BudgetError, match='no writable CPU cgroup: no cgroup file system mounted'):
        cgroups.detect(str(mounts))


def test_a_robot_name_that_cannot_be_a_group_name_is_refused():
    with pytest.raises(cgroups.BudgetError, match='bad robot name'):
        cgroups.Budget({'../etc': 0.5})


def test_in_budget_without_a_run_says_how_to_start_one():
    with pytest.raises(cgroups.BudgetError, match='RASON_BUDGET_RUN is not set.*budget run'):
        cgroups.join_by_name('faulty', 1, env={})


def test_stat_fields_are_read_after_a_command_name_with_spaces_and_brackets():
    fields = ['S', '42'] + ['0'] * 9 + ['250', '50'] + ['0'] * 6 + ['9000'] + ['0'] * 20
    ppid, cpu_s, start = procstat.parse_stat('123 (we (ird) name) ' + ' '.join(fields))
    assert (ppid, start) == (42, 9000)
    assert cpu_s == pytest.approx(300.0 / procstat.CLOCK_TICKS)


def test_status_values_in_kb():
    text = 'Name:\tjava\nVmHWM:\t  204800 kB\nVmRSS:\t  102400 kB\n'
    assert procstat.parse_status_kb(text, 'VmRSS') == 102400
    assert procstat.parse_status_kb(text, 'VmHWM') == 204800
    assert procstat.parse_status_kb('Name:\tkthreadd\n', 'VmRSS') is None


@pytest.mark.parametrize('argv, name', [
    (['/usr/bin/python3', '/ws/devel/lib/rason_bridge/rason_mas', 'faulty.mas2j', '__name:=rason_mas',
      '__log:=/x.log'], 'rason_mas'),
    (['/usr/bin/python3', '/opt/ros/bin/rosmaster', '--core', '-p', '11611'], 'rosmaster'),
    (['/ws/devel/lib/vision_synth/vision_synth_node', '__name:=vision_synth'], 'vision_synth'),
    (['/usr/bin/python3', '-u', '/usr/bin/roslaunch', '--port', '11611'], 'roslaunch'),
    (['/bin/sleep', '5'], 'sleep'),
    (['/usr/bin/python3', '-c', 'while True: pass'], 'python3'),
    (['/usr/bin/python3', '-m', 'rason_hosts.relay', '--port', '1'], 'rason_hosts.relay'),
])
def test_a_process_is_named_by_its_node_or_its_program(argv, name):
    assert procstat.name_from_cmdline(argv) == name


class _Seen(object):
    def __init__(self, pid, name, cpu_s, rss_kb, hwm_kb):
        self.pid, self.ppid, self.name, self.cpu_s = pid, 1, name, cpu_s
        self.start_ticks, self.rss_kb, self.hwm_kb = 0, rss_kb, hwm_kb


def test_the_summary_gives_mean_and_p95_cores_and_rss_per_process_and_in_total():
    # 10 s: 0.2 core for 8 s, 1 core for 1 s, 0.5 core for 1 s
    usage, t, ns = [(0.0, 0)], 0.0, 0
    for cores in [0.2] * 8 + [1.0, 0.5]:
        t, ns = t + 1.0, ns + int(cores * 1e9)
        usage.append((t, ns))
    mas = meter.Observation('faulty', _Seen(10, 'rason_mas', 5.0, 150 * 1024, 180 * 1024), born_in_run=False)
    mas.update(_Seen(10, 'rason_mas', 7.0, 160 * 1024, 200 * 1024))
    node = meter.Observation('faulty', _Seen(11, 'motion_decomp', 0.3, 30 * 1024, 30 * 1024), born_in_run=True)
    sim = meter.Observation(meter.OUTSIDE, _Seen(12, 'rason_sim_node', 4.0, 90 * 1024, 90 * 1024), born_in_run=True)
    s = meter.summarize({'faulty': usage}, {'faulty': [180 * 1024, 190 * 1024]}, [mas, node, sim],
                        {'faulty': {'periods': 100, 'throttled_periods': 3, 'throttled_s': 0.1}}, {'faulty': 0.5}, 1.0)
    f = s['robots']['faulty']
    assert f['cpu_mean_cores'] == pytest.approx(0.31)
    assert f['cpu_p95_cores'] == pytest.approx(1.0)  # nearest rank: the 10th of 10 intervals
    assert f['quota_cores'] == 0.5 and f['seconds'] == 10.0
    assert f['cores_series'][0] == [1.0, 0.2] and len(f['cores_series']) == 10
    assert f['cpu_p95_running_cores'] is None  # no window after the first 15 s
    assert f['rss_total_peak_mb'] == 190.0 and f['rss_sum_of_peaks_mb'] == 230.0
    assert [(p['name'], p['cpu_s'], p['rss_peak_mb']) for p in f['processes']] == [
        ('rason_mas', 2.0, 200.0), ('motion_decomp', 0.3, 30.0)]  # busiest first; born in the run: from 0
    assert s['outside']['processes'][0]['name'] == 'rason_sim_node'
    lines = cli.format_summary(s)
    assert lines[0].startswith('faulty (quota 0.50 core): CPU mean 0.310 core, p95 1.000')
    assert any('outside the budget' in line for line in lines)
    late = meter.summarize({'faulty': usage}, {}, [], {}, {}, 1.0, start_up_s=2.0, running_until=8.5)['robots']['faulty']
    assert late['cpu_p95_running_cores'] == pytest.approx(0.2)  # the windows ending at 3..8 s
    assert late['running_s'] == [2.0, 8.5]


def test_shut_down_begins_when_a_group_first_loses_a_process():
    counts = {'faulty': [(0.0, 0), (1.0, 4), (2.0, 4), (3.0, 3), (4.0, 0)],
              'helper': [(0.0, 0), (1.0, 2), (2.0, 4), (3.5, 4), (4.0, 1)]}
    assert meter.first_departure(counts) == 3.0
    assert meter.first_departure({'faulty': [(0.0, 0), (1.0, 4)]}) is None


def test_percentile_is_nearest_rank():
    assert meter.percentile([5, 1, 4, 2, 3], 95) == 5
    assert meter.percentile([5, 1, 4, 2, 3], 50) == 3


def test_v2_that_cannot_enable_the_cpu_controller_says_why(tmp_path, monkeypatch):
    (tmp_path / 'cgroup.subtree_control').write_text('memory\n')

    def busy(path, value):
        raise OSError(16, 'Device or resource busy')
    monkeypatch.setattr(cgroups, '_write', busy)
    group = cgroups.CpuGroup(cgroups.Hierarchy(2, str(tmp_path)), 'rason-abc123-faulty')
    with pytest.raises(cgroups.BudgetError, match='cannot enable the cpu controller.*Device or resource busy'):
        group.create(0.5)
