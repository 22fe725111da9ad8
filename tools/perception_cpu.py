#!/usr/bin/python3
"""CPU per perception message of rason_mas's perception path, in one process and without a ROS
master: the JVM, Java's Bridge, a project's agents, the node's Inbound, coalescer and perception
pump, as rason_mas wires them. A feeder thread stands in for rospy's receiving thread: it takes
each message's serialized bytes (made before the measurement), makes the message with the data
class Inbound subscribes with (genpy's Perception, or AnyMsg) and calls Inbound's callback, as
rospy does after reading the socket. What the socket and rospy's framing cost is not counted here
(tools/thread_cpu.sh measures the whole node).

  tools/perception_cpu.py pipeline MAS2J|none [SECONDS [WARM [RATE [COUNT]]]]
      CPU per thread (from /proc) over SECONDS after WARM seconds of a COUNT x RATE Hz burst,
      every literal new in every message (rason_bench's burst); also the CPU of the feeder's
      callbacks and of the pump's calls into Java apart, the Python collections (by thread,
      with their CPU), the JVM's collections and the floods ended in the window.
      GC_UNFREEZE=1: with the start-up objects back in the collections (as before gc.freeze)
  tools/perception_cpu.py stages [N]
      each step alone, N messages in a loop, on the calling thread's CPU clock (no agents)

Run with the worktree's ROS environment (for rason_msgs) and /usr/bin/python3.
"""
import gc
import inspect
import os
import sys
import threading
import time

import jpype
import rospy
from rason_msgs.msg import Perception

from rason_bridge import java_config, jvm, log_pump
from rason_bridge.coalesce import PerceptionCoalescer
from rason_bridge.inbound import Inbound
from rason_bridge.params import read_settings
from rason_bridge.perception_pump import PerceptionPump

SOURCE = 'bench_synth_burst'


def burst(count, seq):
    return ['perception%d(%d)' % (k, seq) for k in range(1, count + 1)]


def serialized(count, seq):
    import io
    buff = io.BytesIO()
    Perception(source=SOURCE, perception=burst(count, seq)).serialize(buff)
    return buff.getvalue()


def make_bridge(mas2j):
    jvm.start_jvm()
    settings = read_settings(lambda name, default: default, '/tmp')
    bridge = java_config.bridge()
    java_config.push(bridge, settings, '/perception_cpu', time.time_ns())
    bridge.attach()
    if mas2j != 'none':
        mas = java_config.load_mas(bridge, settings, mas2j)
        bridge.tick(time.monotonic_ns())
        mas.start()
    return bridge, settings


def perceive_of(port):
    """What the node hands the pump: the port's method for the messages Inbound stores."""
    return getattr(port, 'perceiveSerialized', None) or port.perceive


def subscribed_class(inbound):
    """(data class, callback) of Inbound's jason/perception subscription, without a master."""
    seen = {}

    def fake_subscriber(topic, data_class, callback, **_):
        seen[topic] = (data_class, callback)

    real, rospy.Subscriber = rospy.Subscriber, fake_subscriber
    try:
        inbound.subscribe()
    finally:
        rospy.Subscriber = real
    return seen['jason/perception']


def thread_cpu():
    """{tid: (cpu s, name)} of this process's threads."""
    hz = os.sysconf('SC_CLK_TCK')
    out = {}
    for tid in os.listdir('/proc/self/task'):
        try:
            with open('/proc/self/task/%s/stat' % tid) as f:
                fields = f.read().rsplit(')', 1)[1].split()
            with open('/proc/self/task/%s/comm' % tid) as f:
                comm = f.read().strip()
        except OSError:
            continue
        out[int(tid)] = ((int(fields[11]) + int(fields[12])) / hz, comm)
    return out


def pipeline(mas2j, seconds=20.0, warm=30.0, rate=50.0, count=10):
    bridge, settings = make_bridge(mas2j)
    names = {threading.get_native_id(): 'main'}
    perceive, in_perceive = perceive_of(bridge.perception()), [0.0, 0]

    def timed_perceive(*args):  # the CPU of the pump thread's call into Java, apart
        t0 = time.thread_time()
        try:
            return perceive(*args)
        finally:
            in_perceive[0] += time.thread_time() - t0
            in_perceive[1] += 1
    released = [0]

    def release_memory():  # counted: each is a concurrent collection of the JVM
        released[0] += 1
        bridge.releaseMemory()
    pump = PerceptionPump(PerceptionCoalescer(settings.max_sources, java_config.max_source_length()),
                          timed_perceive, release_memory,
                          lambda *a: print('warn', a[0] % a[1:]), lambda *a: print('error', a[0] % a[1:]))
    args = (bridge, bridge.rosChannel(), '/perception_cpu', pump, time.monotonic_ns)
    with_settings = 'settings' in inspect.signature(Inbound).parameters  # since Inbound reads the input limits
    inbound = Inbound(*(args + (settings,) if with_settings else args))
    data_class, callback = subscribed_class(inbound)
    header = {'type': Perception._type, 'md5sum': Perception._md5sum, 'callerid': '/bench_synth'}
    total = int((warm + seconds) * rate) + 10
    messages = [serialized(count, seq) for seq in range(1, total + 1)]
    stop = threading.Event()
    in_callback = [0.0, 0]

    def named(target, name):
        def run():
            names[threading.get_native_id()] = name
            target()
        threading.Thread(target=run, name=name, daemon=True).start()

    def feed():
        period, next_time = 1.0 / rate, time.monotonic()
        for raw in messages:
            if stop.is_set():
                return
            t0 = time.thread_time()
            msg = data_class().deserialize(raw)
            msg._connection_header = header
            callback(msg)
            in_callback[0] += time.thread_time() - t0
            in_callback[1] += 1
            next_time += period
            time.sleep(max(0.0, next_time - time.monotonic()))

    def tick_and_drain():  # the node's 50 ms timer and its log thread (lines dropped, not published)
        while not stop.is_set():
            bridge.tick(time.monotonic_ns())
            log_pump.batch_lines(bridge.log().drainBatch(log_pump.BATCH))
            time.sleep(0.05)

    if os.environ.get('GC_UNFREEZE'):  # undoes rason_bridge.jvm.settle_python_objects, to measure without
        gc.unfreeze()
    pump.start()
    named(feed, 'feeder(rospy)')
    named(tick_and_drain, 'tick+log')
    time.sleep(warm)
    for t in threading.enumerate():
        if t.native_id and t.native_id not in names:
            names[t.native_id] = t.name
    in_perceive[:] = [0.0, 0]
    released[0] = 0
    in_callback[:] = [0.0, 0]
    collections = python_gc_log()
    java_gc0 = java_gc_counts()
    a, w0 = thread_cpu(), time.monotonic()
    time.sleep(seconds)
    b, w1 = thread_cpu(), time.monotonic()
    stop.set()
    java_gc1 = java_gc_counts()
    print('feeder: deserialize + callback %.0f us of its CPU per message (%d); pump: the call into Java %.0f us '
          'per call (%d calls)' % (1e6 * in_callback[0] / max(1, in_callback[1]), in_callback[1],
                                   1e6 * in_perceive[0] / max(1, in_perceive[1]), in_perceive[1]))
    summary = {}
    for thread, generation, cpu in list(collections):
        n, total = summary.get((thread, generation), (0, 0.0))
        summary[(thread, generation)] = (n + 1, total + cpu)
    for (thread, generation), (n, total) in sorted(summary.items()):
        print('python gc: %d collections of generation %d on %s, %.1f ms of its CPU'
              % (n, generation, thread, 1000 * total))
    print('floods ended (releaseMemory) in the window: %d' % released[0])
    print('java gc in the window: %s' % ', '.join('%s %d' % (k, java_gc1[k] - java_gc0.get(k, 0)) for k in java_gc1))
    print('python objects tracked by gc: %d' % len(gc.get_objects()))
    for t in threading.enumerate():
        if t.native_id and t.native_id not in names:
            names[t.native_id] = t.name
    msgs = (w1 - w0) * rate
    rows = sorted(((b[t][0] - a.get(t, (0.0,))[0], names.get(t, b[t][1]), t) for t in b), reverse=True)
    total_cpu = sum(r[0] for r in rows)
    print('%s: window %.1f s after %.0f s warm, %d x %g Hz, ~%d messages; process CPU %.0f ms, %.0f us per message'
          % (os.path.basename(mas2j), w1 - w0, warm, count, rate, msgs, 1000 * total_cpu, 1e6 * total_cpu / msgs))
    jit = sum(r[0] for r in rows if r[1].startswith(('C1 Compiler', 'C2 Compiler')))
    print('  without the JIT compiler threads: %.0f us per message' % (1e6 * (total_cpu - jit) / msgs))
    for cpu, name, tid in rows[:14]:
        if cpu > 0:
            print('  %7.0f ms %6.0f us/msg  %s (%d)' % (1000 * cpu, 1e6 * cpu / msgs, name, tid))
    sys.stdout.flush()
    os._exit(0)


def python_gc_log():
    """A list that gets (thread name, generation, thread CPU s) of each Python collection from now on."""
    log, started = [], {}

    def callback(phase, info):
        tid = threading.get_native_id()
        if phase == 'start':
            started[tid] = time.thread_time()
        elif tid in started:
            log.append((threading.current_thread().name, info['generation'], time.thread_time() - started.pop(tid)))
    gc.callbacks.append(callback)
    return log


def java_gc_counts():
    beans = jpype.JClass('java.lang.management.ManagementFactory').getGarbageCollectorMXBeans()
    return {str(b.getName()): int(b.getCollectionCount()) for b in beans}


def timed(label, n, step):
    step(0)  # the first call loads classes
    t0 = time.thread_time()
    for i in range(1, n + 1):
        step(i)
    us = 1e6 * (time.thread_time() - t0) / n
    print('  %-58s %7.1f us/msg' % (label, us))
    return us


def stages(n=20000):
    bridge, _ = make_bridge('none')
    port = bridge.perception()
    raws = [serialized(10, seq) for seq in range(n + 1)]
    lists = [burst(10, seq) for seq in range(n + 1)]
    print('stages, 10 literals a message, each new, %d messages (thread CPU, no agents):' % n)
    timed('genpy: Perception().deserialize(bytes)', n, lambda i: Perception().deserialize(raws[i]))
    timed('AnyMsg().deserialize(bytes)', n, lambda i: rospy.AnyMsg().deserialize(raws[i]))
    coalescer = PerceptionCoalescer()

    def coalesce(i):
        coalescer.put(SOURCE, lists[i], i)
        coalescer.take(0)
    timed('coalescer put + take', n, coalesce)
    for _ in range(3):  # the JIT compiles the parser before the Java steps are timed
        for i in range(n + 1):
            port.perceive(SOURCE, lists[i], i)
    timed('perceive(source, list of str): JPype + parse (new literals)', n,
          lambda i: port.perceive(SOURCE, lists[i], i))
    timed('perceive(source, list of str): JPype, literals as before', n,
          lambda i: port.perceive(SOURCE, lists[0], i))
    jstring_array = jpype.JArray(jpype.JString)
    arrays = [jstring_array(lists[i]) for i in range(n + 1)]
    timed('JArray(JString)(list of str) alone', n, lambda i: jstring_array(lists[i]))
    timed('perceive(source, String[] made before): parse (new literals)', n,
          lambda i: port.perceive(SOURCE, arrays[i], i))
    timed('perceive(source, String[] made before), literals as before', n,
          lambda i: port.perceive(SOURCE, arrays[0], i))
    if hasattr(port, 'perceiveSerialized'):
        from rason_bridge.perception_wire import SourceReader
        reader, header = SourceReader(2 ** 24, 256, Perception._md5sum), {'md5sum': Perception._md5sum}
        timed('SourceReader.source(bytes, header)', n, lambda i: reader.source(raws[i], header))
        for _ in range(3):
            for i in range(n + 1):
                port.perceiveSerialized(SOURCE, raws[i], i)
        timed('perceiveSerialized(source, bytes): JPype + decode + parse', n,
              lambda i: port.perceiveSerialized(SOURCE, raws[i], i))
        timed('perceiveSerialized(source, bytes), literals as before', n,
              lambda i: port.perceiveSerialized(SOURCE, raws[0], i))
    sys.stdout.flush()
    os._exit(0)


def main(argv):
    if argv[1:2] == ['stages']:
        stages(*[int(a) for a in argv[2:3]])
    elif argv[1:2] == ['pipeline'] and len(argv) >= 3:
        pipeline(argv[2], *[float(a) for a in argv[3:6]], *[int(a) for a in argv[6:7]])
    else:
        print(__doc__, file=sys.stderr)
        return 2
    return 0


if __name__ == '__main__':
    try:
        code = main(sys.argv)
    except BaseException:  # the agents' threads would hold the JVM, and so the process, open
        import traceback
        traceback.print_exc()
        code = 1
    sys.stdout.flush()
    os._exit(code)
