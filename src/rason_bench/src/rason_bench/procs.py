"""Starting and stopping the benchmark's own ROS master and nodes (subprocesses, stopped by PID)."""
import os
import signal
import socket
import subprocess
import time


def free_port():
    """A TCP port nobody listens on right now."""
    with socket.socket() as s:
        s.bind(('127.0.0.1', 0))
        return s.getsockname()[1]


def master_is_up(uri, timeout=0.5):
    import xmlrpc.client
    try:
        proxy = xmlrpc.client.ServerProxy(uri)
        socket.setdefaulttimeout(timeout)
        try:
            return proxy.getPid('/rason_bench')[0] == 1
        finally:
            socket.setdefaulttimeout(None)
    except (OSError, xmlrpc.client.Error):
        return False


class Processes(object):
    """The subprocesses of one benchmark run, all talking to a master on its own port.

    :param log_dir: where each process's output goes (``<name>.log``)
    """

    def __init__(self, log_dir, port=None):
        self.port = port or free_port()
        self.master_uri = 'http://127.0.0.1:%d' % self.port
        self.log_dir = log_dir
        os.makedirs(log_dir, exist_ok=True)
        self.env = dict(os.environ, ROS_MASTER_URI=self.master_uri, ROS_IP='127.0.0.1')
        self._master = None

    def start_master(self, timeout=20.0):
        self._master = self.start('roscore', ['roscore', '-p', str(self.port)])
        deadline = time.monotonic() + timeout
        while not master_is_up(self.master_uri):
            if time.monotonic() > deadline or self._master.poll() is not None:
                raise RuntimeError('roscore on port %d did not start (see %s/roscore.log)'
                                   % (self.port, self.log_dir))
            time.sleep(0.1)

    def start(self, name, argv):
        """Start argv with the run's environment; output to ``<log_dir>/<name>.log``."""
        out = open(os.path.join(self.log_dir, name + '.log'), 'ab')
        try:
            return subprocess.Popen(argv, env=self.env, stdout=out, stderr=subprocess.STDOUT,
                                    start_new_session=True)
        finally:
            out.close()

    def rosrun(self, name, package, executable, *args, **params):
        """``rosrun package executable args __name:=name _param:=value ...`` (rosrun execs: the PID is the node's)."""
        argv = ['rosrun', package, executable] + list(args) + ['__name:=' + name]
        argv += ['_%s:=%s' % (k, v) for k, v in sorted(params.items())]
        return self.start(name, argv)

    @staticmethod
    def stop(proc, sig=signal.SIGTERM, timeout=15.0):
        """Signal one process we started (by its PID) and wait; SIGKILL if it does not end."""
        if proc is None or proc.poll() is not None:
            return
        proc.send_signal(sig)
        try:
            proc.wait(timeout)
        except subprocess.TimeoutExpired:
            proc.kill()
            proc.wait(5)

    def stop_master(self):
        self.stop(self._master, signal.SIGINT)
        self._master = None
