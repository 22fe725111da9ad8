"""The fleet part of ``make bench`` (``--only fleet``, issue 30): rason_mas processes over
``~fleet_channel mqtt`` through mosquitto (config/mosquitto/fleet.conf of the rason package),
on loopback and, with root, across network namespaces (``rason_hosts``).

1. :func:`round_trips`: achieve round trips alice -> bob -> alice between two rason_mas
   processes (agents/fleet.asl), p50/p99.
2. :func:`message_rate`: a simulated robot (``rason.messaging.mqtt.SimulatedFleet``) sends
   ``achieve echo`` to bob at a rate stepped up (:class:`fleetcalc.RateSearch`) and times the
   answers; the rate where p99 passes the bound.
3. :func:`departures`: 100 simulated robots and one rason_mas observing; some robots'
   connections end (their wills); kill -> the observer's ``-present``.
4. :func:`false_departures`: the same fleet across namespaces, the robots' link losing a share
   of its frames; departures the observer notices of robots that never left.

Every process prints what it measures (rason.time_ms, the monotonic clock of this machine in
every process and namespace); :class:`Watched` keeps the lines.
"""
import atexit
import contextlib
import math
import os
import re
import shutil
import socket
import subprocess
import sys
import tempfile
import threading
import time

import rospkg

from rason_bench import fleetcalc
from rason_bench.fleet_report import RATE_P99_BOUND_MS

AGENTS_DIR = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', 'agents'))


#: The message rate's first step (/s); it doubles from there.
RATE_START_PER_S = 50.0
#: The message rate's warm-up, steps of RATE_WARMUP_SECONDS at these rates (/s) before the
#: search: both JVMs compile the message path meanwhile (their second compiler tier takes a
#: method after some 10,000 calls; a search from cold measures the compiling, e.g. p99 52 ms
#: for the first 5 s at 1,000/s and 2 ms for the next 5 s). The report shows these steps too.
RATE_WARMUP_PER_S = (200.0, 600.0, 1000.0, 1000.0)
RATE_WARMUP_SECONDS = 5.0
#: How often a wait looks at the lines that came (s); the times measured are the processes' own.
POLL_S = 0.1


class FleetError(RuntimeError):
    """A process did not start, or did not say what was awaited in time."""


class Watched(object):
    """A process whose stdout lines are kept (and written to ``log_path``) with the
    time.monotonic they arrived."""

    def __init__(self, proc, log_path):
        self.proc = proc
        self._lines = []
        self._cond = threading.Condition()
        self._log = open(log_path, 'a')
        self._thread = threading.Thread(target=self._read, daemon=True)
        self._thread.start()

    def _read(self):
        for line in self.proc.stdout:
            line = line.rstrip('\n')
            self._log.write(line + '\n')
            self._log.flush()
            with self._cond:  # no notify per line: waiters look every POLL_S (they scan every line)
                self._lines.append(line)
        with self._cond:
            self._cond.notify_all()

    def lines(self):
        with self._cond:
            return list(self._lines)

    def count(self):
        with self._cond:
            return len(self._lines)

    def wait(self, ready, timeout, what, since=0):
        """Wait until ``ready(lines from index since)`` returns something true, and return it."""
        deadline = time.monotonic() + timeout
        with self._cond:
            while True:
                value = ready(self._lines[since:])
                if value:
                    return value
                left = deadline - time.monotonic()
                if left <= 0:
                    raise FleetError('no %s within %.0f s' % (what, timeout))
                if self.proc.poll() is not None and not self._thread.is_alive():
                    raise FleetError('the process ended (status %s) before %s' % (self.proc.returncode, what))
                self._cond.wait(min(left, POLL_S))

    def wait_line(self, pattern, timeout, what, since=0):
        """The first line from index since matching pattern (a regex match)."""
        rx = re.compile(pattern)
        return self.wait(lambda lines: next((m for m in map(rx.search, lines) if m), None), timeout, what, since)

    def send(self, text):
        self.proc.stdin.write(text + '\n')
        self.proc.stdin.flush()

    def close(self):
        self._log.close()


def free_port():
    with socket.socket() as s:
        s.bind(('127.0.0.1', 0))
        return s.getsockname()[1]


def fleet_conf():
    return os.path.join(rospkg.RosPack().get_path('rason'), 'config', 'mosquitto', 'fleet.conf')


def jason_lib_classpath():
    from rason_bridge.jvm import jason_lib_classpath as cp
    return os.pathsep.join(cp())


def write_key(folder):
    """A fleet key of this run (only its owner may read it), its path."""
    path = os.path.join(folder, 'fleet.key')
    fd = os.open(path, os.O_WRONLY | os.O_CREAT | os.O_TRUNC, 0o600)
    with os.fdopen(fd, 'w') as f:
        f.write('# the fleet benchmark\'s key\n%s\n' % os.urandom(24).hex())
    return path


class Loopback(object):
    """Everything on this machine's loopback: the bench's ROS master, a broker on a free port."""

    needs_root = False

    def __init__(self, procs, log_dir, tag):
        self.procs, self.log_dir, self.tag = procs, log_dir, tag
        self.started = []

    def broker_url(self):
        return 'tcp://127.0.0.1:%d' % self.port

    def start_broker(self):
        self.port = free_port()
        return self.start(None, 'mosquitto', [sys.executable, '-m', 'rason_hosts.broker', '--config', fleet_conf(),
                                              '--listen', '127.0.0.1', '--port', str(self.port)], ros=False)

    def start(self, host, name, argv, ros=True):
        proc = subprocess.Popen(argv, env=self.procs.env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                stdin=subprocess.PIPE, universal_newlines=True, start_new_session=True)
        watched = Watched(proc, os.path.join(self.log_dir, 'fleet_%s_%s.log' % (self.tag, name)))
        self.started.append(watched)
        return watched

    def close(self):
        for w in reversed(self.started):
            self.procs.stop(w.proc)
            w.close()


class Namespaces(object):
    """Each host a network namespace of its own (rason_hosts), the broker on host ``broker``;
    a ROS master on the loopback of each host that runs a rason_mas."""

    needs_root = True

    def __init__(self, names, log_dir, tag):
        from rason_hosts import Hosts
        self.log_dir, self.tag = log_dir, tag
        self.hosts = Hosts(['broker'] + list(names))
        try:
            self.hosts.start()
        except Exception:
            self.hosts.close()
            raise
        self.masters = set()
        self.started = []
        self.port = 1883  # every run has hosts of its own

    def broker_url(self):
        return 'tcp://%s:%d' % (self.hosts.address('broker'), self.port)

    def start_broker(self):
        return self.start('broker', 'mosquitto', [sys.executable, '-m', 'rason_hosts.broker', '--config', fleet_conf(),
                                                  '--listen', self.hosts.address('broker'), '--port', str(self.port)],
                          ros=False)

    def start(self, host, name, argv, ros=True):
        env = self.hosts.python_env(self.hosts.ros_env())
        if ros and host not in self.masters:
            core = self.hosts.run(host, ['roscore', '-p', '11311'], env=env, stdout=subprocess.PIPE,
                                  stderr=subprocess.STDOUT, universal_newlines=True)
            w = Watched(core, os.path.join(self.log_dir, 'fleet_%s_roscore_%s.log' % (self.tag, host)))
            self.started.append(w)
            w.wait_line('started core service', 60, 'ROS master on %s' % host)
            self.masters.add(host)
        proc = self.hosts.run(host, argv, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                              stdin=subprocess.PIPE, universal_newlines=True)
        watched = Watched(proc, os.path.join(self.log_dir, 'fleet_%s_%s.log' % (self.tag, name)))
        self.started.append(watched)
        return watched

    def close(self):
        try:
            for w in reversed(self.started):
                self.hosts.stop(w.proc)
                w.close()
        finally:
            self.hosts.close()


def start_mas(place, host, ns, mas2j, key, **params):
    """A rason_mas of the fleet (over MQTT) in namespace ns of host, running agents/mas2j."""
    argv = ['rosrun', 'rason_bridge', 'rason_mas', os.path.join(AGENTS_DIR, mas2j), '__ns:=/' + ns,
            '_fleet_channel:=mqtt', '_mqtt_url:=' + place.broker_url(), '_fleet_key_file:=' + key]
    argv += ['_%s:=%s' % kv for kv in sorted(params.items())]
    return place.start(host, 'rason_mas_%s' % ns, argv)


def start_fleet(place, host, key, robots):
    """``robots`` simulated robots (SimulatedFleet) on host; returns once they are connected."""
    sim = place.start(host, 'simulated_fleet', [
        'java', '-cp', jason_lib_classpath(), 'rason.messaging.mqtt.SimulatedFleet', '--url', place.broker_url(),
        '--key-file', key, '--robots', str(robots)], ros=False)
    sim.wait_line(r'^ready \d+', 90, 'the simulated robots connected')
    return sim


def wait_present(observer, robots, timeout, since=0):
    """Wait until the observer has said present of each of robots (agent names) since line index since."""
    wanted = set(robots)

    def all_seen(lines):
        seen = {m.group('robot') for m in map(fleetcalc.PRESENCE.search, lines) if m and m.group('what') == 'present'}
        return wanted <= seen
    observer.wait(all_seen, timeout, 'presence of %d robots' % len(wanted), since)


@contextlib.contextmanager
def placed(place):
    try:
        yield place
    finally:
        place.close()


def round_trips(place, key, hosts, warmup, count, log):
    """alice (host hosts[0]) pings bob (hosts[1]) over the broker: the round trips (ms) after warmup."""
    with placed(place):
        place.start_broker().wait_line(' running|Opening ipv4 listen', 15, 'mosquitto running')
        bob = start_mas(place, hosts[1], 'robot2', 'fleet_bob.mas2j', key)
        alice = start_mas(place, hosts[0], 'robot1', 'fleet_alice.mas2j', key)
        alice.wait(lambda lines: len(fleetcalc.round_trips(lines, 'alice', 0, 1 << 30)) >= warmup + count,
                   120 + 0.1 * (warmup + count), '%d round trips' % (warmup + count))
        samples = fleetcalc.round_trips(alice.lines(), 'alice', warmup, count)
        if bob.proc.poll() is not None:
            raise FleetError('bob ended during the round trips')
    s = fleetcalc.summary(samples)
    log('  round trip p50 %.2f ms, p99 %.2f ms (%d)' % (s['p50'], s['p99'], s['n']))
    return {'round_trip_ms': s, 'warmup': warmup}


def message_rate(place, key, seconds, log, search=None):
    """bob answers ``achieve echo`` from a simulated robot at rates stepped up: each step's
    answers (ms from when each message was due) and the search's answer."""
    search = search or fleetcalc.RateSearch(start=RATE_START_PER_S, bound_ms=RATE_P99_BOUND_MS)
    steps = []
    with placed(place):
        place.start_broker().wait_line(' running|Opening ipv4 listen', 15, 'mosquitto running')
        bob = start_mas(place, None, 'robot2', 'fleet_bob.mas2j', key)
        sim = start_fleet(place, None, key, 1)
        wait_present(bob, ['sim0'], 90)
        warmup = []
        for rate in RATE_WARMUP_PER_S:
            step, p99 = _step(_load(sim, rate, RATE_WARMUP_SECONDS), rate, log, ' (warm-up)')
            warmup.append(step)
        if p99 > RATE_P99_BOUND_MS:
            _drain(sim)
        rate = search.next_rate()
        while rate is not None:
            step, p99 = _step(_load(sim, rate, seconds), rate, log)
            steps.append(step)
            search.record(rate, p99)
            rate = search.next_rate()
            if p99 > RATE_P99_BOUND_MS and rate is not None:
                _drain(sim)
    return {'steps': steps, 'seconds_per_step': seconds, 'bound_ms': RATE_P99_BOUND_MS,
            'warmup': warmup, 'warmup_seconds_per_step': RATE_WARMUP_SECONDS,
            'highest_within': search.highest_within, 'lowest_beyond': search.lowest_beyond}


def _step(run, rate, log, what=''):
    """One load run as the report shows it (its answers' times left out), and its p99 (ms; inf
    when it fell among the unanswered)."""
    p99 = fleetcalc.tail_ms(run['ms'], run['sent'], 99)
    s = fleetcalc.summary(run['ms'])
    step = dict((k, v) for k, v in run.items() if k != 'ms')
    # None: p99 fell among the unanswered (JSON has no infinity)
    step.update(p50_ms=s.get('p50'), p99_ms=None if p99 == math.inf else p99, max_ms=s.get('max'))
    log('  %6.0f/s offered (%.0f/s achieved): %d of %d answered, p50 %s ms, p99 %s ms%s' % (
        rate, run['achieved_rate'] or 0, run['answered'], run['sent'],
        '%.1f' % s['p50'] if s['n'] else '-', '%.1f' % p99 if p99 != math.inf else 'inf', what))
    return step, p99


def _drain(sim, rounds=20):
    """After an overload: small probes until bob answers them all quickly again, so that the
    next step does not start on the last one's backlog."""
    for _ in range(rounds):
        run = _load(sim, 50.0, 0.2)
        if run['answered'] == run['sent'] and max(run['ms']) < RATE_P99_BOUND_MS / 5:
            return
    raise FleetError('bob still lags after an overload (%d probes)' % rounds)


def _load(sim, rate, seconds):
    since = sim.count()
    sim.send('load /robot2/rason_mas bob %g %g' % (rate, seconds))
    m = sim.wait_line(r'^load \d+ ', seconds + 30, 'the load run at %g/s' % rate, since)
    return fleetcalc.load_run(m.string)


def departures(place, key, hosts, robots, singles, batch, log):
    """``robots`` simulated robots on hosts[0], the observer on hosts[1]: ``singles`` robots'
    connections end one at a time, then ``batch`` at once; kill -> the observer's notice (ms)."""
    with placed(place):
        place.start_broker().wait_line(' running|Opening ipv4 listen', 15, 'mosquitto running')
        observer = start_mas(place, hosts[1], 'robot1', 'fleet_watcher.mas2j', key)
        sim = start_fleet(place, hosts[0], key, robots)
        wait_present(observer, ['sim%d' % i for i in range(robots)], 120)
        since_sim, since_obs = sim.count(), observer.count()
        order = list(range(robots - 1, robots - 1 - singles, -1))
        for index in order:
            sim.send('kill %d' % index)
            _wait_notice(observer, index, since_obs)
            time.sleep(0.3)  # spacing between kills, not a wait for a condition
        group = list(range(robots - 1 - singles, robots - 1 - singles - batch, -1))
        sim.send('kill ' + ' '.join(str(i) for i in group))
        for index in group:
            _wait_notice(observer, index, since_obs)
        kills, notices = _kills_and_notices(sim.lines()[since_sim:], observer.lines()[since_obs:])
        delays = fleetcalc.departure_delays(kills, notices)
        others = sorted({i for i, _ in notices if i not in kills})
    single = fleetcalc.summary([delays[i] for i in order if i in delays])
    grouped = fleetcalc.summary([delays[i] for i in group if i in delays])
    log('  one at a time: p50 %.0f ms, max %.0f ms; %d at once: max %.0f ms' % (
        single.get('p50', -1), single.get('max', -1), batch, grouped.get('max', -1)))
    return {'robots': robots, 'single_ms': single, 'batch_ms': grouped, 'batch': batch, 'singles': singles,
            'unnoticed': sorted(set(kills) - set(delays)), 'other_departures': others}


def _wait_notice(observer, index, since, timeout=10.0):
    """Wait for the observer's notice of sim<index>'s departure; one never given is reported
    as unnoticed, not waited for further."""
    rx = re.compile(r'\] absent sim%d ' % index)
    try:
        observer.wait(lambda lines: any(rx.search(l) for l in lines), timeout, 'departure of sim%d' % index, since)
    except FleetError:
        pass


def _kills_and_notices(sim_lines, observer_lines):
    kills = {}
    for line in sim_lines:
        m = fleetcalc.KILLED.match(line)
        if m:
            kills[int(m.group('index'))] = float(m.group('ms'))
    notices = []
    for line in observer_lines:
        m = fleetcalc.PRESENCE.search(line)
        if m and m.group('what') == 'absent' and m.group('robot').startswith('sim'):
            notices.append((int(m.group('robot')[3:]), float(m.group('ms'))))
    return kills, notices


def false_departures(key, robots, losses, window_s, log_dir, log):
    """Across namespaces: ``robots`` simulated robots on host ``robots``, the observer on host
    ``observer``; per loss (% of frames, on the robots' link only) ``window_s`` s in which no
    robot leaves: the departures the observer notices all the same, and per 10 minutes."""
    place = Namespaces(['robots', 'observer'], log_dir, 'false_departures')
    out = {'robots': robots, 'window_s': window_s, 'lossy_link': 'robots', 'levels': []}
    names = ['sim%d' % i for i in range(robots)]
    with placed(place):
        place.start_broker().wait_line(' running|Opening ipv4 listen', 15, 'mosquitto running')
        observer = start_mas(place, 'observer', 'robot1', 'fleet_watcher.mas2j', key)
        start_fleet(place, 'robots', key, robots)
        wait_present(observer, names, 120)
        for loss in losses:
            since = observer.count()
            place.hosts.shape('robots', loss=loss)
            time.sleep(window_s)  # the measured window itself
            place.hosts.shape('robots', loss=0)
            window = observer.lines()[since:]
            absent = [m.group('robot') for m in map(fleetcalc.PRESENCE.search, window)
                      if m and m.group('what') == 'absent' and m.group('robot').startswith('sim')]
            level = {'loss_percent': loss, 'departures': len(absent), 'robots_affected': len(set(absent)),
                     'per_10_min': fleetcalc.per_period(len(absent), window_s)}
            out['levels'].append(level)
            log('  %d %% loss: %d false departures in %g s (%d robots), %.1f per 10 min' % (
                loss, level['departures'], window_s, level['robots_affected'], level['per_10_min']))
            # the whole fleet back before the next level
            observer.wait(lambda lines: not fleetcalc.absent_now(lines), 60, 'every robot present again')
    return out


def namespaces_unavailable():
    """Why the namespace runs cannot be made here (None if they can)."""
    if os.geteuid() != 0:
        return 'network namespaces need root'
    for tool in ('/usr/sbin/nft', '/usr/sbin/mosquitto'):
        if not os.path.exists(tool):
            return '%s is not installed' % tool
    return None


def steps(procs, params, log_dir, log):
    """The fleet part's (key, title, measure) for rason_bench.main; params: main.FLEET (or
    FLEET_QUICK) with robots and losses. The fleet key lives in a private temporary folder."""
    folder = tempfile.mkdtemp(prefix='rason-bench-fleet-')
    atexit.register(shutil.rmtree, folder, True)
    key = write_key(folder)
    p = params
    skip = namespaces_unavailable()

    def across():
        if skip:
            return {'skipped': skip}
        return round_trips(Namespaces(['r1', 'r2'], log_dir, 'namespaces'), key, ('r1', 'r2'), p['warmup'],
                           p['round_trips'], log)

    def lossy():
        if skip:
            return {'skipped': skip}
        return false_departures(key, p['robots'], p['losses'], p['loss_window_s'], log_dir, log)
    return [
        ('fleet.loopback', 'fleet: achieve round trips over MQTT, loopback', lambda: round_trips(
            Loopback(procs, log_dir, 'loopback'), key, (None, None), p['warmup'], p['round_trips'], log)),
        ('fleet.namespaces', 'fleet: achieve round trips over MQTT, across network namespaces', across),
        ('fleet.rate', 'fleet: message rate until p99 passes %g ms' % RATE_P99_BOUND_MS, lambda: message_rate(
            Loopback(procs, log_dir, 'rate'), key, p['rate_seconds'], log)),
        ('fleet.departures', 'fleet: departures among %d simulated robots' % p['robots'], lambda: departures(
            Loopback(procs, log_dir, 'departures'), key, (None, None), p['robots'], p['singles'], p['batch'], log)),
        ('fleet.false_departures', 'fleet: false departures under loss, across network namespaces', lossy)]
