"""Starting and stopping the benchmark's own ROS master and nodes (subprocesses, stopped by
PID). The master is the campaign's :class:`rason_campaign.runner.PrivateMaster` (package
``rason``): one implementation of "a roscore of our own on a free port"."""
import os
import signal
import subprocess

from rason_campaign.runner import PrivateMaster


class Processes(object):
    """The subprocesses of one benchmark run, all talking to a master on its own port.

    :param log_dir: where each process's output goes (``<name>.log``)
    """

    def __init__(self, log_dir, port=None):
        os.makedirs(log_dir, exist_ok=True)
        self.log_dir = log_dir
        self.master = PrivateMaster(os.path.join(log_dir, 'roscore.log'), port)
        self.port = self.master.port
        self.master_uri = self.master.uri
        self.env = self.master.env(dict(os.environ, ROS_IP='127.0.0.1'))

    def start_master(self, timeout=20.0):
        self.master.start(timeout)

    def stop_master(self):
        self.master.stop()

    def start(self, name, argv):
        """Start argv with the run's environment, in a session of its own; output to
        ``<log_dir>/<name>.log``."""
        with open(os.path.join(self.log_dir, name + '.log'), 'ab') as out:
            return subprocess.Popen(argv, env=self.env, stdout=out, stderr=subprocess.STDOUT,
                                    stdin=subprocess.DEVNULL, start_new_session=True)

    def rosrun(self, name, package, executable, *args, **params):
        """``rosrun package executable args __name:=name _param:=value ...`` (rosrun execs: the PID is the node's)."""
        argv = ['rosrun', package, executable] + list(args) + ['__name:=' + name]
        argv += ['_%s:=%s' % (k, v) for k, v in sorted(params.items())]
        return self.start(name, argv)

    def roslaunch(self, name, package, launch_file, *args):
        """``roslaunch package launch_file arg:=value ...`` on the run's master; stop it with
        :meth:`stop` and ``signal.SIGINT`` (roslaunch then stops its nodes)."""
        return self.start(name, ['roslaunch', package, launch_file] + list(args))

    @staticmethod
    def stop(proc, sig=signal.SIGTERM, timeout=15.0):
        """Signal one process we started (by its PID) and wait; if it does not end, SIGKILL
        to its process group (the session it was started in: only what it started)."""
        if proc is None or proc.poll() is not None:
            return
        proc.send_signal(sig)
        try:
            proc.wait(timeout)
        except subprocess.TimeoutExpired:  # still alive, so the group is still ours
            os.killpg(proc.pid, signal.SIGKILL)
            proc.wait(5)
