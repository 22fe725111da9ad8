"""One process's CPU time and memory from /proc, and a readable name for it."""
import os

CLOCK_TICKS = os.sysconf('SC_CLK_TCK')
PAGE_KB = os.sysconf('SC_PAGE_SIZE') // 1024
#: Programs that run a script: the name is the script's (or the ROS node's).
INTERPRETERS = ('python', 'python3', 'java', 'bash', 'sh')


def parse_stat(text):
    """(ppid, CPU seconds user + system, start time in ticks after boot) of a
    /proc/PID/stat line; the command name may hold spaces and brackets."""
    fields = text.rsplit(')', 1)[1].split()
    # fields[0] is field 3 (state): ppid is field 4, utime 14, stime 15, starttime 22
    return int(fields[1]), (int(fields[11]) + int(fields[12])) / float(CLOCK_TICKS), int(fields[19])


def parse_status_kb(text, key):
    """A ``Key:   123 kB`` value of /proc/PID/status, in kB (None if absent: a kernel thread)."""
    for line in text.splitlines():
        if line.startswith(key + ':'):
            return int(line.split()[1])
    return None


def name_from_cmdline(argv):
    """The node name (``__name:=``) if it is a ROS node, else the program or, for an
    interpreter, its script: ``rosmaster``, ``roslaunch``, ``rason_mas``..."""
    for arg in argv:
        if arg.startswith('__name:='):
            return arg.split(':=', 1)[1]
    words = [a for a in argv if a]
    program = ''
    while words and (os.path.basename(words[0]).rstrip('0123456789.') in INTERPRETERS or words[0].startswith('-')):
        if words[0] in ('-c', '-m'):  # python3 -c CODE: the interpreter's name; -m MODULE: the module's
            return words[1] if words[0] == '-m' and len(words) > 1 else program
        program = program or os.path.basename(words[0])
        words = words[1:]
    return os.path.basename(words[0]) if words else program


class ProcSample(object):
    """One look at a process: ``cpu_s`` so far, ``rss_kb`` now, ``hwm_kb`` its peak RSS."""
    __slots__ = ('pid', 'ppid', 'name', 'cpu_s', 'start_ticks', 'rss_kb', 'hwm_kb')

    def __init__(self, pid, ppid, name, cpu_s, start_ticks, rss_kb, hwm_kb):
        self.pid, self.ppid, self.name, self.cpu_s = pid, ppid, name, cpu_s
        self.start_ticks, self.rss_kb, self.hwm_kb = start_ticks, rss_kb, hwm_kb


def sample(pid, proc='/proc'):
    """A :class:`ProcSample` of ``pid``, or None if it has ended."""
    base = os.path.join(proc, str(pid))
    try:
        with open(os.path.join(base, 'stat')) as f:
            ppid, cpu_s, start = parse_stat(f.read())
        with open(os.path.join(base, 'status')) as f:
            status = f.read()
        with open(os.path.join(base, 'cmdline'), 'rb') as f:
            argv = [a.decode('utf-8', 'replace') for a in f.read().split(b'\0')]
    except (OSError, IndexError, ValueError):
        return None
    return ProcSample(pid, ppid, name_from_cmdline(argv), cpu_s, start,
                      parse_status_kb(status, 'VmRSS') or 0, parse_status_kb(status, 'VmHWM') or 0)


def uptime_ticks(proc='/proc'):
    """Now, in clock ticks after boot (what a process's start time is counted in)."""
    with open(os.path.join(proc, 'uptime')) as f:
        return float(f.read().split()[0]) * CLOCK_TICKS


def descendants(root_pid, proc='/proc'):
    """The PIDs of ``root_pid``'s process tree (itself included), from each process's ppid."""
    children = {}
    for entry in os.listdir(proc):
        if entry.isdigit():
            try:
                with open(os.path.join(proc, entry, 'stat')) as f:
                    ppid = parse_stat(f.read())[0]
            except (OSError, IndexError, ValueError):
                continue
            children.setdefault(ppid, []).append(int(entry))
    out, todo = [], [root_pid]
    while todo:
        pid = todo.pop()
        out.append(pid)
        todo.extend(children.get(pid, ()))
    return out
