"""rason_budget on this machine's real CPU cgroups (v1 or v2): needs root (CI runs as root);
skipped, with the reason, when no CPU cgroup is writable."""
import os
import signal
import subprocess
import sys
import time

import pytest

from rason_budget import cgroups
from rason_budget.meter import Meter

try:
    HIERARCHY = cgroups.detect()
    WHY_NOT = ''
except (cgroups.BudgetError, OSError) as e:
    HIERARCHY, WHY_NOT = None, str(e)

pytestmark = pytest.mark.skipif(HIERARCHY is None, reason=WHY_NOT)
IN_BUDGET = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'scripts', 'in_budget')
SPIN = [sys.executable, '-c', 'while True: pass']


def _group_dirs(budget):
    return [d for g in budget.groups.values() for d in g.dirs]


def _wait_for(condition, timeout=10.0):
    deadline = time.monotonic() + timeout
    while not condition():
        if time.monotonic() > deadline:
            return False
        time.sleep(0.05)
    return True


def test_a_spinning_process_is_held_to_its_quota_and_measured():
    with cgroups.Budget({'spinner': 0.2}) as budget:
        dirs = _group_dirs(budget)
        assert budget.groups['spinner'].quota_cores() == pytest.approx(0.2)
        spin = subprocess.Popen(SPIN)
        try:
            budget.join('spinner', spin.pid)
            with Meter(budget, interval=0.25) as m:
                time.sleep(2.0)  # the measuring window itself
        finally:
            spin.kill()
            spin.wait()
    s = m.summary()['robots']['spinner']
    # a busy loop wants a whole core; the quota gives it 0.2 (some of a period's slack at the ends)
    assert 0.05 < s['cpu_mean_cores'] <= 0.25, s
    assert s['throttling']['throttled_periods'] > 0, s
    assert [p['pid'] for p in s['processes']] == [spin.pid]
    assert s['processes'][0]['rss_peak_mb'] > 1.0
    assert not any(os.path.exists(d) for d in dirs)


def test_in_budget_joins_the_robots_group_then_runs_the_command():
    with cgroups.Budget({'faulty': None}) as budget:
        out = subprocess.run([IN_BUDGET, 'faulty', 'cat', '/proc/self/cgroup'], env=dict(os.environ, **budget.env),
                             stdout=subprocess.PIPE, universal_newlines=True, check=True).stdout
        assert '/%s\n' % budget.groups['faulty'].name in out
        gone = subprocess.run([IN_BUDGET, 'helper', 'true'], env=dict(os.environ, **budget.env),
                              stderr=subprocess.PIPE, universal_newlines=True)
    assert gone.returncode == 2 and 'no CPU group rason-%s-helper' % budget.run_id in gone.stderr


def test_groups_are_removed_even_with_a_process_still_in_them():
    budget = cgroups.Budget({'faulty': 0.5}).start()
    dirs = _group_dirs(budget)
    sleeper = subprocess.Popen(['sleep', '30'])
    try:
        budget.join('faulty', sleeper.pid)
        budget.close()
        assert not any(os.path.exists(d) for d in dirs)
        assert sleeper.poll() is None  # not ours to end: moved out of the group
    finally:
        sleeper.kill()
        sleeper.wait()


def test_the_groups_of_a_crashed_run_are_cleaned_and_a_live_runs_are_not():
    owner = subprocess.Popen([sys.executable, '-c', 'import sys, time\n'
                              'from rason_budget import cgroups\n'
                              'b = cgroups.Budget({"faulty": 0.5}).start()\n'
                              'print(b.run_id, flush=True)\n'
                              'time.sleep(60)\n'], stdout=subprocess.PIPE, universal_newlines=True,
                             env=dict(os.environ, PYTHONPATH=os.pathsep.join(sys.path)))
    crashed = None
    try:
        run_id = owner.stdout.readline().strip()
        crashed = cgroups.CpuGroup(HIERARCHY, cgroups.group_name(cgroups.DEFAULT_PREFIX, run_id, 'faulty'))
        assert all(os.path.isdir(d) for d in crashed.dirs)
        assert crashed.name not in cgroups.cleanup(HIERARCHY)  # its owner is alive
        assert all(os.path.isdir(d) for d in crashed.dirs)
        owner.send_signal(signal.SIGKILL)
        owner.wait()
        assert crashed.name in cgroups.cleanup(HIERARCHY)
        assert not any(os.path.exists(d) for d in crashed.dirs)
    finally:
        owner.kill()
        owner.wait()
        if crashed is not None:
            crashed.remove()
