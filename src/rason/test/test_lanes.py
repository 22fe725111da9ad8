"""rason_tools.lanes: make test's jobs in lanes, without ROS (the jobs here are shell lines)."""
import os
import sys

from rason_tools import lanes
from rason_tools.lanes import Job


def _shell(name, record, alone=False, status=0):
    """A job that writes 'start NAME' and 'end NAME' to record, then exits with status."""
    line = 'echo start %s >> %s; echo end %s >> %s; exit %d' % (name, record, name, record, status)
    return Job(name, ['/bin/sh', '-c', line], alone)


def _events(record):
    with open(record) as f:
        return [tuple(line.split()) for line in f]


def test_a_free_lane_takes_the_first_job_that_need_not_run_alone():
    a, b, c = Job('a', [], True), Job('b', [], False), Job('c', [], False)
    assert lanes.next_job([a, b, c], [], 2) is b
    assert lanes.next_job([a, c], [b], 2) is c
    assert lanes.next_job([a], [b, c], 2) is None


def test_a_job_that_runs_alone_waits_for_an_empty_machine_and_the_others():
    a, b = Job('a', [], True), Job('b', [], False)
    assert lanes.next_job([a], [b], 2) is None
    assert lanes.next_job([a], [], 2) is a
    assert lanes.next_job([a, Job('a2', [], True)], [a], 2) is None


def test_jobs_never_outnumber_the_lanes_and_the_lone_job_runs_last_by_itself(tmp_path):
    record = str(tmp_path / 'record')
    jobs = [_shell('solo', record, alone=True)] + [_shell('j%d' % i, record) for i in range(6)]
    ended = lanes.run_jobs(jobs, 2, str(tmp_path / 'logs'), say=lambda line: None)
    assert sorted(ended) == sorted(job.name for job in jobs)
    running, most = set(), 0
    for what, name in _events(record):
        if what == 'start':
            assert 'solo' not in running
            if name == 'solo':
                assert not running
            running.add(name)
            most = max(most, len(running))
        else:
            running.discard(name)
    assert most <= 2
    assert _events(record)[-2:] == [('start', 'solo'), ('end', 'solo')]


def test_each_job_ends_with_its_own_exit_status_and_log(tmp_path):
    record = str(tmp_path / 'record')
    jobs = [_shell('good', record), _shell('bad', record, status=3)]
    said = []
    ended = lanes.run_jobs(jobs, 2, str(tmp_path / 'logs'), say=said.append)
    assert ended['good'][0] == 0 and ended['bad'][0] == 3
    assert any(line.startswith('bad') and 'FAILED, exit status 3' in line for line in said)
    assert os.path.isfile(lanes.log_path(str(tmp_path / 'logs'), 'bad'))


def test_a_job_is_charged_the_cpu_time_of_its_processes(tmp_path):
    spin = "import time\nend = time.process_time() + 0.3\nwhile time.process_time() < end: pass\n"
    jobs = [Job('busy', ['sh', '-c', '%s -c "$0"; %s -c "$0"' % (sys.executable, sys.executable), spin], False),
            Job('idle', ['sleep', '0.3'], False)]
    ended = lanes.run_jobs(jobs, 2, str(tmp_path / 'logs'), say=lambda line: None)
    assert 0.6 <= ended['busy'][2] < 5, ended
    assert ended['idle'][2] < 0.2 and ended['idle'][1] >= 0.3, ended


def test_a_test_over_the_fleet_channel_runs_twice_named_as_catkin_names_it(tmp_path):
    plain = tmp_path / 'plain.test'
    plain.write_text('<launch>\n  <!-- make test: alone -->\n</launch>\n')
    fleet = tmp_path / 'multi.test'
    fleet.write_text('<launch><include file="$(find rason)/test/fleet_channel.launch"/></launch>\n')
    jobs = {job.name: job for job in lanes.rostest_jobs([str(plain), str(fleet)], '/results')}
    assert sorted(jobs) == ['multi', 'multi_mqtt', 'plain']
    assert jobs['plain'].alone and not jobs['multi'].alone
    assert jobs['multi_mqtt'].argv[-1] == 'fleet_channel:=mqtt'
    assert 'multi__fleet_channel_mqtt.xml' in jobs['multi_mqtt'].argv
    assert 'test_plain.xml' in jobs['plain'].argv
    assert jobs['plain'].argv[-1] == str(plain)


def test_the_suite_has_every_part_and_the_project_marks_its_pacing_tests_alone():
    jobs = lanes.suite_jobs(lanes.PARTS, '/results')
    names = [job.name for job in jobs]
    assert names[:4] == ['hosts pytest', 'javatest', 'pytest', 'gtest']
    hosts = jobs[0].argv
    assert any(arg.endswith('test_hosts_netns.py') for arg in hosts)
    assert '--ignore-glob=' + lanes.HOSTS_TESTS in jobs[2].argv
    alone = {job.name for job in jobs if job.alone}
    assert {'case_study_budget', 'sim_pacing'} <= alone
    assert 'case_study_both_actuators' in names and 'multi_two_mqtt' in names
