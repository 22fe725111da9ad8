"""Running one campaign run: ``roslaunch rason faulty_helper.launch`` on a master of its
own, with a wall-clock timeout after which the whole launch is stopped."""
import json
import os
import signal
import socket
import subprocess
import time

from rason_campaign.plan import launch_arguments

LAUNCH = ('rason', 'faulty_helper.launch')


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
    """True when nothing listens on 127.0.0.1:port (a master left there would be reused
    by roslaunch, mixing two runs)."""
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as s:
        s.settimeout(0.5)
        return s.connect_ex(('127.0.0.1', port)) != 0


def pick_port(base, span=50):
    for port in range(base, base + span):
        if port_free(port):
            return port
    raise RuntimeError('no free port in %d..%d for a ROS master' % (base, base + span - 1))


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
    try:
        os.killpg(pgid, signal.SIGTERM)
    except ProcessLookupError:
        pass


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


def run(spec, bag_dir, timeout, base_port=11611):
    """Run ``spec`` to its end or ``timeout`` wall seconds; the bag and the launch's log go
    to ``bag_dir/<spec.name>.bag|.log``, the record to ``.run.json``.

    :rtype: RunRecord
    """
    bag_dir = os.path.abspath(bag_dir)  # roslaunch runs the recorder in ROS_HOME
    bag = os.path.join(bag_dir, spec.name + '.bag')
    log = os.path.join(bag_dir, spec.name + '.log')
    for stale in (bag, bag + '.active'):
        if os.path.exists(stale):
            os.remove(stale)
    port = pick_port(base_port)
    env = dict(os.environ, ROS_MASTER_URI='http://127.0.0.1:%d' % port)
    cmd = ['roslaunch', '-p', str(port)] + list(LAUNCH) + launch_arguments(spec, bag)
    t0 = time.monotonic()
    timed_out = False
    with open(log, 'w') as out:
        out.write(' '.join(cmd) + '\n')
        out.flush()
        proc = subprocess.Popen(cmd, stdout=out, stderr=subprocess.STDOUT, env=env,
                                stdin=subprocess.DEVNULL, start_new_session=True)
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
    record = RunRecord(None if timed_out else proc.returncode, round(time.monotonic() - t0, 1),
                       timed_out, bag, log)
    _recover_bag(bag)
    record.save(os.path.join(bag_dir, spec.name + '.run.json'))
    return record
