"""``make test``'s suites in two lanes: this machine has two cores and a rostest, mostly a
simulated world with its nodes and JVMs, keeps 0.9 to 1.7 of them busy, so one lane at a
time left a good part of the machine idle for 25 minutes. Each job is one command (the hosts
pytest, the JUnit run, the pytest run, the simulator's gtests, one rostest); a free lane takes
the next.

A ``.test`` that says ``<!-- make test: alone -->`` (it measures pacing or holds robots to a
CPU budget, so a neighbour would change what it measures) runs once every other job has ended
and nothing else runs beside it.

    python3 -m rason_tools.lanes [--lanes N] [--only hosts,javatest,pytest,gtest,rostest]

Each job's output goes to ``build/lanes/NAME.log``; a line per ended job says how it ended
and how long it took, and the tail of every failed job's log is printed at the end. The
exit status is 0 only when every job passed. Needs the workspace built (``make setup``).
"""
import argparse
import collections
import glob
import os
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
PACKAGE = os.path.dirname(os.path.dirname(HERE))     # src/rason
REPOSITORY = os.path.dirname(os.path.dirname(PACKAGE))
PYTHON = '/usr/bin/python3'
HOSTS_TESTS = 'src/rason/test/test_hosts_*.py'
ALONE_MARK = '<!-- make test: alone -->'
#: What a .test includes when it runs over both fleet channels (CMakeLists.txt says the same).
FLEET_CHANNEL_LAUNCH = 'test/fleet_channel.launch'
PARTS = ('hosts', 'javatest', 'pytest', 'gtest', 'rostest')
FAILED_LOG_LINES = 60
SLOWEST = '--durations=10'      # the pytest logs name their slowest tests, for the next trim
#: Jobs whose last line is their count of tests (the rostests have summarize_results.py).
SUITES_WITH_A_SUMMARY = ('hosts pytest', 'javatest', 'pytest')

Job = collections.namedtuple('Job', 'name argv alone')


def rostest_jobs(test_files, results_dir):
    """A job per .test, named and filed as ``catkin_make run_tests`` names them, and a second
    one with ``fleet_channel:=mqtt`` for a .test that includes the fleet channel launch."""
    jobs = []
    for path in sorted(test_files):
        with open(path) as f:
            text = f.read()
        stem = os.path.splitext(os.path.basename(path))[0]
        alone = ALONE_MARK in text
        base = [PYTHON, '/usr/bin/rostest', '--pkgdir=' + PACKAGE, '--package=rason',
                '--results-base-dir', results_dir]
        jobs.append(Job(stem, base + ['--results-filename', 'test_%s.xml' % stem, path], alone))
        if FLEET_CHANNEL_LAUNCH in text:
            jobs.append(Job(stem + '_mqtt', base + ['--results-filename', '%s__fleet_channel_mqtt.xml' % stem,
                                                    path, 'fleet_channel:=mqtt'], alone))
    return jobs


def suite_jobs(parts, results_dir, make='make'):
    """The jobs of the chosen parts, the longest first: the hosts pytest (about 9 minutes) holds
    one lane while the other runs through the rest."""
    jobs = []
    if 'hosts' in parts:
        jobs.append(Job('hosts pytest', [PYTHON, '-m', 'pytest', '-q', '-p', 'no:cacheprovider', SLOWEST]
                        + sorted(glob.glob(os.path.join(REPOSITORY, HOSTS_TESTS))), False))
    if 'javatest' in parts:
        jobs.append(Job('javatest', [make, '--no-print-directory', '-C', REPOSITORY, 'javatest'], False))
    if 'pytest' in parts:
        jobs.append(Job('pytest', [PYTHON, '-m', 'pytest', '-q', '-p', 'no:cacheprovider', SLOWEST, 'src',
                                   '--ignore-glob=' + HOSTS_TESTS], False))
    if 'gtest' in parts:
        # after JUnit and pytest, one compiler at a time, as before the lanes: the hosts tests'
        # first minutes (timed on shaped links) keep the neighbours they had then
        build = os.path.join(REPOSITORY, 'build')
        jobs.append(Job('gtest', [make, '--no-print-directory', '-C', build, 'run_tests_rason_sim'], False))
    if 'rostest' in parts:
        jobs += rostest_jobs(glob.glob(os.path.join(PACKAGE, 'test', '*.test')), results_dir)
    return jobs


def next_job(pending, running, lanes):
    """The job to start now, or None: the first pending job that is not alone while a lane is
    free; a job that must run alone only when nothing runs and no other kind is left."""
    if len(running) >= lanes:
        return None
    for job in pending:
        if not job.alone:
            return job
    if not running and pending:
        return pending[0]
    return None


def run_jobs(jobs, lanes, log_dir, say=lambda line: print(line, flush=True), env=None):
    """Runs the jobs; returns ``{name: (exit status, seconds, CPU seconds)}``. Blocks on the
    children's exits (``os.wait4``), so a lane is refilled the moment its job ends. The CPU
    time (user and system) is the job's and that of every process of it that was waited for:
    on two cores, what the lanes can finish in a given time depends on it more than on the
    jobs' wall times."""
    os.makedirs(log_dir, exist_ok=True)
    pending, running, ended = list(jobs), {}, {}
    while pending or running:
        job = next_job(pending, [entry[0] for entry in running.values()], lanes)
        if job is not None:
            pending.remove(job)
            started = time.monotonic()  # before the start: Popen returns once the job runs
            with open(log_path(log_dir, job.name), 'w') as log:
                proc = subprocess.Popen(job.argv, stdout=log, stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL,
                                        cwd=REPOSITORY, env=env)
            running[proc.pid] = (job, proc, started)
            continue
        pid, status, usage = os.wait4(-1, 0)
        if pid not in running:
            continue
        job, proc, started = running.pop(pid)
        proc.returncode = os.waitstatus_to_exitcode(status)
        ended[job.name] = (proc.returncode, time.monotonic() - started, usage.ru_utime + usage.ru_stime)
        say('%-40s %s (%.0f s, CPU %.0f s)' % ((job.name, 'passed' if proc.returncode == 0 else
                                               'FAILED, exit status %d' % proc.returncode) + ended[job.name][1:]))
    return ended


def log_path(log_dir, name):
    return os.path.join(log_dir, name.replace(' ', '_') + '.log')


def last_line(path):
    lines = [line for line in tail(path, 20) if line.strip()]
    return lines[-1].strip() if lines else '(no output)'


def tail(path, lines):
    with open(path, errors='replace') as f:
        return f.read().splitlines()[-lines:]


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('--lanes', type=int, default=2)
    parser.add_argument('--only', default=','.join(PARTS), help='comma-separated, of: ' + ', '.join(PARTS))
    args = parser.parse_args(argv)
    parts = args.only.split(',')
    unknown = sorted(set(parts) - set(PARTS))
    if unknown or args.lanes < 1:
        parser.error('unknown part %s' % ', '.join(unknown) if unknown else '--lanes must be at least 1')
    build = os.path.join(REPOSITORY, 'build')
    log_dir = os.path.join(build, 'lanes')
    jobs = suite_jobs(parts, os.path.join(build, 'test_results'), make=os.environ.get('MAKE', 'make'))
    # a job's own make must not look for the jobserver of the make that started this
    env = {k: v for k, v in os.environ.items() if k not in ('MAKEFLAGS', 'MFLAGS', 'MAKELEVEL')}
    started = time.monotonic()
    ended = run_jobs(jobs, args.lanes, log_dir, env=env)
    for job in jobs:
        if job.name in SUITES_WITH_A_SUMMARY and job.name in ended:
            print('%s: %s' % (job.name, last_line(log_path(log_dir, job.name))))
    failed = [name for name, (status, _, _) in ended.items() if status != 0]
    for name in failed:
        print('---- %s (log %s), its last lines:' % (name, log_path(log_dir, name)))
        print('\n'.join(tail(log_path(log_dir, name), FAILED_LOG_LINES)))
    print('%d jobs in %d lanes, %.0f s, CPU %.0f s: %s' % (
        len(ended), args.lanes, time.monotonic() - started, sum(cpu for _, _, cpu in ended.values()),
        'all passed' if not failed else 'FAILED: ' + ', '.join(failed)))
    return 1 if failed else 0


if __name__ == '__main__':
    sys.exit(main())
