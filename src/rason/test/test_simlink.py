"""The sim link end to end, no root: two ROS masters on loopback (the world's, with
sim_world.launch, and a robot's, with sim_link.launch) joined only by the link's socket file;
a probe node on the robot's master (nodes/simlink_probe.py) sees the simulator's topics there
and drives the robot; the world master's graph is read over its XML-RPC API."""
import json
import os
import select
import shutil
import signal
import socket
import subprocess
import tempfile
import time

import pytest

from rason_hosts import stop_process


def _workspace_built():
    return bool(shutil.which('roslaunch')) and subprocess.run(
        ['rospack', 'find', 'rason_sim'], capture_output=True).returncode == 0


pytestmark = pytest.mark.skipif(not _workspace_built(),
                                reason='needs roslaunch and the built workspace (rason_sim)')

HERE = os.path.dirname(os.path.abspath(__file__))
PROBE = os.path.join(HERE, 'nodes', 'simlink_probe.py')
DEPTH = '/helper/camera/depth_registered/image_raw'
ACK = '/helper/robots_seen'


def _free_port():
    with socket.socket() as sock:
        sock.bind(('127.0.0.1', 0))
        return sock.getsockname()[1]


def _wait(condition, timeout, what):
    deadline = time.monotonic() + timeout
    while not condition():
        assert time.monotonic() < deadline, 'not within %g s: %s' % (timeout, what)
        time.sleep(0.05)


class Link:
    """A world launch, a robot launch and a probe; their logs in a directory of their own."""

    def __init__(self, robot, world_args):
        self.robot, self.world_args = robot, world_args
        self.dir = tempfile.mkdtemp(prefix='simlink-', dir='/tmp')
        self.world_port, self.robot_port = _free_port(), _free_port()
        self.world = self.robot_launch = self.probe = None
        self.world_starts = 0

    def env(self, port):
        return dict(os.environ, ROS_MASTER_URI='http://127.0.0.1:%d' % port)

    def launch(self, port, log, *args):
        with open(os.path.join(self.dir, log), 'ab') as out:
            return subprocess.Popen(['roslaunch', '-p', str(port), 'rason'] + list(args),
                                    stdout=out, stderr=subprocess.STDOUT, env=self.env(port),
                                    start_new_session=True)

    def log(self, name):
        try:
            with open(os.path.join(self.dir, name), errors='replace') as f:
                return f.read()
        except FileNotFoundError:
            return ''

    def start_world(self):
        self.world_starts += 1
        self.world = self.launch(self.world_port, 'world.log', 'sim_world.launch',
                                 'socket_dir:=' + self.dir, 'robots:=' + self.robot,
                                 *self.world_args)

    def start(self):
        self.start_world()
        self.robot_launch = self.launch(self.robot_port, 'robot.log', 'sim_link.launch',
                                        'robot:=' + self.robot,
                                        'socket:=%s/%s.sock' % (self.dir, self.robot))
        _wait(lambda: self.log('robot.log').count('linked to the world side') >= 1, 90,
              'the robot side linked (logs in %s)' % self.dir)
        self.probe = subprocess.Popen(['/usr/bin/python3', PROBE, self.robot],
                                      stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                                      stderr=open(os.path.join(self.dir, 'probe.log'), 'wb'),
                                      env=self.env(self.robot_port), start_new_session=True)
        assert self._answer(60) == {'ready': True}

    def ask(self, op, **args):
        """The probe's answer to op (its own waits are under 30 s)."""
        self.probe.stdin.write((json.dumps(dict(args, op=op)) + '\n').encode())
        self.probe.stdin.flush()
        return self._answer(60)

    def _answer(self, timeout):
        ready = select.select([self.probe.stdout], [], [], timeout)[0]
        assert ready, 'the probe did not answer within %g s (logs in %s)' % (timeout, self.dir)
        line = self.probe.stdout.readline()
        assert line, 'the probe ended (logs in %s)' % self.dir
        return json.loads(line)

    def world_graph(self):
        """{topic: (publishers, subscribers)} on the world's master."""
        import rosgraph
        pubs, subs, _ = rosgraph.Master('/test_simlink', master_uri='http://127.0.0.1:%d'
                                        % self.world_port).getSystemState()
        graph = {}
        for topic, nodes in pubs:
            graph.setdefault(topic, (set(), set()))[0].update(nodes)
        for topic, nodes in subs:
            graph.setdefault(topic, (set(), set()))[1].update(nodes)
        return graph

    def world_link_subscribes(self, topic):
        return '/%s/sim_link' % self.robot in self.world_graph().get(topic, ((), ()))[1]

    def world_link_publishes(self, topic):
        return '/%s/sim_link' % self.robot in self.world_graph().get(topic, ((), ()))[0]

    def stop(self):
        for proc in (self.probe, self.robot_launch, self.world):
            if proc is not None:
                stop_process(proc, 10)
        for name in ('world.log', 'robot.log', 'probe.log'):   # shown if a test failed
            print('--- %s (last lines)\n%s' % (name, '\n'.join(self.log(name).splitlines()[-40:])))
        shutil.rmtree(self.dir, ignore_errors=True)


@pytest.fixture(scope='module')
def rover():
    """The one-robot world (rover, no camera) at real time."""
    link = Link('rover', ['world:=%s/config/one_robot.yaml' % _package('rason_sim')])
    try:
        link.start()
        yield link
    finally:
        link.stop()


@pytest.fixture(scope='module')
def helper():
    """The case study's world, Helper (the camera) linked, as fast as lockstep lets it."""
    link = Link('helper', ['rate:=0', 'lockstep:=true'])
    try:
        link.start()
        yield link
    finally:
        link.stop()


def _package(name):
    return subprocess.run(['rospack', 'find', name], capture_output=True, text=True,
                          check=True).stdout.strip()


def test_clock_odometry_and_commands_cross_the_link(rover):
    clock = rover.ask('clock')
    assert clock['then'] is not None and clock['then'] > clock['first']
    odom = rover.ask('odom')
    assert odom['stamp'] is not None and odom['stamp'] > 0
    # simulated time: odometry is published just before the /clock of its time
    assert abs(odom['stamp'] - odom['clock']) <= 0.1, odom
    drive = rover.ask('drive', distance=0.1)
    assert drive['start'] is not None
    assert drive['end'] >= drive['start'] + 0.1, drive


def test_the_robot_side_relinks_when_the_world_restarts(rover):
    rover.world.send_signal(signal.SIGINT)
    rover.world.wait(30)
    _wait(lambda: 'link to the world side lost' in rover.log('robot.log'), 20,
          'the robot side reported the lost link')
    assert not os.path.exists('%s/rover.sock' % rover.dir), 'the socket file outlived the world'
    rover.start_world()
    _wait(lambda: rover.log('robot.log').count('linked to the world side') >= 2, 90,
          'the robot side linked again')
    clock = rover.ask('clock')
    assert clock['then'] is not None and clock['then'] > clock['first']
    drive = rover.ask('drive', distance=0.05)
    assert drive['end'] >= drive['start'] + 0.05, drive


def test_a_camera_image_crosses_only_while_subscribed(helper):
    assert not helper.world_link_subscribes(DEPTH)
    helper.ask('subscribe_camera')
    try:
        assert helper.ask('next_frame', wait=30)['stamp'] is not None
        assert helper.world_link_subscribes(DEPTH)
    finally:
        helper.ask('unsubscribe_camera')
    _wait(lambda: not helper.world_link_subscribes(DEPTH), 10,
          'the world side unsubscribed from the depth image')


def test_lockstep_waits_for_the_acknowledgements_sent_from_the_robot_side(helper):
    helper.ask('subscribe_camera')
    helper.ask('advertise_ack')
    try:
        _wait(lambda: helper.world_link_publishes(ACK), 10,
              'the world side advertised robots_seen')
        # acknowledged frames keep coming (frames from before the wait are taken too)
        for _ in range(20):
            stamp = helper.ask('next_frame', wait=5)['stamp']
            assert stamp is not None
            helper.ask('ack', stamp=stamp)
        stamp = helper.ask('next_frame', wait=5)['stamp']
        assert stamp is not None
        # not acknowledged: the simulator holds the next frame (it would wait 2 s)
        assert helper.ask('next_frame', wait=1.0)['stamp'] is None
        helper.ask('ack', stamp=stamp)
        after = helper.ask('next_frame', wait=1.5)['stamp']
        assert after is not None and after > stamp
        helper.ask('ack', stamp=after)
    finally:
        helper.ask('unadvertise_ack')
    _wait(lambda: not helper.world_link_publishes(ACK), 10,
          'the world side unadvertised robots_seen')
    # nobody acknowledges now, and the simulator no longer waits for it
    start = time.monotonic()
    for _ in range(10):
        assert helper.ask('next_frame', wait=3)['stamp'] is not None
    assert time.monotonic() - start < 4.0
    helper.ask('unsubscribe_camera')
