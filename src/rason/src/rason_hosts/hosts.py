"""Robots on hosts of their own: one Linux network namespace per host, all on one switch.

Hosts(['broker', 'r1', 'r2']) makes, for a short random run id RUN:
  - a namespace rason-RUN-switch holding a Linux bridge br0;
  - per host a namespace rason-RUN-NAME whose eth0 (198.18.0.x/24) is a veth to a port of br0;
nothing is created in the root namespace, so parallel runs never clash. Links are shaped at
run time (loss, rate, cut) and every process, namespace and rule is removed on close, on
interpreter exit, or by cleanup() after a crashed run. No rospy here.
"""
import atexit
import collections
import os
import re
import secrets
import select
import shutil
import signal
import subprocess
import sys
import tempfile
import threading
import time
import weakref

from . import rules
from .addresses import host_address, HOST_SUBNET
from .owners import owner_alive, owner_file, record_owner

NETNS_DIR = '/var/run/netns'
OWNERS_DIR = '/run/rason-hosts'   # one file per live run: the owning process (pid, start time)
DEFAULT_PREFIX = 'rason'
SWITCH = 'switch'
HOST_NAME = re.compile(r'^[a-z0-9][a-z0-9_]{0,23}$')
PACKAGE_PARENT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


class HostsError(RuntimeError):
    pass


def _ip(*argv, input=None, check=True):
    result = subprocess.run(list(argv), input=input, capture_output=True, text=True)
    if check and result.returncode != 0:
        raise HostsError('%s: %s' % (' '.join(argv), result.stderr.strip()))
    return result


def ensure_netns_dir():
    """`ip netns` keeps its namespaces as files here; some minimal systems lack the folder."""
    os.makedirs(NETNS_DIR, exist_ok=True)


def list_namespaces():
    ensure_netns_dir()
    return sorted(os.listdir(NETNS_DIR))


def namespace_pids(namespace):
    result = _ip('ip', 'netns', 'pids', namespace, check=False)
    return [int(pid) for pid in result.stdout.split()]


def _owner_file(prefix, run_id):
    return owner_file(OWNERS_DIR, prefix, run_id)


def _owner_alive(prefix, run_id):
    return owner_alive(OWNERS_DIR, prefix, run_id)


def _kill_namespace(namespace):
    for pid in namespace_pids(namespace):
        try:
            os.kill(pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
    _ip('ip', 'netns', 'del', namespace, check=False)


def cleanup(prefix=DEFAULT_PREFIX, all_runs=False):
    """Remove the namespaces (and so their veths, bridge, nft tables, qdiscs) of dead runs.

    A run is dead when the process that made it is gone. all_runs=True also removes live runs.
    Returns the names of the namespaces removed.
    """
    pattern = re.compile(r'^%s-([0-9a-f]{6})-' % re.escape(prefix))
    removed = []
    for namespace in list_namespaces():
        match = pattern.match(namespace)
        if not match or (not all_runs and _owner_alive(prefix, match.group(1))):
            continue
        _kill_namespace(namespace)
        removed.append(namespace)
    if os.path.isdir(OWNERS_DIR):
        for name in os.listdir(OWNERS_DIR):
            run_id = name[len(prefix) + 1:]
            if name.startswith(prefix + '-') and (all_runs or not _owner_alive(prefix, run_id)):
                os.unlink(os.path.join(OWNERS_DIR, name))
    return removed


#: Every host as the multi-robot guide asks a fleet's computer to be on a lossy link: a few
#: small messages in flight (a pose, an agent's message, a heartbeat) are retransmitted at a
#: steady timeout, not after an exponential backoff. That needs a loss-based congestion
#: control: a new namespace inherits this machine's, BBR, under which Linux never counts a
#: stream as thin. A Debian host has cubic, which a namespace cannot choose unless the machine
#: allows it; reno is the loss-based one it always can.
HOST_TCP_SETTINGS = ('net.ipv4.tcp_congestion_control=reno', 'net.ipv4.tcp_thin_linear_timeouts=1')

_pending = weakref.WeakKeyDictionary()   # proc -> bytes read from its stdout, not yet a line
SKIPPED_SHOWN = 8                        # lines a failed read_line quotes, to show what came instead


def read_line(proc, timeout, contains=''):
    """The next stdout line of proc that contains contains, waiting at most timeout s.

    Reads the pipe's file descriptor itself (a buffered readline after select could hide
    lines already read); use only read_line on that stdout.
    """
    deadline = time.monotonic() + timeout
    fd = proc.stdout.fileno()
    pending = _pending.get(proc, b'')
    skipped = collections.deque(maxlen=SKIPPED_SHOWN)
    try:
        while True:
            while b'\n' in pending:
                line, pending = pending.split(b'\n', 1)
                text = line.decode(errors='replace')
                if contains in text:
                    return text
                skipped.append(text)
            left = deadline - time.monotonic()
            if left <= 0 or not select.select([fd], [], [], left)[0]:
                raise HostsError('no line with %r from %r within %g s; the last lines before it:\n%s'
                                 % (contains, proc.args, timeout, '\n'.join(skipped) or '(none)'))
            data = os.read(fd, 65536)
            if not data:
                raise HostsError('%r ended (exit %r) before printing %r'
                                 % (proc.args, proc.wait(), contains))
            pending += data
    finally:
        _pending[proc] = pending


def stop_process(proc, timeout=5.0):
    """SIGTERM to the process group, then SIGKILL after timeout s."""
    if proc.poll() is None:
        for signum, wait in ((signal.SIGTERM, timeout), (signal.SIGKILL, timeout)):
            try:
                os.killpg(proc.pid, signum)
            except ProcessLookupError:
                break
            try:
                proc.wait(wait)
                break
            except subprocess.TimeoutExpired:
                continue
    for stream in (proc.stdin, proc.stdout, proc.stderr):
        if stream:
            stream.close()
    return proc.poll()


class Relay:
    """A delaying TCP relay (rason_hosts.relay) running inside a host's namespace."""

    def __init__(self, proc, address, port, control_path):
        self.proc = proc
        self.address = address
        self.port = port
        self.control_path = control_path

    def set_delay(self, delay_ms):
        from .relay import set_relay_delay
        return set_relay_delay(self.control_path, delay_ms)


class Hosts:
    """N named hosts on one switch. Use as a context manager; see the module docstring."""

    def __init__(self, names, run_id=None, prefix=DEFAULT_PREFIX, clean_leftovers=True):
        """names: the hosts, numbered 198.18.0.1, .2, ... in this order. run_id: six hex digits
        (default random). clean_leftovers: on start, remove what crashed runs left (never a
        live run's namespaces)."""
        names = list(names)
        for name in names:
            if not HOST_NAME.match(name) or name == SWITCH:
                raise ValueError('host name %r: lower-case letters, digits, _ (not %r)'
                                 % (name, SWITCH))
        if len(set(names)) != len(names):
            raise ValueError('host names must differ: %r' % names)
        self.names = names
        self.prefix = prefix
        self.run_id = run_id or secrets.token_hex(3)
        if not re.match(r'^[0-9a-f]{6}$', self.run_id):
            raise ValueError('run_id must be six hex digits, not %r' % self.run_id)
        self.clean_leftovers = clean_leftovers
        self._ports = {name: 'p%d' % i for i, name in enumerate(names)}
        self._addresses = {name: host_address(i) for i, name in enumerate(names)}
        self._links = {name: {'loss': 0, 'cut': False, 'rate': None} for name in names}
        self._procs = []
        self._timers = []
        self._made = []
        self._lock = threading.RLock()
        self._tmp = None
        self._closed = False

    # names and addresses
    def namespace(self, name):
        if name != SWITCH and name not in self._addresses:
            raise KeyError('no host %r (hosts: %s)' % (name, ', '.join(self.names)))
        return '%s-%s-%s' % (self.prefix, self.run_id, name)

    def address(self, name):
        return self._addresses[name]

    @property
    def subnet(self):
        return str(HOST_SUBNET)

    @property
    def namespaces(self):
        return [self.namespace(SWITCH)] + [self.namespace(n) for n in self.names]

    # life cycle
    def __enter__(self):
        self.start()
        return self

    def __exit__(self, *exc):
        self.close()
        return False

    def start(self):
        if os.geteuid() != 0:
            raise HostsError('network namespaces need root')
        ensure_netns_dir()
        if self.clean_leftovers:
            cleanup(self.prefix)
        record_owner(OWNERS_DIR, self.prefix, self.run_id)
        atexit.register(self.close)
        self._tmp = tempfile.mkdtemp(prefix='rason-hosts-%s-' % self.run_id)
        try:
            self._make()
        except BaseException:
            self.close()
            raise
        return self

    def _add_namespace(self, namespace):
        _ip('ip', 'netns', 'add', namespace)
        self._made.append(namespace)
        _ip('ip', '-n', namespace, 'link', 'set', 'lo', 'up')

    def _make(self):
        switch = self.namespace(SWITCH)
        self._add_namespace(switch)
        _ip('ip', '-n', switch, 'link', 'add', 'br0', 'type', 'bridge')
        _ip('ip', '-n', switch, 'link', 'set', 'br0', 'up')
        prefix_len = HOST_SUBNET.prefixlen
        for name in self.names:
            namespace, port = self.namespace(name), self._ports[name]
            self._add_namespace(namespace)
            _ip('ip', 'link', 'add', 'eth0', 'netns', namespace, 'type', 'veth',
                'peer', 'name', port, 'netns', switch)
            _ip('ip', '-n', switch, 'link', 'set', port, 'master', 'br0')
            _ip('ip', '-n', switch, 'link', 'set', port, 'up')
            _ip('ip', '-n', namespace, 'addr', 'add',
                '%s/%d' % (self._addresses[name], prefix_len), 'dev', 'eth0')
            _ip('ip', '-n', namespace, 'link', 'set', 'eth0', 'up')
            _ip('ip', 'netns', 'exec', namespace, 'sysctl', '-qw', *HOST_TCP_SETTINGS)

    def close(self):
        """Stop every process started here, then delete every namespace. Idempotent."""
        with self._lock:
            if self._closed:
                return
            self._closed = True
        for timer in self._timers:
            timer.cancel()
        for proc in self._procs:
            if proc.poll() is None:
                try:
                    os.killpg(proc.pid, signal.SIGTERM)
                except ProcessLookupError:
                    pass
        for proc in self._procs:
            stop_process(proc, timeout=3.0)
        for namespace in reversed(self._made):
            _kill_namespace(namespace)   # also whatever a process left running inside
        try:
            os.unlink(_owner_file(self.prefix, self.run_id))
        except OSError:
            pass
        if self._tmp:
            shutil.rmtree(self._tmp, ignore_errors=True)
        atexit.unregister(self.close)

    # processes
    def run(self, name, argv, env=None, **popen_kwargs):
        """Start argv inside host name's namespace, in a process group of its own.

        Returns the subprocess.Popen; popen_kwargs go to Popen (stdout=subprocess.PIPE, ...).
        The process is stopped (group SIGTERM, then SIGKILL) when the hosts close.
        """
        if self._closed:
            raise HostsError('hosts are closed')
        argv = ['ip', 'netns', 'exec', self.namespace(name)] + [str(a) for a in argv]
        proc = subprocess.Popen(argv, env=env, start_new_session=True, **popen_kwargs)
        self._procs.append(proc)
        return proc

    def call(self, name, argv, timeout=30.0, env=None, input=None, text=True):
        """Run argv in host name to completion, input on its stdin; returns CompletedProcess
        (text output, or bytes when text is false)."""
        argv = ['ip', 'netns', 'exec', self.namespace(name)] + [str(a) for a in argv]
        return subprocess.run(argv, env=env, input=input, capture_output=True, text=text, timeout=timeout)

    def stop(self, proc, timeout=5.0):
        return stop_process(proc, timeout)

    def python_env(self, env=None):
        """env (default os.environ) with this package importable, for python3 -m rason_hosts.*"""
        env = dict(os.environ if env is None else env)
        env['PYTHONPATH'] = os.pathsep.join(p for p in (PACKAGE_PARENT, env.get('PYTHONPATH'))
                                            if p)
        return env

    @staticmethod
    def ros_env(env=None, master_port=11311):
        """env (default os.environ) for a ROS process whose master is on its host's loopback.

        Each host has a loopback of its own, so every robot can run its master on the same
        port without clashing, and nothing of a robot's ROS graph is reachable from another.
        """
        env = dict(os.environ if env is None else env)
        env.update(ROS_MASTER_URI='http://127.0.0.1:%d' % master_port, ROS_IP='127.0.0.1')
        env.pop('ROS_HOSTNAME', None)
        return env

    def run_python(self, name, module, args, **popen_kwargs):
        """Start python3 -m module args in host name (stdout piped, text)."""
        popen_kwargs.setdefault('stdout', subprocess.PIPE)
        popen_kwargs.setdefault('text', True)
        return self.run(name, [sys.executable, '-m', module] + list(args),
                        env=self.python_env(popen_kwargs.pop('env', None)), **popen_kwargs)

    # links
    def shape(self, name, loss=None, rate=None):
        """Change host name's link, both directions, at run time.

        loss: percent (0..100) of IP frames dropped in each direction independently.
        rate: '1mbit', '500kbit', ... limits each direction (tbf); 0 or '' removes the limit.
        Arguments left None keep their current value.
        """
        with self._lock:
            link = self._links[name]
            if loss is not None:
                link['loss'] = loss
            if rate is not None:
                link['rate'] = rate or None
                self._apply_rate(name)
            self._apply_rules(name)

    def cut(self, name):
        """Drop every frame to and from host name until heal(name)."""
        with self._lock:
            self._links[name]['cut'] = True
            self._apply_rules(name)

    def heal(self, name):
        with self._lock:
            self._links[name]['cut'] = False
            self._apply_rules(name)

    def partition(self, name, seconds):
        """cut(name) now and heal(name) after seconds (in a timer thread); returns the timer."""
        self.cut(name)
        timer = threading.Timer(seconds, self._heal_unless_closed, (name,))
        timer.daemon = True
        self._timers.append(timer)
        timer.start()
        return timer

    def _heal_unless_closed(self, name):
        with self._lock:
            if not self._closed:
                self.heal(name)

    def link(self, name):
        """The current shaping of host name's link: {'loss': %, 'cut': bool, 'rate': str|None}."""
        return dict(self._links[name])

    def _apply_rules(self, name):
        link = self._links[name]
        script = rules.link_ruleset(name, self._ports[name], link['loss'], link['cut'])
        _ip('ip', 'netns', 'exec', self.namespace(SWITCH), 'nft', '-f', '-', input=script)

    def _apply_rate(self, name):
        rate = self._links[name]['rate']
        # The host's eth0 carries its egress; the switch port carries its ingress.
        for namespace, device in ((self.namespace(name), 'eth0'),
                                  (self.namespace(SWITCH), self._ports[name])):
            if rate:
                _ip('tc', '-n', namespace, *rules.tbf_args(device, rate))
            else:
                _ip('tc', '-n', namespace, *rules.tbf_delete_args(device), check=False)

    def relay(self, host, target, delay_ms, port=0, timeout=10.0):
        """A TCP relay in host, on host's address and port (0: any free), to target (addr, port).

        Every chunk is delayed delay_ms in each direction (a round trip gains 2*delay_ms);
        clients that connect to (relay.address, relay.port) see the delay. relay.set_delay(ms)
        changes it at run time.
        """
        control = os.path.join(self._tmp, 'relay-%d.sock' % len(self._procs))
        proc = self.run_python(host, 'rason_hosts.relay', [
            '--listen', '%s:%d' % (self.address(host), port),
            '--target', '%s:%d' % tuple(target), '--delay-ms', str(delay_ms),
            '--control', control])
        words = read_line(proc, timeout, 'listening ').split()
        return Relay(proc, words[1], int(words[2]), control)
