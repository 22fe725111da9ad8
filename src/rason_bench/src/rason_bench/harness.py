"""The controlling node of a benchmark run: starts measurements with control percepts,
acts as the decomposer of the benchmark agent's actions (``OK`` at once) and collects
the reports in them (:mod:`rason_bench.protocol`); notes when it hears motions and their
cancels on ``jason/action``. :class:`MotionWatch` times the twists on ``cmd_vel``."""
import itertools
import threading
import time

import rospy
from geometry_msgs.msg import Twist
from rason_msgs.msg import Action, Event, Perception

from rason_bench import preempt, protocol

#: Actions of other decomposers whose arrival the harness notes (time.monotonic).
NOTED_ACTIONS = ('move', Action.CANCEL)


class Timeout(RuntimeError):
    """The agent did not report in time."""


class Harness(object):

    def __init__(self):
        self._cond = threading.Condition()
        self._reports = []
        self._heard = {}  # perception source -> messages heard
        self._noted = []  # (time.monotonic, agent, action, action_id) of NOTED_ACTIONS
        self._runs = itertools.count(1)
        self._events = rospy.Publisher('jason/event', Event, queue_size=1000, tcp_nodelay=True)
        self._perceptions = rospy.Publisher('jason/perception', Perception, queue_size=1000, tcp_nodelay=True)
        rospy.Subscriber('jason/action', Action, self._on_action, queue_size=None, tcp_nodelay=True)
        self._hearing = None
        self.hear(True)

    def hear(self, on):
        """Count the messages on jason/perception (:meth:`heard`), or stop: the hostile part
        does not want this process to read 1 MB literals or a flood while it times the agent."""
        if on and self._hearing is None:
            self._hearing = rospy.Subscriber('jason/perception', Perception, self._on_perception, queue_size=1000,
                                             tcp_nodelay=True)
        elif not on and self._hearing is not None:
            self._hearing.unregister()
            self._hearing = None

    def next_run(self):
        return next(self._runs)

    # ---- the decomposer of the agent's actions ----

    def _on_action(self, msg):
        if msg.action in NOTED_ACTIONS:
            now = time.monotonic()
            with self._cond:
                self._noted.append((now, msg.agent, msg.action, msg.action_id))
                self._cond.notify_all()
            return
        received_ms = time.monotonic() * 1000.0
        try:
            report = protocol.parse_report(msg.action, msg.parameters)
        except protocol.BadReport as e:
            rospy.logerr('bad report from %s: %s', msg.agent, e)
            report = None
        if report is None and msg.action != 'ping':
            return
        self._events.publish(Event(agent=msg.agent, event_type=Event.ACTION_FEEDBACK,
                                   parameters=['OK', str(msg.action_id)]))
        if isinstance(report, protocol.Reacted):
            report = protocol.reaction(report, received_ms)
        elif isinstance(report, protocol.Marked):
            report = protocol.mark_seen(report, received_ms)
        if report is not None:
            with self._cond:
                self._reports.append(report)
                self._cond.notify_all()

    def _on_perception(self, msg):
        with self._cond:
            self._heard[msg.source] = self._heard.get(msg.source, 0) + 1
            self._cond.notify_all()

    # ---- waiting ----

    def _wait(self, ready, timeout, what):
        deadline = time.monotonic() + timeout
        with self._cond:
            while not ready():
                left = deadline - time.monotonic()
                if left <= 0 or rospy.is_shutdown():
                    raise Timeout('no %s within %.0f s' % (what, timeout))
                self._cond.wait(min(left, 0.1))

    def collect(self, kind, run, ready, timeout, what):
        """Wait until ``ready(reports)`` holds for the reports of type ``kind`` for ``run``
        (in arrival order); returns and forgets them."""
        def mine():
            return [r for r in self._reports if isinstance(r, kind) and r.run == run]
        self._wait(lambda: ready(mine()), timeout, '%s for run %d' % (what, run))
        with self._cond:
            found = mine()
            self._reports = [r for r in self._reports if not (isinstance(r, kind) and r.run == run)]
        return found

    def reports(self, kind, run, count, timeout, done=None, grace=0.0):
        """Wait for ``count`` reports of type ``kind`` for ``run`` (or, if given, one for which
        ``done(report)`` holds and then ``grace`` s more for the rest); returns them in arrival
        order."""
        done_at = []

        def ready(found):
            if len(found) >= count:
                return True
            if done is None:
                return False
            if not done_at and any(done(r) for r in found):
                done_at.append(time.monotonic())
            return bool(done_at) and time.monotonic() >= done_at[0] + grace
        return self.collect(kind, run, ready, timeout, '%d %s reports' % (count, kind.__name__))

    def heard(self, source):
        """How many messages of ``source`` this node has heard on jason/perception."""
        with self._cond:
            return self._heard.get(source, 0)
    def noted_action(self, agent, action, since, timeout, action_id=None):
        """The first ``action`` (one of :data:`NOTED_ACTIONS`) of ``agent`` heard at or after
        ``since`` (time.monotonic), with ``action_id`` if given: ``(time, action_id)``; older
        notes are forgotten."""
        def first():
            return next((n for n in self._noted if n[0] >= since and n[1] == agent and n[2] == action
                         and (action_id is None or n[3] == action_id)), None)
        self._wait(lambda: first() is not None, timeout, '%s of %s' % (action, agent))
        with self._cond:
            found = first()
            self._noted = [n for n in self._noted if n[0] >= since]
        return found[0], found[3]

    def wait_heard(self, source, count=1, timeout=20.0):
        """Wait until ``count`` more messages of ``source`` have been heard."""
        with self._cond:
            target = self._heard.get(source, 0) + count
        self._wait(lambda: self._heard.get(source, 0) >= target, timeout, 'messages from %s' % source)

    def handshake(self, agent, timeout=60.0):
        """Wait until ``agent`` answers a one-ping run: our percepts reach it, its actions reach
        us and our feedback reaches it (connection counts can still include a node just stopped)."""
        deadline = time.monotonic() + timeout
        while True:
            run = self.next_run()
            self.control(protocol.go_ping(agent, run, 1))
            try:
                self.reports(protocol.RoundTrip, run, 1, 0.5)
                return
            except Timeout:
                if time.monotonic() > deadline:
                    raise Timeout('%s did not answer within %.0f s' % (agent, timeout))

    # ---- commands ----

    def control(self, literal):
        self._perceptions.publish(Perception(source=protocol.CONTROL_SOURCE, perception=[literal]))

    def publish_perception(self, msg):
        """Any rason_msgs/Perception, on the topic (and so in the order) of the harness's own."""
        self._perceptions.publish(msg)

    def publish_event(self, msg):
        """Any rason_msgs/Event, as a decomposer would publish it."""
        self._events.publish(msg)

    def cycle(self, agent, iterations, timeout):
        """One run of the Listing 5.4 loop by ``agent``: a :class:`protocol.Cycle`."""
        run = self.next_run()
        self.control(protocol.go_cycle(agent, run, iterations))
        return self.reports(protocol.Cycle, run, 1, timeout)[0]

    def pings(self, agent, count, timeout):
        """``count`` action round trips by ``agent``: ms each."""
        run = self.next_run()
        self.control(protocol.go_ping(agent, run, count))
        return [r.ms for r in self.reports(protocol.RoundTrip, run, count, timeout)]

    def _publish_series(self, source, literal, count, period):
        """Publish ``literal(run, seq, now_ms)`` from ``source`` (a name, or a function of seq),
        seq 0 .. count - 1, one every ``period`` s on the wall clock; the run."""
        run = self.next_run()
        source_of = source if callable(source) else (lambda _seq: source)
        next_time = time.monotonic()
        for seq in range(count):
            now_ms = time.monotonic() * 1000.0
            self._perceptions.publish(Perception(source=source_of(seq), perception=[literal(run, seq, now_ms)]))
            next_time += period
            time.sleep(max(0.0, next_time - time.monotonic()))
        return run

    def stamps(self, count, period, timeout):
        """Publish ``count`` stamp percepts, one every ``period`` s; ms from publish to the agent's
        plan, for each stamp the agent saw (with per-source replacement, a stamp overtaken by the
        next one before the agent perceived is never seen, by design)."""
        run = self._publish_series(protocol.STAMP_SOURCE, protocol.stamp, count, period)
        last = count - 1
        return [r.ms for r in self.reports(protocol.Seen, run, count, timeout, done=lambda r: r.seq == last)]

    def triggers(self, count, period, timeout):
        """Publish ``count`` trigger percepts, one every ``period`` s (sources in turn:
        :func:`protocol.trigger_source`); ms from publish to the agent's ``react`` action
        arriving here, for each trigger it reacted to."""
        run = self._publish_series(protocol.trigger_source, protocol.trigger, count, period)
        last = count - 1
        return [r.ms for r in self.reports(protocol.Reaction, run, count, timeout, done=lambda r: r.seq == last,
                                           grace=1.0)]

    def spin(self, agent, count, timeout=30.0):
        """``agent`` starts ``count`` busy intentions; the run (for :meth:`stop_spin`)."""
        run = self.next_run()
        self.control(protocol.go_spin(agent, run, count))
        self.reports(protocol.Spinning, run, 1, timeout)
        return run

    def stop_spin(self, agent, run, count, timeout=30.0):
        """End the busy intentions of ``run``; the turns each made."""
        self.control(protocol.stop_spin(agent, run))
        return [r.turns for r in self.reports(protocol.Spun, run, count, timeout)]

    def ticks(self, agents, count, period, timeout):
        """Publish tick(Run, Seq), seq 0 .. count - 1, one every ``period`` s, from one source;
        once every agent of ``agents`` has had the last one, {agent: [its Ticked in order]}."""
        run = self._publish_series(protocol.TICK_SOURCE, lambda r, q, _now: protocol.tick(r, q), count, period)
        last = count - 1

        def ready(found):
            return set(agents) <= {r.agent for r in found if r.seq == last}
        found = self.collect(protocol.Ticked, run, ready, timeout, 'the last tick at %s' % ', '.join(agents))
        return {a: [r for r in found if r.agent == a] for a in agents}

class MotionWatch(object):
    """Subscribes ``cmd_vel`` and times, per take-back round (:class:`preempt.Round`), the
    first non-zero twist and the first zero twist after it (time.monotonic on arrival)."""

    def __init__(self, topic='cmd_vel'):
        self._cond = threading.Condition()
        self._round = preempt.Round()
        self._sub = rospy.Subscriber(topic, Twist, self._on_twist, queue_size=None, tcp_nodelay=True)

    def _on_twist(self, msg):
        now = time.monotonic()
        zero = preempt.is_zero(msg.linear.x, msg.linear.y, msg.linear.z,
                               msg.angular.x, msg.angular.y, msg.angular.z)
        with self._cond:
            self._round.twist(now, zero)
            self._cond.notify_all()

    def start_round(self):
        """Forget what was heard; returns the new round (read it after :meth:`wait`)."""
        with self._cond:
            self._round = preempt.Round()
            return self._round

    def wait(self, ready, timeout, what):
        """Wait until ``ready(round)``."""
        deadline = time.monotonic() + timeout
        with self._cond:
            while not ready(self._round):
                left = deadline - time.monotonic()
                if left <= 0 or rospy.is_shutdown():
                    raise Timeout('no %s within %.0f s' % (what, timeout))
                self._cond.wait(min(left, 0.1))

    def wait_publisher(self, timeout):
        """Wait until a publisher of the topic is connected."""
        deadline = time.monotonic() + timeout
        while self._sub.get_num_connections() == 0:
            if time.monotonic() > deadline:
                raise Timeout('nobody publishes %s within %.0f s' % (self._sub.name, timeout))
            time.sleep(0.05)

    def close(self):
        self._sub.unregister()
