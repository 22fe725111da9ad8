"""Helpers shared by the rostest scripts: waiting on a condition with a deadline, watching
rosout, publishing feedback, and commanding and starting the agents of the multi-robot tests."""
import functools
import itertools
import os
import re
import signal
import subprocess
import threading
import time
import xmlrpc.client

import rosgraph
import rospkg
import rospy
from rosgraph_msgs.msg import Log
from rason_msgs.msg import AgentMessage, Event, Perception, Presence

from fleet_wire import fleet_channel, fleet_params


@functools.lru_cache(maxsize=None)
def node_command(package, executable):
    """The command that runs ``executable`` of ``package``, as ``rosrun package executable``
    would: its file in the catkin workspace, looked up once per test process (rosrun looks it up
    on every start, most of a second of CPU each time)."""
    from catkin.find_in_workspaces import find_in_workspaces
    found = find_in_workspaces(['libexec'], project=package, path=executable, first_match_only=True)
    if not found or not os.access(found[0], os.X_OK):
        raise RuntimeError('no executable %s in package %s (is the workspace built?)' % (executable, package))
    return [found[0]]


def poll(predicate, timeout, interval=0.02):
    """Call ``predicate`` until it returns something true, and return that; None once
    ``timeout`` s have passed (or ROS shut down) without it."""
    deadline = time.monotonic() + timeout
    while True:
        value = predicate()
        if value or time.monotonic() >= deadline or rospy.is_shutdown():
            return value or None
        time.sleep(interval)


def wait_for(predicate, timeout, what, interval=0.02):
    """:func:`poll`, failing with an AssertionError that names ``what`` was awaited."""
    value = poll(predicate, timeout, interval)
    if not value:
        raise AssertionError('waited %.1f s for %s in vain' % (timeout, what))
    return value


class LogWatcher(object):
    """Collects every rosout line (with the time it was heard) and waits for patterns."""

    def __init__(self):
        self._lines = []
        self._cond = threading.Condition()
        self._sub = rospy.Subscriber('/rosout', Log, self._on_log, queue_size=None)

    def _on_log(self, msg):
        with self._cond:
            self._lines.append((time.monotonic(), msg.level, msg.name, msg.msg))
            self._cond.notify_all()

    def wait_ready(self, timeout=20.0):
        """Wait until this watcher is connected to every node that publishes on /rosout."""
        master = rosgraph.Master(rospy.get_name())

        def connected_to_all():
            publishers, _, _ = master.getSystemState()
            listed = sum(len(n) for t, n in publishers if t == '/rosout')
            return listed and self._sub.get_num_connections() >= listed
        return bool(poll(connected_to_all, timeout))

    def clear(self):
        with self._cond:
            del self._lines[:]

    def lines(self, pattern=None, node=None):
        """Lines matching pattern, from the node called ``node`` if given."""
        with self._cond:
            return [l for l in self._lines if (pattern is None or re.search(pattern, l[3]))
                    and (node is None or l[2] == node)]

    def wait_quiet(self, seconds, pattern=None, timeout=30.0):
        """Wait until no line matching ``pattern`` has come for ``seconds``, counted from now
        at the earliest: for a test that needs, say, an agent left idle that long. Fails after
        ``timeout`` s of lines still coming."""
        start = time.monotonic()
        with self._cond:
            while True:
                now = time.monotonic()
                heard = [l[0] for l in self._lines if pattern is None or re.search(pattern, l[3])]
                quiet_since = max([start] + heard)
                if now - quiet_since >= seconds:
                    return
                if now - start >= timeout:
                    raise AssertionError('lines matching %r still came after %.0f s' % (pattern, timeout))
                self._cond.wait(min(seconds - (now - quiet_since), 0.1))

    def wait_for(self, pattern, timeout=20.0, count=1, node=None):
        """Wait until ``count`` lines match (from ``node`` if given); returns them (empty on timeout)."""
        deadline = time.monotonic() + timeout
        with self._cond:
            while True:
                found = [l for l in self._lines if re.search(pattern, l[3])
                         and (node is None or l[2] == node)]
                if len(found) >= count:
                    return found
                left = deadline - time.monotonic()
                if left <= 0 or rospy.is_shutdown():
                    return []
                self._cond.wait(min(left, 0.1))


class ScreenOutput(object):
    """The lines a process prints (stdout and stderr): for what a node says at its start,
    which can be over before any rosout connection is made."""

    def __init__(self, proc):
        self.proc = proc
        self._lines = []
        self._cond = threading.Condition()
        threading.Thread(target=self._read, daemon=True).start()

    def _read(self):
        for line in self.proc.stdout:
            with self._cond:
                self._lines.append(line.rstrip('\n'))
                self._cond.notify_all()

    def wait_for(self, pattern, timeout=20.0):
        """The lines matching ``pattern`` once there is one; empty after ``timeout`` s without."""
        deadline = time.monotonic() + timeout
        with self._cond:
            while True:
                found = [l for l in self._lines if re.search(pattern, l)]
                left = deadline - time.monotonic()
                if found or left <= 0:
                    return found
                self._cond.wait(min(left, 0.1))


def feedback(agent, result, action_id, event_type=Event.ACTION_FEEDBACK):
    """An Event message as a decomposer sends it."""
    return Event(agent=agent, event_type=event_type, parameters=[result, str(action_id)])


def wait_for_subscribers(pub, count=1, timeout=10.0):
    """True once ``pub`` has ``count`` subscribers, False if it has not after ``timeout`` s."""
    return bool(poll(lambda: pub.get_num_connections() >= count, timeout))


def wait_for_link(publisher_node, topic, subscriber_node, timeout=30.0):
    """True once publisher_node's publication of topic has its connection to subscriber_node up
    (what it publishes before that is lost), read from the publisher's own bus info; False if
    not after timeout s. Names are resolved."""
    master = rosgraph.Master('/rason_testing')

    def linked():
        try:
            code, _, info = xmlrpc.client.ServerProxy(master.lookupNode(publisher_node)).getBusInfo(
                '/rason_testing')
        except Exception:   # the node not registered or not answering yet
            return False
        return code == 1 and any(c[1] == subscriber_node and c[2] == 'o' and c[4] == topic for c in info)
    return bool(poll(linked, timeout))


def start_agents(log, timeout=20.0):
    """Once ``log`` hears every node, publish the percept ``go`` that the test agents wait for."""
    if not log.wait_ready(timeout):
        raise AssertionError('not connected to every /rosout publisher')
    pub = rospy.Publisher('jason/perception', Perception, queue_size=1, latch=True)
    if not wait_for_subscribers(pub, timeout=timeout):
        raise AssertionError('rason_mas does not subscribe to jason/perception')
    pub.publish(Perception(source='rostest_start', perception=['go']))
    return pub


# ---- multi-robot tests ------------------------------------------------------------------

HERE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
MULTI_AGENTS = os.path.join(HERE, 'agents', 'multi')
_command_ids = itertools.count(1)


class Robot(object):
    """Commands the agents of one namespace through percepts ``cmd(Id, Command)``
    (the test agents in agents/multi run Command and print ``Id ...``)."""

    def __init__(self, ns):
        self.ns = ns
        self.mas = '/%s/rason_mas' % ns
        self._pub = rospy.Publisher('/%s/jason/perception' % ns, Perception, queue_size=10)

    def wait_connected(self, timeout=30.0):
        if not wait_for_subscribers(self._pub, timeout=timeout):
            raise AssertionError('%s does not subscribe to jason/perception' % self.mas)
        # a robot the .test forgot to name to test/fleet_channel.launch would run on another channel
        channel = rospy.get_param(self.mas + '/fleet_channel', 'ros')
        if channel != fleet_channel():
            raise AssertionError('%s runs on fleet channel %s, this test on %s' % (self.mas, channel, fleet_channel()))

    def command(self, text):
        """Publish one command; returns its id (unique in the test process)."""
        n = next(_command_ids)
        self._pub.publish(Perception(source='rostest_cmd', perception=['cmd(%d, %s)' % (n, text)]))
        return n

    def perceive(self, source, *literals):
        self._pub.publish(Perception(source=source, perception=list(literals)))


def run(log, robot, agent, text, expect, timeout=15.0):
    """Command ``agent`` of ``robot`` and wait for its ``[agent] Id <expect>`` line; returns the text after the id."""
    n = robot.command(text)
    found = log.wait_for(r'^\[%s\] %d (%s)$' % (agent, n, expect), timeout=timeout)
    if not found:
        got = [l[3] for l in log.lines(r'^\[%s\] %d ' % (agent, n))]
        raise AssertionError('%s: %s gave no line matching %r (got %r)' % (agent, text, expect, got))
    return re.search(r'^\[%s\] %d (.*)$' % (agent, n), found[0][3]).group(1)


def run_refused_node(package, node, ns, name, param, value, timeout=60.0):
    """Runs a node whose ~param is value and that must refuse it: returns (exit status,
    its [FATAL] lines, all its output)."""
    rospy.set_param('/%s/%s/%s' % (ns, name, param), value)
    proc = subprocess.Popen(node_command(package, node) + ['__ns:=/' + ns, '__name:=' + name],
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, universal_newlines=True)
    out, _ = proc.communicate(timeout=timeout)
    return proc.returncode, [line for line in out.splitlines() if line.startswith('[FATAL]')], out


def start_mas(ns, mas2j, output=None, cwd=None, **params):
    """Start a rason_mas in namespace ns with ~params (and those of this test's fleet channel,
    :func:`fleet_wire.fleet_params`); stop it with :func:`stop_mas` or SIGKILL.

    :param output: where its stdout and stderr go (e.g. ``subprocess.PIPE``); None: this process's
    :param cwd: its working directory (None: this process's)
    """
    args = node_command('rason_bridge', 'rason_mas') + [mas2j, '__ns:=/' + ns]
    args += ['_%s:=%s' % (k, v) for k, v in dict(fleet_params(), **params).items()]
    # the node's own process (no rosrun shell in between): SIGKILL hits the JVM too
    return subprocess.Popen(args, stdout=output, stderr=subprocess.STDOUT if output else None,
                            universal_newlines=True, cwd=cwd)


def stop_mas(proc, timeout=20.0):
    if proc.poll() is None:
        proc.send_signal(signal.SIGTERM)
        try:
            proc.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            proc.kill()
            proc.wait()
    return proc.returncode


class FleetSigner(object):
    """Signs agent messages and presence as a rason_mas of the fleet does (Java's FleetAuth with
    the fleet key of ROS_HOME), as this test node: for tests whose input must get past the
    authentication (e.g. malformed content from a keyed node). Starts a JVM in the test process."""

    def __init__(self, key_file=None):
        import jpype
        from rason_bridge.fleet_auth import default_key_file
        from rason_bridge.jvm import start_jvm
        start_jvm()
        self.mas_id = rospy.get_name()  # receivers compare it with the publishing node's name
        self.incarnation = time.time_ns()
        path = key_file or default_key_file(rospkg.get_ros_home())
        keys = jpype.JClass('rason.messaging.FleetKeys').load(jpype.JClass('java.nio.file.Paths').get(path))
        self._auth = jpype.JClass('rason.messaging.FleetAuth')()
        self._auth.require(keys)
        self._auth.setIncarnation(self.incarnation)
        self._wire = jpype.JClass('rason.messaging.WireMessage')
        self._strings = jpype.JArray(jpype.JString)
        self._as_list = jpype.JClass('java.util.Arrays').asList

    def message(self, sender, receiver_mas, receiver, performative, content, msg_id='', in_reply_to=''):
        """An AgentMessage from agent ``sender`` of this node, signed (call in publishing order)."""
        s = self._auth.sign(self._wire(self.mas_id, sender, receiver_mas, receiver, performative, content, msg_id,
                                       in_reply_to))
        return AgentMessage(sender_mas=self.mas_id, sender=sender, receiver_mas=receiver_mas, receiver=receiver,
                            performative=performative, content=content, msg_id=msg_id, in_reply_to=in_reply_to,
                            incarnation=int(s.incarnation()), sequence=int(s.sequence()), stamp=int(s.stamp()),
                            key_id=str(s.keyId()), mac=bytes(s.mac()))

    def presence(self, agents, leaving=False, period=0.5, df_agents=(), df_services=()):
        """This node's presence announcing ``agents`` (and the directory registrations df_agents[i]
        provides df_services[i]), signed (call in publishing order)."""
        lists = [self._as_list(self._strings(list(x))) for x in (agents, df_agents, df_services)]
        s = self._auth.signPresence(self.mas_id, lists[0], lists[1], lists[2], period, leaving)
        return Presence(mas_id=self.mas_id, incarnation=int(s.incarnation()), agents=list(agents),
                        df_agents=list(df_agents), df_services=list(df_services), period=period,
                        leaving=leaving, sequence=int(s.sequence()), stamp=int(s.stamp()), key_id=str(s.keyId()),
                        mac=bytes(s.mac()))


def run_launch(*args, timeout=60.0):
    """(exit status, output) of ``rosrun rason run_launch rason ARGS`` (a launch file and its
    NAME:=VALUE args); one still running after timeout is interrupted as roslaunch's Ctrl-C would."""
    launch = subprocess.Popen(['rosrun', 'rason', 'run_launch', 'rason'] + list(args),
                              stdout=subprocess.PIPE, stderr=subprocess.STDOUT, universal_newlines=True)
    try:
        output, _ = launch.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        launch.send_signal(signal.SIGINT)    # roslaunch's own shutdown: no node left behind
        output, _ = launch.communicate(timeout=60)
        output += '\n(the launch did not end within %.0f s: interrupted)' % timeout
    return launch.returncode, output
