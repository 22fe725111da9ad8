"""Who owns a run (of the hosts harness, of the robot budget): one file per live run in a folder
under /run, holding the owning process's pid and start time, so that a crashed run's leftovers
are told from a live run's even when the pid has been reused. No rospy."""
import os


def start_time(pid):
    """The start time of process pid (clock ticks since boot, as text), or None if it is gone."""
    try:
        with open('/proc/%d/stat' % pid) as f:
            return f.read().rsplit(')', 1)[1].split()[19]
    except (OSError, IndexError):
        return None


def owner_file(folder, prefix, run_id):
    return os.path.join(folder, '%s-%s' % (prefix, run_id))


def record_owner(folder, prefix, run_id):
    """Records this process as the owner of run run_id."""
    os.makedirs(folder, exist_ok=True)
    with open(owner_file(folder, prefix, run_id), 'w') as f:
        f.write('%d %s\n' % (os.getpid(), start_time(os.getpid())))


def owner_alive(folder, prefix, run_id):
    """Whether the process that recorded itself as run run_id's owner still runs."""
    try:
        with open(owner_file(folder, prefix, run_id)) as f:
            pid, started = f.read().split()
    except (OSError, ValueError):
        return False
    return start_time(int(pid)) == started
