"""CPU cgroups, one per robot: ``rason-RUN-ROBOT`` with a quota of ``cores`` CPUs.

cgroup v1 (controllers ``cpu`` and ``cpuacct``, mounted together or apart) and v2 (the
unified hierarchy with the ``cpu`` controller) are both handled; :func:`detect` says which
one this machine has, or raises :class:`BudgetError` with the reason when neither can be
written (not root, a read-only mount, no cpu controller). A :class:`Budget` removes its
groups on close and at interpreter exit; :func:`cleanup` removes those of crashed runs
(their owner process is gone), as rason_hosts does with network namespaces."""
import atexit
import errno
import os
import re
import secrets
import time

from rason_hosts.owners import owner_alive, owner_file, record_owner

OWNERS_DIR = '/run/rason-budget'   # one file per live run: the owning process (pid, start time)
DEFAULT_PREFIX = 'rason'
ROBOT_NAME = re.compile(r'^[a-z0-9][a-z0-9_]{0,23}$')
DEFAULT_PERIOD_US = 100000


class BudgetError(RuntimeError):
    pass


def parse_mounts(text):
    """(v1, v2) from /proc/self/mounts: v1 maps each cgroup v1 controller (``cpu``,
    ``cpuacct``, ...) to its mount point; v2 is the cgroup2 mount point or None."""
    v1, v2 = {}, None
    for line in text.splitlines():
        fields = line.split()
        if len(fields) < 4:
            continue
        where, fstype, options = fields[1], fields[2], fields[3].split(',')
        if fstype == 'cgroup2' and v2 is None:
            v2 = where
        elif fstype == 'cgroup':
            for option in options:
                if option in ('cpu', 'cpuacct', 'memory') and option not in v1:
                    v1[option] = where
    return v1, v2


class Hierarchy(object):
    """Where the groups go: ``version`` 1 or 2, ``cpu_root`` (the quota) and ``acct_root``
    (the usage; the same directory on v2 and on a v1 with cpu,cpuacct mounted together)."""

    def __init__(self, version, cpu_root, acct_root=None):
        self.version = version
        self.cpu_root = cpu_root
        self.acct_root = acct_root or cpu_root

    @property
    def roots(self):
        return [self.cpu_root] if self.acct_root == self.cpu_root else [self.cpu_root, self.acct_root]

    def __repr__(self):
        return 'cgroup v%d (%s)' % (self.version, ', '.join(self.roots))


def detect(mounts='/proc/self/mounts'):
    """The writable CPU cgroup hierarchy of this machine.

    :raises BudgetError: neither v1 (cpu and cpuacct) nor v2 (with the cpu controller) is
        mounted and writable; the message says what was found
    """
    with open(mounts) as f:
        v1, v2 = parse_mounts(f.read())
    found = []
    if 'cpu' in v1 and 'cpuacct' in v1:
        h = Hierarchy(1, v1['cpu'], v1['cpuacct'])
        unwritable = [r for r in h.roots if not os.access(r, os.W_OK)]
        if not unwritable:
            return h
        found.append('cgroup v1 at %s is not writable (run as root)' % ', '.join(unwritable))
    elif v1:
        found.append('cgroup v1 without both cpu and cpuacct (has %s)' % ', '.join(sorted(v1)))
    if v2 is not None:
        try:
            with open(os.path.join(v2, 'cgroup.controllers')) as f:
                controllers = f.read().split()
        except OSError:
            controllers = []
        if 'cpu' not in controllers:
            found.append('cgroup v2 at %s without the cpu controller (it has: %s)'
                         % (v2, ' '.join(controllers) or 'none'))
        elif not os.access(os.path.join(v2, 'cgroup.subtree_control'), os.W_OK):
            found.append('cgroup v2 at %s is not writable (run as root)' % v2)
        else:
            return Hierarchy(2, v2)
    raise BudgetError('no writable CPU cgroup: %s' % ('; '.join(found) or 'no cgroup file system mounted'))


def _write(path, value):
    with open(path, 'w') as f:
        f.write(str(value))


def _read(path):
    with open(path) as f:
        return f.read()


def group_name(prefix, run_id, robot):
    return '%s-%s-%s' % (prefix, run_id, robot)


class CpuGroup(object):
    """One robot's group in ``hierarchy``: a quota of ``cores`` (None: no limit, measured only)."""

    def __init__(self, hierarchy, name):
        self.hierarchy = hierarchy
        self.name = name
        self.dirs = [os.path.join(root, name) for root in hierarchy.roots]

    @property
    def cpu_dir(self):
        return self.dirs[0]

    @property
    def acct_dir(self):
        return self.dirs[-1]

    def create(self, cores, period_us=DEFAULT_PERIOD_US):
        if self.hierarchy.version == 2:
            control = os.path.join(self.hierarchy.cpu_root, 'cgroup.subtree_control')
            if 'cpu' not in _read(control).split():
                try:
                    _write(control, '+cpu')
                except OSError as e:  # EBUSY: a non-root group with processes of its own (a container's)
                    raise BudgetError('cannot enable the cpu controller in %s (%s): in a container, move its '
                                      'processes into a child group first, or give it a delegated cgroup'
                                      % (control, e.strerror))
        for d in self.dirs:
            os.mkdir(d)
        self.set_quota(cores, period_us)

    def set_quota(self, cores, period_us=DEFAULT_PERIOD_US):
        quota = -1 if cores is None else max(1000, int(round(cores * period_us)))
        if self.hierarchy.version == 2:
            _write(os.path.join(self.cpu_dir, 'cpu.max'), '%s %d' % ('max' if quota < 0 else quota, period_us))
        else:
            _write(os.path.join(self.cpu_dir, 'cpu.cfs_period_us'), period_us)
            _write(os.path.join(self.cpu_dir, 'cpu.cfs_quota_us'), quota)

    def quota_cores(self):
        """The quota in cores, None when unlimited."""
        if self.hierarchy.version == 2:
            quota, period = _read(os.path.join(self.cpu_dir, 'cpu.max')).split()
            return None if quota == 'max' else int(quota) / float(period)
        quota = int(_read(os.path.join(self.cpu_dir, 'cpu.cfs_quota_us')))
        period = int(_read(os.path.join(self.cpu_dir, 'cpu.cfs_period_us')))
        return None if quota < 0 else quota / float(period)

    def join(self, pid):
        """Move process ``pid`` (all its threads) into the group."""
        for d in self.dirs:
            _write(os.path.join(d, 'cgroup.procs'), pid)

    def pids(self):
        try:
            return [int(p) for p in _read(os.path.join(self.cpu_dir, 'cgroup.procs')).split()]
        except OSError:
            return []

    def usage_ns(self):
        """CPU time used by the group's processes since it was made (ns)."""
        if self.hierarchy.version == 2:
            return 1000 * _cpu_stat(os.path.join(self.cpu_dir, 'cpu.stat'))['usage_usec']
        return int(_read(os.path.join(self.acct_dir, 'cpuacct.usage')))

    def throttling(self):
        """{'periods', 'throttled_periods', 'throttled_s'}: how often the quota held it back."""
        s = _cpu_stat(os.path.join(self.cpu_dir, 'cpu.stat'))
        throttled_s = s['throttled_usec'] / 1e6 if 'throttled_usec' in s else s.get('throttled_time', 0) / 1e9
        return {'periods': s.get('nr_periods', 0), 'throttled_periods': s.get('nr_throttled', 0),
                'throttled_s': round(throttled_s, 3)}

    def remove(self, timeout=5.0):
        """Move what is left in the group to the root group (a process still running there
        is not ours to end), then remove the directories."""
        for d, root in zip(self.dirs, self.hierarchy.roots):
            deadline = time.monotonic() + timeout
            while os.path.isdir(d):
                try:
                    for pid in _read(os.path.join(d, 'cgroup.procs')).split():
                        try:
                            _write(os.path.join(root, 'cgroup.procs'), pid)
                        except OSError as e:  # ended meanwhile
                            if e.errno != errno.ESRCH:
                                raise
                    os.rmdir(d)
                except OSError as e:
                    if e.errno == errno.ENOENT:
                        break
                    if e.errno != errno.EBUSY or time.monotonic() > deadline:
                        raise BudgetError('cannot remove %s: %s' % (d, e))
                    time.sleep(0.05)  # a process was ending (a zombie still counts)


def _cpu_stat(path):
    out = {}
    for line in _read(path).splitlines():
        key, _, value = line.partition(' ')
        if value.strip().isdigit():
            out[key] = int(value)
    return out


def _owner_file(prefix, run_id):
    return owner_file(OWNERS_DIR, prefix, run_id)


def _owner_alive(prefix, run_id):
    return owner_alive(OWNERS_DIR, prefix, run_id)


def leftover_groups(hierarchy, prefix=DEFAULT_PREFIX, all_runs=False):
    """[(run_id, group name)] of this prefix whose owner process is gone (all_runs: every one)."""
    pattern = re.compile(r'^%s-([0-9a-f]+)-([a-z0-9_]+)$' % re.escape(prefix))
    out = set()
    for root in hierarchy.roots:
        for name in os.listdir(root):
            m = pattern.match(name)
            if m and os.path.isdir(os.path.join(root, name)) and (all_runs or not _owner_alive(prefix, m.group(1))):
                out.add((m.group(1), name))
    return sorted(out)


def cleanup(hierarchy=None, prefix=DEFAULT_PREFIX, all_runs=False):
    """Remove the groups crashed runs left (all_runs: every run's); the names removed."""
    hierarchy = hierarchy or detect()
    removed = []
    for run_id, name in leftover_groups(hierarchy, prefix, all_runs):
        CpuGroup(hierarchy, name).remove()
        try:
            os.remove(_owner_file(prefix, run_id))
        except OSError:
            pass
        removed.append(name)
    return removed


class Budget(object):
    """A CPU group per robot for one run: ``Budget({'faulty': 0.5, 'helper': 0.5})`` makes
    ``rason-RUN-faulty`` and ``rason-RUN-helper``, each held to half a core (a value of None:
    no quota, the group only measures). Processes join with :meth:`join` or by starting
    through ``in_budget ROBOT`` with ``RASON_BUDGET_RUN=RUN`` (:attr:`env`).

    :param period_us: the scheduler period the quota is a share of (100 ms, the kernel's default)
    :param clean_leftovers: on start, remove the groups crashed runs left (never a live run's)
    """

    def __init__(self, robots, run_id=None, prefix=DEFAULT_PREFIX, period_us=DEFAULT_PERIOD_US,
                 hierarchy=None, clean_leftovers=True):
        for robot in robots:
            if not ROBOT_NAME.match(robot):
                raise BudgetError('bad robot name %r: lower-case letters, digits and _' % robot)
        self.robots = dict(robots)
        self.run_id = run_id or secrets.token_hex(3)
        self.prefix = prefix
        self.period_us = period_us
        self.hierarchy = hierarchy
        self.clean_leftovers = clean_leftovers
        self.groups = {}

    @property
    def env(self):
        """What ``in_budget`` needs in the environment of the processes it starts."""
        return {'RASON_BUDGET_RUN': self.run_id, 'RASON_BUDGET_PREFIX': self.prefix}

    def start(self):
        self.hierarchy = self.hierarchy or detect()
        if self.clean_leftovers:
            cleanup(self.hierarchy, self.prefix)
        record_owner(OWNERS_DIR, self.prefix, self.run_id)
        atexit.register(self.close)
        try:
            for robot, cores in sorted(self.robots.items()):
                group = CpuGroup(self.hierarchy, group_name(self.prefix, self.run_id, robot))
                self.groups[robot] = group
                group.create(cores, self.period_us)
        except Exception:
            self.close()
            raise
        return self

    def join(self, robot, pid):
        self.groups[robot].join(pid)

    def close(self):
        """Remove every group (idempotent); raises BudgetError if one could not be removed."""
        errors = []
        for group in self.groups.values():
            try:
                group.remove()
            except BudgetError as e:
                errors.append(str(e))
        self.groups = {}
        try:
            os.remove(_owner_file(self.prefix, self.run_id))
        except OSError:
            pass
        atexit.unregister(self.close)
        if errors:
            raise BudgetError('; '.join(errors))

    def __enter__(self):
        return self.start()

    def __exit__(self, *exc):
        self.close()


def join_by_name(robot, pid, env=None, hierarchy=None):
    """What ``in_budget`` does: put ``pid`` in ``rason-$RASON_BUDGET_RUN-ROBOT``.

    :raises BudgetError: RASON_BUDGET_RUN unset, or no such group (the run that made it is
        over, or another machine's)
    """
    env = os.environ if env is None else env
    run_id = env.get('RASON_BUDGET_RUN', '')
    if not run_id:
        raise BudgetError('RASON_BUDGET_RUN is not set: start the launch under a budget, e.g. '
                          '"rosrun rason budget run --cores 0.5 --robot %s -- roslaunch ..."' % robot)
    group = CpuGroup(hierarchy or detect(), group_name(env.get('RASON_BUDGET_PREFIX', DEFAULT_PREFIX), run_id, robot))
    if not all(os.path.isdir(d) for d in group.dirs):
        raise BudgetError('no CPU group %s (is the budget run %s still on?)' % (group.name, run_id))
    group.join(pid)
    return group
