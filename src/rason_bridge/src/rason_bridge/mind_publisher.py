"""The mind publisher: the thread that switches the agents' state readings on while jason/mind
has subscribers, and publishes what changed (:mod:`rason_bridge.mind`), the state the agents
end in last; no rospy."""
import threading
import time

from rason_bridge.mind import MindSwitch, to_msg


class MindPublisher(object):
    """
    :param mind: Java's ``MindPort`` (``setPeriodNanos``, ``changes``, ``inspectorUrl``,
        ``requestReads``, ``readsPending``)
    :param publisher: the jason/mind publisher (``get_num_connections``, ``publish``)
    :param period: seconds between two readings (more than 0)
    :param now_ns: ``now_ns()`` -> the ROS time in nanoseconds
    :param closed: the exception a publisher raises once the node shuts down
    :param alive: ``alive()`` -> False once the process shuts down
    """

    def __init__(self, mind, publisher, mas_id, period, now_ns, closed, debug, alive=lambda: True):
        self._mind = mind
        self._publisher = publisher
        self._mas_id = mas_id
        self._period = period
        self._now_ns = now_ns
        self._closed = closed
        self._debug = debug
        self._alive = alive
        self._switch = MindSwitch(int(round(period * 1e9)))
        self._stop = threading.Event()
        self._publishing = threading.Lock()  # the final publication is never overtaken by an older one

    def start(self):
        threading.Thread(target=self._run, name='rason_mind', daemon=True).start()

    def stop(self):
        self._stop.set()

    def finish(self, timeout=1.0, poll=0.01):
        """The last publication, before the agents stop: each agent reads the state it ends in
        (waiting at most ``timeout`` s for them) and what changed is published; then stops."""
        self._stop.set()
        if not self._switch.on:
            return
        self._mind.requestReads()
        deadline = time.monotonic() + timeout
        while self._mind.readsPending() > 0 and time.monotonic() < deadline:
            time.sleep(poll)  # Java has no callback for this; each read ends one agent's cycle
        self._publish()

    def _run(self):
        while not self._stop.is_set() and self._alive():
            self.step()
            self._stop.wait(self._period)

    def step(self):
        """Switch the readings on or off as the subscribers come and go; publish what changed."""
        period = self._switch.update(self._publisher.get_num_connections())
        if period is not None:
            self._mind.setPeriodNanos(period)
        if not self._switch.on:
            return
        self._publish()

    def _publish(self):
        with self._publishing:
            minds = self._mind.changes()
            if minds is None:
                return
            try:
                self._publisher.publish(to_msg(self._mas_id, self._now_ns(), minds,
                                               str(self._mind.inspectorUrl())))
            except self._closed as e:  # shutting down
                self._debug('jason/mind not published: %s', e)
