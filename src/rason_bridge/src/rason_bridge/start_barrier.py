"""The start barrier: a program written for one MAS often assumes its agents start together
(Jason's own examples ``.wait(1000)`` for directory registrations). Split over robots started
seconds apart, it would find nobody; with ``~await_agents`` / ``~await_robots`` the node holds
its agents' start until those are present, at most ``~await_timeout`` seconds. No rospy."""

import time

#: How often the node looks at who is present while it holds the start (s).
POLL = 0.05


class StartBarrier(object):
    """
    :param agents: names of agents (of any robot) that must be present
    :param robots: how many other rason_mas processes must be reachable
    :param timeout: seconds (wall clock) after which the agents start anyway
    """

    def __init__(self, agents, robots, timeout):
        self.agents = list(agents)
        self.robots = robots
        self.timeout = timeout

    @property
    def active(self):
        return bool(self.agents) or self.robots > 0

    def describe(self):
        """What the barrier waits for, as a log line says it."""
        parts = []
        if self.agents:
            parts.append('agents %s' % ', '.join(self.agents))
        if self.robots:
            parts.append('%d other robot%s' % (self.robots, '' if self.robots == 1 else 's'))
        return ' and '.join(parts)

    def missing(self, present_agents, present_robots):
        """What is still missing, as a list of log words (empty: the agents may start)."""
        out = ['agent %s' % a for a in self.agents if a not in present_agents]
        if present_robots < self.robots:
            out.append('%d of %d other robots' % (self.robots - present_robots, self.robots))
        return out

    def wait(self, present, clock, pause, alive=lambda: True):
        """Holds until nothing is missing, the timeout passes or ``alive()`` turns false.

        :param present: ``present()`` -> (names of the present agents, number of reachable robots)
        :param clock: ``clock()`` -> seconds, monotonic
        :param pause: ``pause(seconds)`` waits (an Event's wait, so a shutdown ends it)
        :return: (what is still missing, seconds waited)
        """
        start = clock()
        while True:
            missing = self.missing(*present())
            waited = clock() - start
            if not missing or waited >= self.timeout or not alive():
                return missing, waited
            pause(min(POLL, self.timeout - waited))


def hold(barrier, present, info, warn, pause, alive, clock=time.monotonic):
    """Holds the agents' start behind barrier (if it waits for anything), with one log line
    when it starts holding and one when it lets go: which says what was missing, if anything."""
    if not barrier.active:
        return
    info('holding the agents until %s are present (at most %g s, ~await_timeout)'
         % (barrier.describe(), barrier.timeout))
    missing, waited = barrier.wait(present, clock, pause, alive)
    if missing:
        warn('starting the agents without %s: not present after %.1f s (~await_timeout)' % (', '.join(missing), waited))
    else:
        info('%s present after %.1f s: starting the agents' % (barrier.describe(), waited))
