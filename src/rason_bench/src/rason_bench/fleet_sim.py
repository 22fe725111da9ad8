"""The simulated world with a fleet (issue 34): ``roslaunch rason fleet.launch`` with N = 2,
4, 6, 8 robots of ``rason_sim/config/fleet.yaml`` (r1, r2, r3 with the camera), each with
its execution layer (decomposer, fault injector, diagnosis reporter; vision_synth on the
cameras), at rate 0 with lockstep, every robot turning in place (``turn`` on its
decomposer, so the controller lockstep is in play too): the real-time factor the machine
sustains, the simulator's CPU and the whole launch's. ``--only fleet_sim``."""
import os
import signal
import threading
import time

import rosgraph
import rospy

from rason_bench import stats

SIZES = (2, 4, 6, 8)
CAMERAS = ('r1', 'r2', 'r3')
#: one long turn per robot: it lasts the whole measured window (0.5 rad/s: 126 s of sim time)
TURN_DEGREES = 3600
SIM_NODE = 'rason_sim_node'


def robots_of(n):
    return ['r%d' % k for k in range(1, n + 1)]


def _ticks_by_pid(root):
    """{pid: (command name, utime + stime in clock ticks)} of root and every process under it
    (roslaunch puts each node in a session of its own, so it is the parent links that count)."""
    stats = {}
    for entry in os.listdir('/proc'):
        if not entry.isdigit():
            continue
        try:
            with open('/proc/%s/stat' % entry) as f:
                text = f.read()
        except OSError:
            continue
        rest = text[text.rindex(')') + 2:].split()
        stats[int(entry)] = (text[text.index('(') + 1:text.rindex(')')], int(rest[1]),
                             int(rest[11]) + int(rest[12]))
    out = {}
    for pid, (name, _, ticks) in stats.items():
        ancestor = pid
        while ancestor > 1 and ancestor != root:
            ancestor = stats[ancestor][1] if ancestor in stats else 0
        if ancestor == root:
            out[pid] = (name, ticks)
    return out


def _machine_busy():
    """(busy, all) jiffies of every CPU together, from /proc/stat."""
    with open('/proc/stat') as f:
        values = [int(v) for v in f.readline().split()[1:]]
    idle = values[3] + values[4]
    return sum(values) - idle, sum(values)


def cpu_percent(before, after, wall_s):
    """% of one core used between two _ticks_by_pid samples, by command name (/proc's, cut at
    15 characters: rason_sim_node, motion_decomp_n, vision_synth_no ...)."""
    hz = os.sysconf('SC_CLK_TCK')
    by_name = {}
    for pid, (name, ticks) in after.items():
        used = ticks - before.get(pid, (name, 0))[1]
        by_name[name] = by_name.get(name, 0.0) + 100.0 * used / hz / wall_s
    return by_name


class _Watch(object):
    """/clock pairs, each camera robot's robots_seen arrivals, the turns' results."""

    def __init__(self, robots):
        from rason_msgs.msg import Event, RobotSightings
        from rosgraph_msgs.msg import Clock
        self.lock = threading.Lock()
        self.clock = []
        self.seen = {r: [] for r in robots if r in CAMERAS}
        self.results = {}
        self.subs = [rospy.Subscriber('/clock', Clock, self._on_clock, queue_size=10)]
        for r in self.seen:
            self.subs.append(rospy.Subscriber('/%s/robots_seen' % r, RobotSightings,
                                              lambda msg, r=r: self._on_seen(r, msg), queue_size=10))
        for r in robots:
            self.subs.append(rospy.Subscriber('/%s/jason/event' % r, Event,
                                              lambda msg, r=r: self._on_event(r, msg), queue_size=10))
        self.event_kind = Event.ACTION_FEEDBACK

    def _on_clock(self, msg):
        with self.lock:
            self.clock.append((time.monotonic(), msg.clock.to_sec()))

    def _on_seen(self, robot, msg):
        with self.lock:
            self.seen[robot].append((time.monotonic(), msg.header.stamp.to_sec()))

    def _on_event(self, robot, msg):
        if msg.event_type == self.event_kind and msg.parameters:
            with self.lock:
                self.results[robot] = msg.parameters[0]

    def every_camera_seen(self):
        with self.lock:
            return all(self.seen.values())

    def close(self):
        for s in self.subs:
            s.unregister()


def _decomposers_listening(robots):
    """True when every robot's motion_decomp subscribes to its jason/action."""
    _, subscribers, _ = rosgraph.Master(rospy.get_name()).getSystemState()
    listening = {t: set(n) for t, n in subscribers}
    return all('/%s/motion_decomp' % r in listening.get('/%s/jason/action' % r, ()) for r in robots)


def _wait(condition, timeout, proc, what, log_dir):
    deadline = time.monotonic() + timeout
    while not condition():
        if time.monotonic() > deadline or proc.poll() is not None:
            raise RuntimeError('%s (see %s/fleet_sim.log)' % (what, log_dir))
        time.sleep(0.2)


def measure_one(procs, n, window, log, settle=3.0, start_timeout=120.0, turning=True):
    """One fleet of n robots: started, every camera's frames processed and every robot
    turning (unless not ``turning``), ``settle`` s more, then ``window`` wall s measured."""
    from rason_msgs.msg import Action
    robots = robots_of(n)
    watch = _Watch(robots)
    proc = procs.roslaunch('fleet_sim', 'rason', 'fleet.launch', 'robots:=%s' % ' '.join(robots), 'rate:=0')
    try:
        _wait(watch.every_camera_seen, start_timeout, proc, 'a camera robot\'s vision_synth never reported a frame',
              procs.log_dir)
        _wait(lambda: _decomposers_listening(robots), start_timeout, proc, 'a decomposer never listened',
              procs.log_dir)
        actions = {r: rospy.Publisher('/%s/jason/action' % r, Action, queue_size=1) for r in robots}
        _wait(lambda: all(p.get_num_connections() >= 1 for p in actions.values()), 30.0, proc,
              'the decomposers did not connect', procs.log_dir)
        for k, (r, pub) in enumerate(sorted(actions.items()) if turning else ()):
            pub.publish(Action(agent=r, action_id=k + 1, action='turn', parameters=[str(TURN_DEGREES)]))
        time.sleep(settle)
        machine0, ticks0, start = _machine_busy(), _ticks_by_pid(proc.pid), time.monotonic()
        time.sleep(window)
        machine1, ticks1, end = _machine_busy(), _ticks_by_pid(proc.pid), time.monotonic()
        with watch.lock:
            pairs = [p for p in watch.clock if start <= p[0] < end]
            frames = {r: len([s for w, s in seen if start <= w < end]) for r, seen in watch.seen.items()}
            ended = dict(watch.results)
        for pub in actions.values():
            pub.unregister()
    finally:
        watch.close()
        procs.stop(proc, sig=signal.SIGINT, timeout=30.0)
        # the launch set /use_sim_time: nodes started after it must not wait for a /clock
        if rospy.has_param('/use_sim_time'):
            rospy.delete_param('/use_sim_time')
    wall = end - start
    by_name = cpu_percent(ticks0, ticks1, wall)
    sim_cpu, total_cpu = by_name.get(SIM_NODE, 0.0), sum(by_name.values())
    rtf = stats.real_time_factor(pairs)
    sim_span = pairs[-1][1] - pairs[0][1] if len(pairs) > 1 else 0.0
    out = {'robots': n, 'turning': turning, 'cameras': len(frames), 'window_s': round(wall, 2), 'real_time_factor': rtf,
           'sim_cpu_pct': round(sim_cpu, 1), 'total_cpu_pct': round(total_cpu, 1),
           'processes': len(ticks1),
           'cpu_by_process_pct': {name: round(pct, 1) for name, pct in sorted(by_name.items())},
           'machine_cpu_pct': round(100.0 * os.cpu_count() * (machine1[0] - machine0[0])
                                    / max(1, machine1[1] - machine0[1]), 1),
           'frames_per_sim_s': {r: round(c / sim_span, 2) if sim_span > 0 else None for r, c in frames.items()},
           'turns_ended_early': {r: res for r, res in ended.items()}}
    log('  N=%d (%d cameras): real-time factor %s, simulator %.0f %%, launch %.0f %% (%d processes), '
        'machine %.0f %% of a core' % (n, out['cameras'], '%.2f' % rtf if rtf is not None else 'unknown',
                                        sim_cpu, total_cpu, out['processes'], out['machine_cpu_pct']))
    return out


def measure(procs, quick, log):
    """Every size of SIZES, one after the other."""
    window = 8.0 if quick else 20.0
    return {'window_s': window, 'sizes': [measure_one(procs, n, window, log) for n in SIZES]}
