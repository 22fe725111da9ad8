"""Running one campaign run: ``roslaunch rason faulty_helper.launch`` (or the launch file of
the run's arm, ``RunSpec.launch``) on a master of its own that the launch starts, with a
wall-clock timeout after which the whole launch is stopped.

:class:`PrivateMaster` (a ``roscore`` on a free port, stopped by its PID) is also what
``rason_bench`` starts its benchmarks on."""
import json
import os
import signal
import socket
import subprocess
import threading
import time
import xmlrpc.client

from rason_campaign.plan import launch_arguments


class RunRecord(object):
    """What the runner saw of a run: exit code (None if it had to be killed), wall seconds,
    whether it timed out, the bag and the launch log."""

    def __init__(self, exit_code, wall, timed_out, bag, log):
        self.exit_code = exit_code
        self.wall = wall
        self.timed_out = timed_out
        self.bag = bag
        self.log = log

    @property
    def failure(self):
        """Why the run did not end by itself as it should, or None."""
        if self.timed_out:
            return 'timed out after %.0f s' % self.wall
        if self.exit_code not in (0, None):
            return 'roslaunch exited with code %s' % self.exit_code
        return None

    def to_dict(self):
        return {'exit_code': self.exit_code, 'wall': self.wall, 'timed_out': self.timed_out,
                'bag': self.bag, 'log': self.log}

    @classmethod
    def from_dict(cls, d):
        return cls(**d)

    def save(self, path):
        with open(path, 'w') as f:
            json.dump(self.to_dict(), f, indent=1)

    @classmethod
    def load(cls, path):
        with open(path) as f:
            return cls.from_dict(json.load(f))


def port_free(port):
    """True when 127.0.0.1:port can be bound now (a master left there would be reused by
    roslaunch, mixing two runs). Connections of a previous run still closing (TIME_WAIT) do
    not count: the master binds with SO_REUSEADDR too."""
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as s:
        s.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        try:
            s.bind(('127.0.0.1', port))
        except OSError:
            return False
    return True


def pick_port(base=None, span=50):
    """The first free port in base .. base + span - 1, or, without base, one the system
    chooses among its free ones.

    :raises RuntimeError: none of the span is free
    """
    if base is None:
        with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as s:
            s.bind(('127.0.0.1', 0))
            return s.getsockname()[1]
    for port in range(base, base + span):
        if port_free(port):
            return port
    raise RuntimeError('no free port in %d..%d for a ROS master' % (base, base + span - 1))


class _Transport(xmlrpc.client.Transport):
    """XML-RPC over HTTP with a connect and read timeout."""

    def __init__(self, timeout):
        super(_Transport, self).__init__()
        self._timeout = timeout

    def make_connection(self, host):
        conn = super(_Transport, self).make_connection(host)
        conn.timeout = self._timeout
        return conn


_CALLER = '/rason_private_master'


def master_is_up(uri, timeout=0.5):
    """True when a ROS master at ``uri`` answers ``getPid``."""
    proxy = xmlrpc.client.ServerProxy(uri, transport=_Transport(timeout))
    try:
        return proxy.getPid(_CALLER)[0] == 1
    except (OSError, xmlrpc.client.Error):
        return False


class PrivateMaster(object):
    """A ``roscore`` of our own on a free port, in a session of its own, stopped by its PID.

    :param log: file its output is appended to
    :param port: the port; by default one the system says is free
    :param command: what to run instead of ``roscore -p PORT`` (tests)
    """

    def __init__(self, log, port=None, command=None):
        self.port = port or pick_port()
        self.uri = 'http://127.0.0.1:%d' % self.port
        self.log = log
        self._command = list(command) if command else ['roscore', '-p', str(self.port)]
        self._proc = None

    def env(self, base=None):
        """``base`` (default os.environ) with ROS_MASTER_URI set to this master."""
        return master_env(self.uri, base)

    def start(self, timeout=20.0):
        """Start it and wait until it answers.

        :raises RuntimeError: it ended or did not answer within ``timeout`` s (then stopped)
        """
        if master_is_up(self.uri):
            raise RuntimeError('a ROS master already runs on port %d' % self.port)
        with open(self.log, 'ab') as out:
            self._proc = subprocess.Popen(TAKING_SIGINT + self._command, env=self.env(), stdout=out,
                                          stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL,
                                          start_new_session=True)
        deadline = time.monotonic() + timeout
        while not master_is_up(self.uri):
            if time.monotonic() > deadline or self._proc.poll() is not None:
                self.stop()
                raise RuntimeError('roscore on port %d did not start (see %s)' % (self.port, self.log))
            time.sleep(0.1)
        return self

    def stop(self, grace=15.0):
        """SIGINT (roscore then stops the master and rosout); SIGKILL to its process group
        (its session: roscore and what it started) if it has not ended within ``grace`` s."""
        proc, self._proc = self._proc, None
        if proc is None or proc.poll() is not None:
            return
        proc.send_signal(signal.SIGINT)
        try:
            proc.wait(grace)
        except subprocess.TimeoutExpired:  # still alive, so the group is still ours
            _signal_group(proc.pid, signal.SIGKILL)
            proc.wait(5.0)

    @property
    def running(self):
        return self._proc is not None and self._proc.poll() is None

    def __enter__(self):
        return self.start()

    def __exit__(self, *exc):
        self.stop()


def _signal_group(pgid, sig):
    """Signal the process group we started (its own session), if anything of it is left."""
    try:
        os.killpg(pgid, sig)
    except ProcessLookupError:
        pass


# A shell starts a background job (a campaign left running) with SIGINT ignored, and its
# children would inherit that: roscore and roslaunch would then sit out the SIGINT that stops
# them cleanly (the bag closed) until SIGTERM after the grace. GNU env gives them the default.
TAKING_SIGINT = ['env', '--default-signal=INT']


def _stop(proc, grace=20.0):
    """SIGINT to the launch's process group (roslaunch then stops its nodes and the recorder
    closes the bag), then SIGTERM, then SIGKILL."""
    for sig, wait in ((signal.SIGINT, grace), (signal.SIGTERM, 5.0), (signal.SIGKILL, 5.0)):
        try:
            os.killpg(proc.pid, sig)
        except ProcessLookupError:
            return
        try:
            proc.wait(wait)
            return
        except subprocess.TimeoutExpired:
            continue


def _stop_leftovers(pgid):
    """Anything of the launch's process group still alive after roslaunch ended."""
    _signal_group(pgid, signal.SIGTERM)


def _recover_bag(bag):
    """A recorder killed before closing leaves ``bag.active``: reindex it into ``bag``."""
    active = bag + '.active'
    if os.path.exists(bag) or not os.path.exists(active):
        return
    subprocess.call(['rosbag', 'reindex', active], stdout=subprocess.DEVNULL,
                    stderr=subprocess.DEVNULL)
    orig = active.replace('.bag.active', '.orig.bag.active')
    if os.path.exists(orig):
        os.remove(orig)
    os.rename(active, bag)


class RunInterrupted(Exception):
    """The run was stopped by :func:`stop_all` (Ctrl-C): it gets no record, so that
    ``--resume`` makes it again rather than count a run cut short."""


# Launches under way (runs on several slots at once), so Ctrl-C can stop them all, and those
# stop_all stopped.
_live = set()
_interrupted = set()
_live_lock = threading.Lock()


def stop_all():
    """Stops every launch under way (bag closed); their runs raise RunInterrupted."""
    with _live_lock:
        procs = list(_live)
        _interrupted.update(procs)
    for proc in procs:
        _stop(proc)


# A run's JVMs live for seconds: with the client compiler alone and the serial collector
# they cost about 45 % less CPU (2.4 s of a run's ~19 s) than with the tiered compiler and
# G1 that suit a robot's long-lived rason_mas; their peak speed is never needed. The
# shell's RASON_JVM_OPTIONS come after these (a later JVM option wins).
RUN_JVM_OPTIONS = '-XX:TieredStopAtLevel=1 -XX:-UseG1GC -XX:+UseSerialGC'


def master_env(master_uri, base=None):
    """``base`` (default os.environ) with ROS_MASTER_URI ``master_uri``."""
    return dict(os.environ if base is None else base, ROS_MASTER_URI=master_uri)


def launch_env(master_uri, base=None):
    """The environment of a run's roslaunch: :func:`master_env`, RASON_JVM_OPTIONS led by
    :data:`RUN_JVM_OPTIONS`."""
    env = master_env(master_uri, base)
    env['RASON_JVM_OPTIONS'] = (RUN_JVM_OPTIONS + ' ' + env.get('RASON_JVM_OPTIONS', '')).strip()
    return env


def run(spec, bag_dir, timeout, base_port=11611, env=None, on_start=None):
    """Run ``spec`` to its end or ``timeout`` wall seconds, on a master of its own (first
    free port from ``base_port``); the bag and the launch's log go to
    ``bag_dir/<spec.name>.bag|.log``, the record to ``.run.json``.

    roslaunch starts that master and rosout itself (no master answers on the port it is
    given) and stops them when the launch ends: a Python process less per run than a
    ``roscore`` beside it. A master is not kept for several runs: it would try to shut down
    the nodes of the run before, by their old addresses, when this run's nodes register
    with the same names, and an address a node of this run got since then made that node
    stop (a campaign saw it).

    :rtype: RunRecord
    """
    bag_dir = os.path.abspath(bag_dir)  # roslaunch runs the recorder in ROS_HOME
    bag = os.path.join(bag_dir, spec.name + '.bag')
    log = os.path.join(bag_dir, spec.name + '.log')
    for stale in (bag, bag + '.active'):
        if os.path.exists(stale):
            os.remove(stale)
    port = pick_port(base_port)  # free: no master of another run answers there
    cmd = ['roslaunch', '--port', str(port)] + list(spec.launch) + launch_arguments(spec, bag)
    with open(log, 'w') as out:
        out.write(' '.join(cmd) + '\n')
    timed_out, returncode, wall = _launch(cmd, 'http://127.0.0.1:%d' % port, log, timeout, env, on_start)
    record = RunRecord(None if timed_out else returncode, wall, timed_out, bag, log)
    _recover_bag(bag)
    record.save(os.path.join(bag_dir, spec.name + '.run.json'))
    return record


def _launch(cmd, master_uri, log, timeout, env=None, on_start=None):
    """roslaunch ``cmd`` on ``master_uri`` until it ends or ``timeout`` wall seconds, output
    appended to ``log``; (timed out, exit code, wall seconds).

    :raises RunInterrupted: stop_all stopped it meanwhile"""
    timed_out = False
    t0 = time.monotonic()
    with open(log, 'a') as out:
        proc = subprocess.Popen(TAKING_SIGINT + list(cmd), stdout=out, stderr=subprocess.STDOUT,
                                env=dict(launch_env(master_uri), **(env or {})), stdin=subprocess.DEVNULL,
                                start_new_session=True)
        if on_start:
            on_start(proc)
        with _live_lock:
            _live.add(proc)
        try:
            proc.wait(timeout)
        except subprocess.TimeoutExpired:
            timed_out = True
            _stop(proc)
        except KeyboardInterrupt:  # the launch is in a session of its own: stop it too
            _stop(proc)
            raise
        else:
            _stop_leftovers(proc.pid)
        finally:
            with _live_lock:
                _live.discard(proc)
                interrupted = proc in _interrupted
                _interrupted.discard(proc)
    if interrupted:
        raise RunInterrupted('stopped after %.0f s' % (time.monotonic() - t0))
    return timed_out, proc.returncode, round(time.monotonic() - t0, 1)
