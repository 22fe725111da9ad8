"""The case study with each robot on a host of its own (issue 31): a broker host, a world host
running the simulator, and Faulty's and Helper's hosts, each with its own ROS master, joined to
the world by the sim link's Unix sockets and to each other only by MQTT over shaped links.

CaseStudyOnHosts(hosts, folder, ...).play() starts everything, waits for the diagnosis (and,
with recovery, the mission's end), optionally cuts Helper's link for a while once its search
has begun, and returns an Outcome: what Faulty diagnosed, the mission, both robots' true poses
(read on the world's master) and every line the processes printed, stamped with the wall
clock. No rospy: the ROS side is roslaunch and rostopic inside the hosts.
"""
import math
import os
import re
import shutil
import subprocess
import tempfile
import threading
import time

from .hosts import HostsError, read_line

HOST_NAMES = ['broker', 'world', 'faulty', 'helper']
ROBOTS = ('faulty', 'helper')
BROKER_PORT = 1883
CASE_STUDY_FAULTY_YAW = -1.5708   # faulty_helper.launch's faulty_yaw
MISSION_LENGTH = 1.0      # m ahead of Faulty's start: the thesis's mission
DIAGNOSIS = re.compile(r'\[faulty\] Diagnosis: (\w+) \((.*)\)')
MISSION = re.compile(r'\[faulty\] Mission completed: (\w+) by \[?([\w, ]*)\]? \(recovery (\w+)\)')
#: Helper's search for Faulty has begun (thesis Listing A.2, findRobot).
SEARCH = re.compile(r'\[helper\] (Finding|Found) faulty')
#: Faulty's first move: where a cut is timed from when no search comes (no fault).
MOVING = re.compile(r'\[faulty\] Moving to Destination')


def cut_anchor(fault):
    """What a scenario's cut is timed from: Helper's search, or with no fault (Helper never
    searches) Faulty's first move; either way the diagnosis too, which ends the wait (a
    diagnosis given before the search: nothing left to cut)."""
    first = MOVING if fault == 'none' else SEARCH
    return re.compile('%s|%s' % (first.pattern, DIAGNOSIS.pattern))
FLEET_CONF = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', 'config',
                          'mosquitto', 'fleet.conf')


class Transcript:
    """Every line the scenario's processes print, (wall time, source, text), in arrival order,
    read by a thread per process so that no pipe fills; waits for a line matching a pattern."""

    def __init__(self, echo=None):
        self._lines = []
        self._changed = threading.Condition()
        self._echo = echo    # called with (source, text) of each line as it comes

    def follow(self, source, proc, path=None):
        thread = threading.Thread(target=self._read, args=(source, proc, path), daemon=True)
        thread.start()

    def _read(self, source, proc, path):
        sink = open(path, 'w') if path else None
        try:
            for raw in iter(proc.stdout.readline, b''):
                text = raw.decode(errors='replace').rstrip('\n')
                if sink:
                    sink.write(text + '\n')
                    sink.flush()
                with self._changed:
                    self._lines.append((time.time(), source, text))
                    self._changed.notify_all()
                if self._echo:
                    self._echo(source, text)
        finally:
            if sink:
                sink.close()

    def lines(self, pattern=None, since=0.0):
        with self._changed:
            lines = list(self._lines)
        return [line for line in lines
                if line[0] >= since and (pattern is None or pattern.search(line[2]))]

    def first(self, pattern, since=0.0):
        found = self.lines(pattern, since)
        return found[0] if found else None

    def wait(self, pattern, timeout, what, since=0.0):
        """The first line matching pattern (since a wall time), waiting at most timeout s."""
        deadline = time.monotonic() + timeout
        with self._changed:
            while True:
                for line in self._lines:
                    if line[0] >= since and pattern.search(line[2]):
                        return line
                left = deadline - time.monotonic()
                if left <= 0:
                    raise HostsError('waited %g s for %s in vain; last lines:\n%s'
                                     % (timeout, what, self.tail()))
                self._changed.wait(min(left, 1.0))

    def tail(self, count=30):
        return '\n'.join('%s: %s' % (source, text) for _, source, text in self._lines[-count:])


def planar(x, y, qz, qw):
    """(x, y, yaw) of a planar pose given by its position and its quaternion's z, w."""
    return x, y, math.atan2(2.0 * qw * qz, 1.0 - 2.0 * qz * qz)


def true_poses(csv_lines):
    """[(wall, x, y, yaw)] from (wall time, line) pairs of ``rostopic echo -p`` on a
    geometry_msgs/PoseStamped topic (its first line names the columns)."""
    poses, columns = [], None
    for wall, line in csv_lines:
        fields = line.split(',')
        if line.startswith('%time'):
            columns = dict((name, i) for i, name in enumerate(fields))
            continue
        if columns is None or len(fields) != len(columns):
            continue
        value = lambda name: float(fields[columns['field.pose.' + name]])  # noqa: E731
        poses.append((wall,) + planar(value('position.x'), value('position.y'),
                                      value('orientation.z'), value('orientation.w')))
    return poses


def judge_mission(poses, completed_by=None):
    """How Faulty's own mission went by the true poses: (closest to the goal of a robot that
    completed it, Faulty's distance from its start at the end), the goal MISSION_LENGTH ahead
    of Faulty's first pose. poses: {robot: [(wall, x, y, yaw)]}; completed_by: the robots the
    mission's line names (default Faulty). A mission delegated to another robot brings Faulty
    back to nothing: the second value is then None."""
    by = completed_by or ['faulty']
    own = poses.get('faulty') or []
    if not own:
        return None, None
    _, x0, y0, yaw0 = own[0]
    gx, gy = x0 + MISSION_LENGTH * math.cos(yaw0), y0 + MISSION_LENGTH * math.sin(yaw0)
    distances = [math.hypot(x - gx, y - gy) for robot in by for _, x, y, _ in poses.get(robot) or []]
    closest = min(distances) if distances else None
    back = math.hypot(own[-1][1] - x0, own[-1][2] - y0) if 'faulty' in by else None
    return closest, back


class Outcome:
    """What one run on hosts gave: the diagnosis (component, evidence), the mission (completed,
    by, recovery) or None, Faulty's and Helper's true poses, the transcript and the phases' wall
    times."""

    def __init__(self, diagnosis, mission, poses, transcript, marks, helper_poses=None):
        self.diagnosis, self.mission, self.poses = diagnosis, mission, poses
        self.helper_poses = helper_poses or []
        self.transcript, self.marks = transcript, marks

    def mission_judged(self):
        """(closest to the goal, Faulty back at its start or None): judge_mission of the robots
        the mission's line says completed it."""
        by = [r.strip() for r in self.mission[1].split(',') if r.strip()] if self.mission else None
        return judge_mission({'faulty': self.poses, 'helper': self.helper_poses}, by)


class CaseStudyOnHosts:
    """One case-study run on Hosts(HOST_NAMES): see the module's docstring.

    loss: % of frames lost each way on each robot's link; delay_ms: added each way to each
    robot's connection to the broker (a relay on the broker's host); partition: seconds
    Helper's link is cut partition_after s after its search began (None: no cut); rate: the simulator's
    real-time factor (0: as fast as lockstep allows)."""

    def __init__(self, hosts, folder, fault='both_actuators', recovery=False, loss=0, delay_ms=0,
                 partition=None, partition_after=0.0, rate=0, seed=1, timeout=240.0, echo=None):
        self.hosts, self.folder = hosts, os.path.abspath(folder)   # the launches run elsewhere
        self.fault, self.recovery, self.loss, self.delay_ms = fault, recovery, loss, delay_ms
        self.partition_seconds, self.partition_after = partition, partition_after
        self.rate, self.seed = rate, seed
        self.timeout = timeout
        self.transcript = Transcript(echo)
        self.marks = {}
        self.diagnosis = None   # Faulty's (component, evidence) once given, also when the run fails after it
        self._envs = {}

    def play(self):
        self.marks['start'] = time.time()
        url = self._start_broker()
        for name in ('world',) + ROBOTS:
            self._start_master(name)
        # the one key every robot of the fleet shares (copied to each robot in a real fleet)
        key = os.path.join(self.folder, 'fleet.key')
        subprocess.run(['rosrun', 'rason_bridge', 'fleet_key', key], check=True,
                       stdout=subprocess.DEVNULL)
        # a short path of its own: a Unix socket's path has at most 107 bytes
        sockets = tempfile.mkdtemp(prefix='rason_sim_link_')
        try:
            return self._play(url, key, sockets)
        finally:
            shutil.rmtree(sockets, ignore_errors=True)

    def _play(self, url, key, sockets):
        # the case study's world: faulty_helper.launch's poses (Faulty facing away from Helper)
        self._launch('world', ['sim_world.launch', 'rate:=%s' % self.rate, 'seed:=%d' % self.seed,
                               'faulty_yaw:=%s' % CASE_STUDY_FAULTY_YAW, 'socket_dir:=%s' % sockets])
        for robot in ROBOTS:
            poses = self.hosts.run('world', ['rostopic', 'echo', '-p', '/%s/true_pose' % robot],
                                   env=self._envs['world'], stdout=subprocess.PIPE,
                                   stderr=subprocess.STDOUT)
            self.transcript.follow('pose/' + robot, poses,
                                   os.path.join(self.folder, 'world', 'true_pose_%s.csv' % robot))
        for robot in ROBOTS:
            self.hosts.shape(robot, loss=self.loss)
            args = ['robot_host.launch', 'robot:=%s' % robot, 'mqtt_url:=%s' % url,
                    'sim_socket:=%s' % os.path.join(sockets, robot + '.sock'),
                    'fleet_key_file:=%s' % key, 'recovery:=%s' % str(self.recovery).lower(),
                    'end_with_agents:=false']
            if robot == 'faulty':
                args.append('fault:=%s' % self.fault)
            self._launch(robot, args)
        self.marks['launched'] = time.time()
        cut = None
        if self.partition_seconds:
            anchor = self.transcript.wait(cut_anchor(self.fault), self.timeout, "Helper's search")
            if not DIAGNOSIS.search(anchor[2]):
                if self.partition_after:
                    time.sleep(self.partition_after)    # the scenario's cut comes that long into the search
                self.marks['cut'] = time.time()
                cut = self.hosts.partition('helper', self.partition_seconds)
                self.marks['search'] = anchor[0]
        line = self.transcript.wait(DIAGNOSIS, self.timeout, "Faulty's diagnosis")
        self.marks['diagnosis'] = line[0]
        diagnosis = self.diagnosis = DIAGNOSIS.search(line[2]).groups()
        mission = None
        if self.recovery:
            line = self.transcript.wait(MISSION, self.timeout, "the mission's end")
            self.marks['mission'] = line[0]
            mission = MISSION.search(line[2]).groups()
        if cut is not None:
            cut.join(self.partition_seconds + 10)
        self.marks['end'] = time.time()
        return Outcome(diagnosis, mission, self.true_poses('faulty'), self.transcript, self.marks,
                       self.true_poses('helper'))

    def true_poses(self, robot):
        """[(wall, x, y, yaw)] of robot's true poses so far (read on the world's master)."""
        return true_poses((wall, text) for wall, source, text in self.transcript.lines()
                          if source == 'pose/' + robot)

    def _start_broker(self):
        address = self.hosts.address('broker')
        broker = self.hosts.run_python('broker', 'rason_hosts.broker', [
            '--config', FLEET_CONF, '--listen', address, '--port', BROKER_PORT],
            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=False)
        read_line(broker, 15, ' running')
        self.transcript.follow('broker', broker, os.path.join(self.folder, 'broker.log'))
        if not self.delay_ms:
            return 'tcp://%s:%d' % (address, BROKER_PORT)
        # on the broker's host: each robot's connection crosses its own lossy link to reach it
        relay = self.hosts.relay('broker', (address, BROKER_PORT), self.delay_ms)
        return 'tcp://%s:%d' % (relay.address, relay.port)

    def _start_master(self, name):
        logs = os.path.join(self.folder, name)
        os.makedirs(logs, exist_ok=True)
        self._envs[name] = self.hosts.ros_env(dict(os.environ, ROS_LOG_DIR=logs, PYTHONUNBUFFERED='1'))
        core = self.hosts.run(name, ['roscore', '-p', '11311'], env=self._envs[name],
                              stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
        read_line(core, 60, 'started core service')
        self.transcript.follow(name + '/roscore', core, os.path.join(logs, 'roscore.out'))

    def _launch(self, name, args):
        proc = self.hosts.run(name, ['roslaunch', 'rason'] + args, env=self._envs[name],
                              stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
        self.transcript.follow(name, proc, os.path.join(self.folder, name, 'launch.out'))
        return proc
