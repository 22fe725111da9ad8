"""``rosrun rason run_launch PACKAGE FILE.launch [ARG:=VALUE ...]``: a launch file run as
roslaunch runs it, except for how it ends. roslaunch ends a launch when a ``required`` node
exits, but always with a red "REQUIRED process has died!" banner and with exit status 0,
even when the run failed, and runs on when another node fails. Here a required node that
exits, or any node that exits with a non-zero status while the launch runs (e.g. agents that
cannot start on a robot whose ``.stopMAS`` would not end the launch), ends the launch quietly,
and the exit status is that node's: 0 when it finished cleanly (an agent's ``.stopMAS``), its own
non-zero status (or 128 + the signal that killed it) when it failed, and then the node's last
fatal line (from its log file) is repeated last on screen. A launch that ends otherwise (Ctrl-C,
every node gone) exits with status 1.

Mistakes roslaunch lets through are refused or shown before any node starts: an ``ARG:=VALUE``
the file does not declare (roslaunch ignores it) stops with status 2 and the file's arguments;
the first lines show the effective configuration: each namespace (robot) with its nodes, the
program each ``rason_mas`` runs, the entries each wiring node (``generic_synthesizer``,
``generic_decomposer``) was given, and the lines of the file's ``launch_config`` nodes (which
plain roslaunch prints as they start; here they are printed, not started).

Everything else is roslaunch's: the summary, a master started when none is running, the
nodes' output, SIGINT and SIGTERM."""
import difflib
import os
import re
import sys
import threading

import rosgraph.names
import roslaunch
import roslaunch.parent
import roslaunch.pmon
import roslaunch.rlutil
import rospkg

from rason_tools.launch_args import launch_args
from rason_tools.launch_config import node_line

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


def undeclared_args(given, declared):
    """Why each ``NAME:=VALUE`` of ``given`` whose NAME is not in ``declared`` is refused (a line
    each, naming close matches or, without any, every declared argument)."""
    lines = []
    for arg in given:
        name = arg.split(':=', 1)[0]
        if name in declared or name.startswith('_'):
            continue
        close = difflib.get_close_matches(name, declared, n=3, cutoff=0.6)
        hint = ('did you mean %s?' % ' or '.join(close)) if close else 'its arguments: %s' % ', '.join(declared)
        lines.append('%s: the launch file has no argument %r (roslaunch would ignore it): %s' % (arg, name, hint))
    return lines


WIRING = ('perceptions', 'actions')


def configuration(nodes, params):
    """The effective configuration, a line a namespace: its nodes, the program of each
    ``rason_mas`` and the wiring entries of each node given ``~perceptions`` or ``~actions``.

    :param nodes: ``[(namespace, name, type, args)]`` as roslaunch resolved them
    :param params: the launch's parameter names
    """
    by_ns = {}
    for namespace, name, node_type, args in nodes:
        shown = name
        if node_type == 'rason_mas' and args:
            shown += ' (program %s)' % args.split()[0]
        prefix = rosgraph.names.ns_join(namespace or '/', name) + '/'
        for kind in WIRING:
            entries = sorted({p[len(prefix + kind) + 1:].split('/')[0] for p in params
                              if p.startswith(prefix + kind + '/')})
            if entries:
                shown += ' (%s: %s)' % (kind, ', '.join(entries))
        by_ns.setdefault(namespace or '/', []).append(shown)
    return ['  %s: %s' % (ns, '; '.join(shown)) for ns, shown in sorted(by_ns.items())]


FATAL_LINE = re.compile(r'^\[[^\]]*\]\[(?:FATAL|CRITICAL)\] \d{4}-\d\d-\d\d [\d:,]+: (.*)$')


def last_fatal_line(log_text):
    """The last fatal line a rospy node wrote to its log file (``__log:=``), or None."""
    found = None
    for line in log_text.splitlines():
        match = FATAL_LINE.match(line)
        if match:
            found = match.group(1)
    return found


def node_log_file(run_id, process_name):
    """The log file roslaunch gives a node (its ``__log:=``)."""
    return os.path.join(rospkg.get_log_dir(), run_id, '%s.log' % process_name.replace('/', '-'))


class RunEnd(roslaunch.pmon.ProcessListener):
    """Waits for the first of the ending nodes to exit, or any node to fail, and keeps its exit
    code. A node killed by a signal has not failed: roslaunch's own shutdown (Ctrl-C) kills."""

    def __init__(self):
        self.nodes = set()
        self.stopping = lambda: False
        self.ended_by = None
        self.process = None
        self.exit_code = None
        self.done = threading.Event()

    def process_died(self, process_name, exit_code):
        node = process_base_name(process_name)
        failed = exit_code is not None and exit_code > 0 and not self.stopping()
        if (node in self.nodes or failed) and not self.done.is_set():
            self.ended_by, self.process, self.exit_code = node, process_name, exit_code
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
        # the launch files' own configuration lines, printed here before any node starts
        shown = [n for n in self.config.nodes if (n.package, n.type) == ('rason', 'launch_config')]
        self.config.nodes = [n for n in self.config.nodes if (n.package, n.type) != ('rason', 'launch_config')]
        launch_file = os.path.basename(self.roslaunch_files[0][0])
        print('run_launch: %s, effective configuration (namespace: nodes):' % launch_file)
        print('\n'.join(configuration([(n.namespace, n.name, n.type, n.args) for n in self.config.nodes],
                                       list(self.config.params))
                         + [node_line(n.args) for n in shown]))
        sys.stdout.flush()

    def _start_pm(self):
        super(QuietEndParent, self)._start_pm()
        # before any node starts, so a node that dies at once is heard too
        self.pm.add_process_listener(self.run_end)
        self.run_end.stopping = lambda: self.pm.is_shutdown


def launch_args_of(launch_file):
    try:
        return launch_args(launch_file)[1]
    except Exception:       # roslaunch's own parse says what is wrong with the file
        return None


def _fatal_line_of(run_id, process_name):
    try:
        with open(node_log_file(run_id, process_name), errors='replace') as f:
            return last_fatal_line(f.read())
    except OSError:
        return None


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
    declared = launch_args_of(launch_file)
    refused = undeclared_args(launch_args, [name for name, _, _ in declared]) if declared is not None else []
    if refused:
        print('\n'.join('run_launch: %s' % line for line in refused), file=sys.stderr)
        return 2
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
        fatal = _fatal_line_of(run_id, run_end.process)
        if fatal:
            print('run_launch: %s: %s' % (run_end.ended_by, fatal), file=sys.stderr)
    else:
        print('run_launch: %s finished: the launch is shut down' % run_end.ended_by)
    return status
