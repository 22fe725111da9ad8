"""Start-up of a one-agent rason_mas (issue 35): from starting its process to the agent's first
reasoning cycle, and the process's memory once it runs. The process is the node's own script
(not ``rosrun``, whose package search is no part of the node's start-up); the agent
(agents/startup.asl) reads the monotonic clock in its first cycle and reports it when asked."""
import os
import re
import time

import psutil
import rospy
from roslib.packages import find_node

from rason_bench import protocol, stats
from rason_bench.experiments import agents_file

#: The node's own line about class-data sharing (rason_bridge.jvm.cds_decision).
_CDS_LINE = re.compile(r'(class-data sharing: .*)$')


def measure(procs, harness, runs, log):
    """``runs`` starts, one after the other: per start the seconds to the first cycle, the CPU
    time the process had used when asked (user + sys: start-up and the handshake, less
    dependent on a busy machine than the wall time), the RSS then and the peak RSS (MB); their
    medians, and the node's class-data sharing line."""
    exe = find_node('rason_bridge', 'rason_mas')[0]
    samples = []
    for i in range(runs):
        if rospy.has_param('/rason_mas/agents'):  # left by the previous run's node
            rospy.delete_param('/rason_mas/agents')
        t0 = time.monotonic()
        proc = procs.start('rason_mas', [exe, agents_file('startup.mas2j'), '__name:=rason_mas'])
        try:
            agent = _agent_name(time.monotonic() + 60.0)
            harness.handshake(agent, 60.0)
            run = harness.next_run()
            harness.control(protocol.go_started(agent, run))
            first_ms = harness.reports(protocol.Started, run, 1, 10.0)[0].ms
            ps = psutil.Process(proc.pid)
            cpu = ps.cpu_times()
            samples.append({'to_first_cycle_s': first_ms / 1000.0 - t0, 'cpu_s': cpu.user + cpu.system,
                            'rss_mb': ps.memory_info().rss / 2.0 ** 20, 'rss_peak_mb': _peak_mb(proc.pid)})
        finally:
            procs.stop(proc)
        log('  start %d: first reasoning cycle after %.2f s; CPU %.2f s; RSS %.0f MB (peak %.0f MB)'
            % (i + 1, samples[-1]['to_first_cycle_s'], samples[-1]['cpu_s'], samples[-1]['rss_mb'],
               samples[-1]['rss_peak_mb']))
    out = {key: stats.median([s[key] for s in samples])
           for key in ('to_first_cycle_s', 'cpu_s', 'rss_mb', 'rss_peak_mb')}
    out.update(runs=samples, cds=_cds_line(os.path.join(procs.log_dir, 'rason_mas.log')))
    log('  %s' % out['cds'])
    return out


def _agent_name(deadline):
    while time.monotonic() < deadline:
        if rospy.has_param('/rason_mas/agents'):
            return rospy.get_param('/rason_mas/agents')[0]
        time.sleep(0.05)
    raise RuntimeError('rason_mas did not list its agents')


def _peak_mb(pid):
    """VmHWM: the largest RSS the process has had."""
    with open('/proc/%d/status' % pid) as f:
        return next(int(line.split()[1]) for line in f if line.startswith('VmHWM:')) / 1024.0


def _cds_line(log_file):
    """The last class-data sharing line the node logged, or None."""
    try:
        with open(log_file, errors='replace') as f:
            found = [m.group(1) for m in map(_CDS_LINE.search, f) if m]
    except OSError:
        return None
    return found[-1].strip() if found else None
