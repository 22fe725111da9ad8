"""Simulated time standing still, said: under /use_sim_time every .wait, action timeout and
plan deadline of the agents waits for /clock, so a paused or dead simulator suspends them all,
as ROS means it to. That must not look like agents that hang for no reason; no rospy."""
import time

#: Wall seconds without a step of /clock before it is said.
STALL = 5.0


class ClockWatch(object):
    """
    :param stall: wall seconds without a /clock step before :meth:`due` says so
    :param repeat: wall seconds between two reminders while it stands still
    """

    def __init__(self, stall=STALL, repeat=60.0, clock=time.monotonic):
        self._stall, self._repeat, self._clock = stall, repeat, clock
        self._ros = None                 # the last ROS time heard (ns)
        self._moved_at = clock()         # wall time of the last step (or of the start)
        self._said_at = None             # wall time of the last "stands still" line

    def heard(self, ros_ns):
        """A /clock message (rospy's thread); a time other than the last is a step (one back too:
        a simulator restarted)."""
        if ros_ns != self._ros:
            self._ros = ros_ns
            self._moved_at = self._clock()

    def due(self):
        """The line to log now, or None."""
        now = self._clock()
        still = now - self._moved_at
        if still < self._stall:
            if self._said_at is None:
                return None
            self._said_at = None
            return '/clock moves again: the agents\' waits and timeouts go on'
        if self._said_at is not None and now - self._said_at < self._repeat:
            return None
        self._said_at = now
        where = ('no /clock heard since the start' if self._ros is None
                 else 'simulated time stands at %.3f s' % (self._ros / 1e9))
        return ('/clock has not moved for %.0f s (%s): under /use_sim_time the agents\' .wait, action timeouts '
                'and deadlines wait with it; is the simulator paused, or gone?' % (still, where))
