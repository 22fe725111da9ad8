"""Measuring a budget run: every ``interval`` s, each robot group's CPU usage and each of
its processes' CPU time and RSS (and, given the run's root process, those of the processes
outside every group: master, simulator, recorder). :func:`summarize` turns what was seen
into per-robot numbers: CPU in cores (mean over the run, p95 over the intervals) and RSS per
process (peak, VmHWM) and in total."""
import math
import threading
import time

from rason_budget import procstat

OUTSIDE = 'outside'
#: The first seconds of a run, when the JVM and the nodes start: a burst a robot has once.
START_UP_S = 15.0


def percentile(values, q):
    """Nearest-rank percentile (q in [0, 100]) of a non-empty list."""
    ordered = sorted(values)
    return ordered[max(0, int(math.ceil(q / 100.0 * len(ordered))) - 1)]


class Observation(object):
    """What was seen of one process: CPU seconds at first and last look, RSS, peak RSS."""

    def __init__(self, where, s, born_in_run):
        self.where, self.pid, self.name = where, s.pid, s.name
        # a process started after the meter: its CPU time from its start counts
        self.first_cpu_s = 0.0 if born_in_run else s.cpu_s
        self.last_cpu_s = s.cpu_s
        self.rss_max_kb = s.rss_kb
        self.hwm_kb = s.hwm_kb
        self.rss_last_kb = s.rss_kb

    def update(self, s):
        if s.name:  # a launch prefix execs the node: its name from then on; none once it ended
            self.name = s.name
        self.last_cpu_s = s.cpu_s
        self.rss_max_kb = max(self.rss_max_kb, s.rss_kb)
        self.hwm_kb = max(self.hwm_kb, s.hwm_kb)
        self.rss_last_kb = s.rss_kb

    @property
    def cpu_s(self):
        return self.last_cpu_s - self.first_cpu_s


class Meter(object):
    """Samples ``budget``'s groups in a thread from :meth:`start` to :meth:`stop`.

    :param root_pid: a callable giving the run's root process (or None) at each sample, to
        also see the processes of its tree that are in no group
    """

    def __init__(self, budget, interval=0.5, root_pid=None):
        self.budget = budget
        self.interval = interval
        self.root_pid = root_pid or (lambda: None)
        self.usage = {robot: [] for robot in budget.groups}   # [(t, ns)]
        self.rss_total = {robot: [] for robot in budget.groups}  # [kB] at each look
        self.counts = {robot: [] for robot in budget.groups}  # [(t, processes in the group)]
        self.procs = {}  # (where, pid) -> Observation
        self.throttling = {}
        self._stop = threading.Event()
        self._thread = threading.Thread(target=self._run, name='budget-meter', daemon=True)
        self._start_ticks = None

    def start(self):
        self._start_ticks = procstat.uptime_ticks()
        self.sample()
        self._thread.start()
        return self

    def stop(self):
        if self._thread.is_alive():
            self._stop.set()
            self._thread.join()
            self.sample()
        for robot, group in self.budget.groups.items():
            self.throttling[robot] = group.throttling()

    def __enter__(self):
        return self.start()

    def __exit__(self, *exc):
        self.stop()

    def _run(self):
        while not self._stop.wait(self.interval):
            self.sample()

    def _see(self, where, pid):
        s = procstat.sample(pid)
        if s is None:
            return 0
        key = (where, pid)
        if key in self.procs:
            self.procs[key].update(s)
        else:
            self.procs[key] = Observation(where, s, s.start_ticks >= self._start_ticks)
        return s.rss_kb

    def sample(self):
        now = time.monotonic()
        inside = set()
        for robot, group in self.budget.groups.items():
            try:
                self.usage[robot].append((now, group.usage_ns()))
            except OSError:
                continue
            pids = group.pids()
            inside.update(pids)
            for pid in pids:  # seen outside before in_budget joined the group: only inside counts
                self.procs.pop((OUTSIDE, pid), None)
            self.rss_total[robot].append(sum(self._see(robot, pid) for pid in pids))
            self.counts[robot].append((now, len(pids)))
        root = self.root_pid()
        if root:
            in_a_group = {pid for where, pid in self.procs if where != OUTSIDE}
            for pid in procstat.descendants(root):
                if pid not in inside and pid not in in_a_group:
                    self._see(OUTSIDE, pid)

    def summary(self):
        return summarize(self.usage, self.rss_total, self.procs.values(), self.throttling,
                         {r: self.budget.robots[r] for r in self.usage}, self.interval,
                         running_until=first_departure(self.counts))


def _mb(kb):
    return round(kb / 1024.0, 1)


def _process_rows(observations, seconds):
    rows = [{'name': o.name, 'pid': o.pid, 'cpu_s': round(o.cpu_s, 2),
             'cpu_mean_cores': round(o.cpu_s / seconds, 3) if seconds else None,
             'rss_peak_mb': _mb(max(o.hwm_kb, o.rss_max_kb)), 'rss_last_mb': _mb(o.rss_last_kb)}
            for o in observations]
    return sorted(rows, key=lambda r: -r['cpu_s'])


def first_departure(counts):
    """The first time (monotonic) a group had fewer processes than it once had: the run's
    shut-down begins (in the case study Faulty's agents stop), or None."""
    ends = []
    for series in counts.values():
        most = 0
        for t, n in series:
            if n < most:
                ends.append(t)
                break
            most = max(most, n)
    return min(ends) if ends else None


def summarize(usage, rss_total, observations, throttling, quotas, interval, start_up_s=START_UP_S,
              running_until=None):
    """Per robot: CPU in cores (mean over the run; p95 and max over the sampling intervals;
    p95 while running: after the first ``start_up_s`` s and up to ``running_until`` (monotonic
    time, when shut-down began); and each interval's as ``cores_series``),
    CPU seconds, how often the quota throttled it, RSS in total (peak of the sum of its
    processes at a look, and the sum of their peaks) and per process; the same per process
    for those outside every group."""
    out = {'interval_s': interval, 'robots': {}}
    seconds = None
    for robot, series in sorted(usage.items()):
        if len(series) < 2:
            continue
        t0, u0 = series[0]
        t1, u1 = series[-1]
        seconds = t1 - t0
        windows = [(b[0] - t0, (b[1] - a[1]) / 1e9 / (b[0] - a[0])) for a, b in zip(series, series[1:]) if b[0] > a[0]]
        cores = [c for _, c in windows]
        end = (running_until - t0) if running_until is not None else seconds
        running = [c for t, c in windows if start_up_s < t <= end]
        mine = [o for o in observations if o.where == robot]
        out['robots'][robot] = {
            'quota_cores': quotas.get(robot), 'seconds': round(seconds, 1),
            'cpu_s': round((u1 - u0) / 1e9, 2),
            'cpu_mean_cores': round((u1 - u0) / 1e9 / seconds, 3) if seconds else None,
            'cpu_p95_cores': round(percentile(cores, 95), 3) if cores else None,
            'cpu_max_cores': round(max(cores), 3) if cores else None,
            'start_up_s': start_up_s,
            'running_s': [start_up_s, round(end, 2)],
            'cpu_p95_running_cores': round(percentile(running, 95), 3) if running else None,
            'cores_series': [[round(t, 2), round(c, 3)] for t, c in windows],
            'throttling': throttling.get(robot),
            'rss_total_peak_mb': _mb(max(rss_total.get(robot) or [0])),
            'rss_sum_of_peaks_mb': _mb(sum(max(o.hwm_kb, o.rss_max_kb) for o in mine)),
            'processes': _process_rows(mine, seconds)}
    outside = [o for o in observations if o.where == OUTSIDE]
    if outside:
        out[OUTSIDE] = {'cpu_s': round(sum(o.cpu_s for o in outside), 2),
                        'processes': _process_rows(outside, seconds)}
    return out
