"""Behaviour with numbers (they were rostest assertions; the rostests now check the
behaviour loosely): the simulator's real-time factor and topic rates with both robots'
execution layers running, an idle agent's wake-up on a perception, and the perception rate
limit. ``--only behaviour``."""
import importlib
import signal
import threading
import time

import rospy

from rason_bench import stats
from rason_bench.experiments import Mas

#: The topics whose rates the simulator part measures: (name, topic, package, type).
SIM_TOPICS = (('faulty odom', '/faulty/odom', 'nav_msgs.msg', 'Odometry'),
              ('helper odom', '/helper/odom', 'nav_msgs.msg', 'Odometry'),
              ('camera', '/helper/camera/rgb/camera_info', 'sensor_msgs.msg', 'CameraInfo'),
              ('vision', '/helper/jason/perception', 'rason_msgs.msg', 'Perception'))


class _Arrivals(object):
    """Wall (monotonic) times of a topic's messages, and the last message."""

    def __init__(self, topic, kind):
        self.lock = threading.Lock()
        self.times = []
        self.last = None
        self.sub = rospy.Subscriber(topic, kind, self._on_msg, queue_size=100)

    def _on_msg(self, msg):
        now = time.monotonic()
        with self.lock:
            self.times.append(now)
            self.last = msg
            self.on_msg(now, msg)

    def on_msg(self, now, msg):
        pass


class _Clock(_Arrivals):
    """/clock: (wall, simulated) seconds of each message."""

    def __init__(self):
        from rosgraph_msgs.msg import Clock
        self.pairs = []
        super(_Clock, self).__init__('/clock', Clock)

    def on_msg(self, now, msg):
        self.pairs.append((now, msg.clock.to_sec()))


def sim_rates(procs, window, log, settle=2.0, start_timeout=90.0):
    """``roslaunch rason two_robots.launch`` (what the sim_rates rostest launches: the
    simulator at real-time factor 1, both robots' decomposers and fault injectors, the
    vision synthesizer) on the bench's master; once the vision synthesizer publishes and
    ``settle`` s more, the real-time factor and each topic's rate over ``window`` wall s."""
    counters = {name: _Arrivals(topic, getattr(importlib.import_module(module), kind))
                for name, topic, module, kind in SIM_TOPICS}
    clock = _Clock()
    proc = procs.roslaunch('two_robots', 'rason', 'two_robots.launch')
    try:
        deadline = time.monotonic() + start_timeout
        while counters['vision'].last is None:  # vision_synth subscribed: the camera renders
            if time.monotonic() > deadline or proc.poll() is not None:
                raise RuntimeError('the vision synthesizer never published (see %s/two_robots.log)'
                                   % procs.log_dir)
            time.sleep(0.1)
        time.sleep(settle)
        start = time.monotonic()
        time.sleep(window)
        end = time.monotonic()
        with clock.lock:
            pairs = [p for p in clock.pairs if start <= p[0] < end]
        out = {'window_s': window, 'settle_s': settle, 'real_time_factor': stats.real_time_factor(pairs),
               'rates_hz': {}}
        for name, c in counters.items():
            with c.lock:
                out['rates_hz'][name] = stats.rate_hz(c.times, start, end)
    finally:
        for c in list(counters.values()) + [clock]:
            c.sub.unregister()
        procs.stop(proc, sig=signal.SIGINT, timeout=30.0)
        # the launch set /use_sim_time: nodes started after it must not wait for a /clock
        if rospy.has_param('/use_sim_time'):
            rospy.delete_param('/use_sim_time')
    rtf = out['real_time_factor']
    log('  simulator: real-time factor %s; %s' % ('%.3f' % rtf if rtf is not None else 'unknown (no /clock)',
                                                 ', '.join('%s %.1f Hz' % kv for kv in sorted(out['rates_hz'].items()))))
    return out


def wakeup(procs, harness, count, gap, log):
    """Stamped percepts to an idle agent, ``gap`` s apart (longer than an idle Jason agent
    sleeps, 1 s): ms from publish to its plan for each."""
    with Mas(procs, harness, 'bench.mas2j'):
        harness.stamps(5, 0.05, timeout=30.0)  # warm up
        time.sleep(gap)
        samples = harness.stamps(count, gap, timeout=30.0 + count * gap)
    out = {'gap_s': gap, 'stamps_sent': count, 'wakeup_ms': stats.summarize(samples),
           'wakeup_samples': [round(x, 3) for x in samples]}
    if samples:
        log('  idle wake-up: %d of %d stamps, max %.1f ms, p50 %.1f ms'
            % (len(samples), count, out['wakeup_ms']['max'], out['wakeup_ms']['p50']))
    return out


def rate_limit(procs, harness, seconds, rate_hz, log):
    """tick(Run, Seq) at ``rate_hz`` for ``seconds`` from one source to two agents of one node,
    ``plain`` and ``limited`` (perception_rate=5 in agents/rate_limit.mas2j): how many updates
    reached each, and how often."""
    count = int(round(seconds * rate_hz))
    with Mas(procs, harness, 'rate_limit.mas2j') as mas:
        agents = sorted(mas.agents)
        harness.ticks(agents, 10, 0.05, timeout=30.0)  # warm up
        time.sleep(1.0)
        got = harness.ticks(agents, count, 1.0 / rate_hz, timeout=30.0 + seconds)
    out = {'sent': count, 'sent_hz': rate_hz, 'seconds': seconds,
           'agents': {a: stats.update_rate([r.ms for r in got[a]]) for a in agents}}
    log('  rate limit: %d ticks at %g Hz; %s' % (count, rate_hz, '; '.join(
        '%s %d updates, %s/s' % (a, r['n'], '%.2f' % r['per_s'] if r['per_s'] is not None else '-')
        for a, r in sorted(out['agents'].items()))))
    return out
