"""Running a Jason project to its end under Jason's own runner or under rason_mas, and reading
what its agents printed, so that the rostests can compare the two.

Jason's runner (``jason.infra.local.RunLocalMAS``, headless, its console log) resolves a
project's relative paths from the working directory: it runs in the project's folder, as
Jason users run it. rason_mas resolves them from the .mas2j's folder: it runs from ``/``.
"""
import os
import re
import signal
import subprocess

from rason_bridge.jvm import jason_lib_classpath
from rason_testing import node_command

#: Jason's own console logging configuration, inside its jar.
JASON_LOG_CONF = '$jasonJar/templates/console-info-logging.properties'

_ROSOUT_PREFIX = re.compile(r'^\[(?:DEBUG|INFO|WARN|ERROR|FATAL)\] \[[0-9.]+\]: ')
_AGENT_LINE = re.compile(r'^\[\w+\] ')


class Finished(object):
    """A run that ended: its exit status (None if it had to be killed) and its output lines."""

    def __init__(self, returncode, output):
        self.returncode = returncode
        self.output = output

    def text(self):
        return '\n'.join(self.output)


def jason_command(mas2j, classpath=()):
    """The command that runs ``mas2j`` under Jason's runner, and the folder to run it in (the project's);
    ``classpath``: the project's own classes and jars, after Jason's (as its Gradle build puts them)."""
    cmd = ['java', '-Djava.awt.headless=true', '-cp', os.pathsep.join(jason_lib_classpath() + list(classpath)),
           'jason.infra.local.RunLocalMAS', os.path.basename(mas2j), '--no-net', '--log-conf', JASON_LOG_CONF]
    return cmd, os.path.dirname(os.path.abspath(mas2j))


def run_jason(mas2j, timeout, classpath=()):
    """Run ``mas2j`` under Jason's runner in the project's folder until it stops (.stopMAS)."""
    cmd, cwd = jason_command(mas2j, classpath)
    return _run(cmd, cwd, timeout)


def run_rason_mas(mas2j, name, timeout, **params):
    """Run ``mas2j`` in a rason_mas named ``name`` (from ``/``) until it stops; ``params`` are its ~params."""
    cmd = node_command('rason_bridge', 'rason_mas') + [os.path.abspath(mas2j), '__name:=' + name]
    cmd += ['_%s:=%s' % item for item in sorted(params.items())]
    return _run(cmd, '/', timeout)


def _run(cmd, cwd, timeout):
    proc = subprocess.Popen(cmd, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            universal_newlines=True, start_new_session=True)
    try:
        out, _ = proc.communicate(timeout=timeout)
        return Finished(proc.returncode, out.splitlines())
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGKILL)
        out, _ = proc.communicate()
        return Finished(None, out.splitlines())


def agent_lines(output, agent=None):
    """The lines agents printed or logged, ``[agent] text``, in order, whichever runner showed them
    (rason_mas puts rosout's level and time first); only ``agent``'s if given."""
    lines = []
    for line in output:
        line = _ROSOUT_PREFIX.sub('', line).rstrip()
        if _AGENT_LINE.match(line) and (agent is None or line.startswith('[%s] ' % agent)):
            lines.append(line)
    return lines
