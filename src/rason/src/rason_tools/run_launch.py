"""``rosrun rason run_launch PACKAGE FILE.launch [ARG:=VALUE ...]``: a launch file run as
roslaunch runs it, except for how it ends. roslaunch ends a launch when a ``required`` node
exits, but always with a red "REQUIRED process has died!" banner and with exit status 0,
even when the run failed. Here a required node that exits ends the launch quietly, and the
exit status is that node's: 0 when it finished cleanly (an agent's ``.stopMAS``), its own
non-zero status (or 128 + the signal that killed it) when it failed. A launch that ends
otherwise (Ctrl-C, every node gone) exits with status 1.

Everything else is roslaunch's: the summary, a master started when none is running, the
nodes' output, SIGINT and SIGTERM."""
import sys
import threading

import rosgraph.names
import roslaunch
import roslaunch.parent
import roslaunch.pmon
import roslaunch.rlutil

USAGE = 'usage: rosrun rason run_launch PACKAGE FILE.launch [ARG:=VALUE ...]  (or FILE.launch [ARG:=VALUE ...])'


def process_base_name(process_name):
    """The node's name of a roslaunch process name: ``faulty/rason_mas-7`` -> ``faulty/rason_mas``."""
    return process_name.rsplit('-', 1)[0]


def node_key(namespace, name):
    """The name roslaunch gives a node's process, without its counter."""
    return rosgraph.names.ns_join(namespace or '/', name).lstrip('/')


def exit_status(exit_code):
    """The shell's status for a process's exit code (subprocess: -N when killed by signal N)."""
    if exit_code is None:
        return 1
    return 128 - exit_code if exit_code < 0 else exit_code


class RunEnd(roslaunch.pmon.ProcessListener):
    """Waits for the first of the ending nodes to exit and keeps its exit code."""

    def __init__(self):
        self.nodes = set()
        self.ended_by = None
        self.exit_code = None
        self.done = threading.Event()

    def process_died(self, process_name, exit_code):
        node = process_base_name(process_name)
        if node in self.nodes and not self.done.is_set():
            self.ended_by, self.exit_code = node, exit_code
            self.done.set()


class QuietEndParent(roslaunch.parent.ROSLaunchParent):
    """roslaunch's parent with its required nodes handed to a :class:`RunEnd` instead."""

    def __init__(self, run_id, files, run_end):
        self.run_end = run_end
        super(QuietEndParent, self).__init__(run_id, files)

    def _load_config(self):
        super(QuietEndParent, self)._load_config()
        for node in self.config.nodes:
            if node.required:
                node.required = False    # no banner: run_end ends the launch instead
                self.run_end.nodes.add(node_key(node.namespace, node.name))

    def _start_pm(self):
        super(QuietEndParent, self)._start_pm()
        # before any node starts, so a node that dies at once is heard too
        self.pm.add_process_listener(self.run_end)


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    if not argv or argv[0] in ('-h', '--help'):
        print(USAGE)
        return 0 if argv else 2
    try:
        resolved = roslaunch.rlutil.resolve_launch_arguments(argv)
    except roslaunch.RLException as e:
        print('run_launch: %s\n%s' % (e, USAGE), file=sys.stderr)
        return 2
    # resolve_launch_arguments leaves out the NAME:=VALUE arguments (rosgraph.myargv)
    launch_file = resolved[0]
    launch_args = [a for a in argv if ':=' in a]
    run_id = roslaunch.rlutil.get_or_generate_uuid(None, False)
    roslaunch.configure_logging(run_id)
    run_end = RunEnd()
    parent = QuietEndParent(run_id, [(launch_file, launch_args)], run_end)
    try:
        parent.start()
        while not run_end.done.wait(0.1) and not parent.pm.is_shutdown:
            parent.spin_once()
    except roslaunch.RLException as e:
        print('run_launch: %s' % e, file=sys.stderr)
        return 1
    finally:
        parent.shutdown()
    if not run_end.done.is_set():
        print('run_launch: the launch ended before any of its required nodes (%s) did'
              % ', '.join(sorted(run_end.nodes)), file=sys.stderr)
        return 1
    status = exit_status(run_end.exit_code)
    if status:
        print('run_launch: %s failed (exit status %d): the launch is shut down' % (run_end.ended_by, status),
              file=sys.stderr)
    else:
        print('run_launch: %s finished: the launch is shut down' % run_end.ended_by)
    return status
