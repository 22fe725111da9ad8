"""Robots with brokers of their own (issue 30, the second topology): needs root (CI runs as root).

Each robot runs its own mosquitto, bridged to the fleet broker on a third host
(config/mosquitto/robot_bridge.conf), and its rason_mas processes connect to that local broker
only. Robot r1 runs two rason_mas (agents/hosts/local_r1.mas2j: a1 and d1;
local_r1_more.mas2j: c1), robot r2 one (local_r2.mas2j: b1); a1 talks with b1 across the fleet,
c1 with d1 inside r1. Then r1 is cut off for PARTITION_SECONDS:

- c1 and d1 go on talking through r1's broker: each keeps the other present and gets, before
  the heal, what the other sent during the cut;
- a1 and b1 lose each other's present/1 and get it back after the heal, and what they sent to
  each other meanwhile waits (in r1's broker for its bridge, in the fleet broker for r1's
  session) and arrives after the heal: every message of the run reaches Jason exactly once, in
  order per pair, and no send fails.
"""
import os
import subprocess
import time

import pytest

from rason_hosts import read_line

from hosts_agents import NEEDS_HOSTS_AND_WORKSPACE, run_on_hosts, check_order, check_sends, drain, report, stats

HERE = os.path.dirname(os.path.abspath(__file__))
AGENTS_DIR = os.path.join(HERE, 'agents', 'hosts')
CONFIG_DIR = os.path.join(HERE, '..', 'config', 'mosquitto')


pytestmark = NEEDS_HOSTS_AND_WORKSPACE

PORT = 1883
PARTITION_SECONDS = 8.0   # past presence_timeout (2 s): r1 and r2 see each other go
MESSAGE_TTL = 30          # ~message_ttl (s): outlasts the cut and the bridge's reconnect (<= 5 s)
#: (robot, node name, program) of each rason_mas
PROCESSES = [('r1', 'rason_mas', 'local_r1.mas2j'), ('r1', 'rason_mas_more', 'local_r1_more.mas2j'),
             ('r2', 'rason_mas', 'local_r2.mas2j')]
PEER = {'a1': 'b1', 'b1': 'a1', 'c1': 'd1', 'd1': 'c1'}
ACROSS, INSIDE = ('a1', 'b1'), ('c1', 'd1')


def _robot_broker(hosts, robot, folder):
    """The robot's own broker on its loopback, bridged to the fleet broker, its log kept in
    folder; returns once bridged."""
    broker = hosts.run_python(robot, 'rason_hosts.broker', [
        '--config', os.path.join(CONFIG_DIR, 'robot_bridge.conf'), '--listen', '127.0.0.1',
        '--port', PORT, '--fleet', '%s:%d' % (hosts.address('broker'), PORT), '--robot', robot],
        stderr=subprocess.STDOUT, text=False)
    read_line(broker, 15, ' running')
    drain(broker, os.path.join(folder, '%s_broker.log' % robot))
    state = hosts.run(robot, ['stdbuf', '-oL', 'mosquitto_sub', '-p', PORT, '-t',
                              'rason/bridge/%s/state' % robot, '-v'], stdout=subprocess.PIPE)
    read_line(state, 30, 'state 1')
    hosts.stop(state)
    return broker


def _play(hosts, log, marks, folder):
    fleet = hosts.run_python('broker', 'rason_hosts.broker', [
        '--config', os.path.join(CONFIG_DIR, 'fleet.conf'), '--listen', hosts.address('broker'),
        '--port', PORT], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=False)
    read_line(fleet, 15, ' running')
    drain(fleet, os.path.join(folder, 'fleet_broker.log'))
    envs = {}
    for robot in ('r1', 'r2'):
        _robot_broker(hosts, robot, folder)
        os.makedirs(os.path.join(folder, robot))
        envs[robot] = hosts.ros_env(dict(os.environ, ROS_LOG_DIR=os.path.join(folder, robot),
                                         PYTHONUNBUFFERED='1'))
        core = hosts.run(robot, ['roscore', '-p', '11311'], env=envs[robot],
                         stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
        read_line(core, 60, 'started core service')
        drain(core, os.path.join(folder, robot, 'roscore.out'))
    for robot, node, program in PROCESSES:
        mas = hosts.run(robot, [
            'rosrun', 'rason_bridge', 'rason_mas', os.path.join(AGENTS_DIR, program),
            '__ns:=/' + robot, '__name:=' + node, '_fleet_channel:=mqtt',
            '_mqtt_url:=tcp://127.0.0.1:%d' % PORT, '_message_ttl:=%d' % MESSAGE_TTL],
            env=envs[robot], stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
        log.follow('%s%s' % (robot, node[len('rason_mas'):]), mas)

    log.wait(lambda seen: len(seen.burst_done) == len(PEER), 180, 'every agent to end its burst')
    marks['cut'] = time.time()
    timer = hosts.partition('r1', PARTITION_SECONDS)
    log.wait(lambda seen: all(any(p[0] == a for p in seen.presence_changes(False, marks['cut']))
                              for a in ACROSS), PARTITION_SECONDS, 'a1 and b1 to see each other go')
    timer.join(PARTITION_SECONDS + 10)
    assert not hosts.link('r1')['cut']
    marks['healed'] = time.time()
    log.wait(lambda seen: all(any(p[0] == a for p in seen.presence_changes(True, marks['healed']))
                              for a in ACROSS), 30, 'a1 and b1 to see each other back')
    log.wait(lambda seen: all(seen.resumed_since(a, marks['healed']) for a in PEER), 30,
             'every agent to get a message through after the heal')
    for robot in ('r1', 'r2'):
        hosts.run(robot, ['rostopic', 'pub', '-r', '2', '/%s/jason/perception' % robot,
                          'rason_msgs/Perception', '{source: hosts_test, perception: [stop]}'],
                  env=envs[robot], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    log.wait(lambda seen: len(seen.stream_ended) == len(PEER), 60, 'every agent to end its stream')
    log.wait(lambda seen: not seen.unresolved(), MESSAGE_TTL + 10, 'every send to end')
    marks['settled'] = time.time()


@pytest.fixture(scope='module')
def local_run(tmp_path_factory):
    return run_on_hosts(tmp_path_factory, 'hosts_local_brokers', ['broker', 'r1', 'r2'], _play)


def test_every_message_arrives_once_in_order_and_no_send_fails(local_run):
    seen = local_run.seen
    keys = sorted(seen.sends)
    print('\nall sends: %s' % stats(seen, keys))
    problems = check_sends(seen, keys, True, PEER, MESSAGE_TTL) + check_order(seen, keys, PEER)
    assert not problems, report(problems)


def test_the_robot_cut_off_keeps_talking_inside_and_its_queue_flows_after_the_heal(local_run):
    seen, marks = local_run.seen, local_run.marks
    cut, healed = marks['cut'], marks['healed']
    inside_drops = [p for p in seen.presence if p[0] in INSIDE and not p[2]
                    and p[3] < marks['settled'] - 1]
    assert not inside_drops, 'c1 and d1 lost each other: %s' % inside_drops
    for sender in INSIDE:
        during = [n for n in seen.order[sender] if cut + 1 <= seen.sends[(sender, n)][1] <= healed - 1]
        assert during, '%s sent nothing during the cut' % sender
        late = [n for n in during if not any(m == n and at < healed for m, _, at in seen.got[sender])]
        assert not late, '%s -> %s: sent during the cut, not received before the heal: %s' % (
            sender, PEER[sender], late)
    for sender in ACROSS:
        during = [n for n in seen.order[sender] if cut + 1 <= seen.sends[(sender, n)][1] <= healed - 1]
        assert during, '%s sent nothing during the cut' % sender
        early = [n for n in during if any(m == n and at < healed for m, _, at in seen.got[sender])]
        assert not early, '%s -> %s crossed the cut: %s' % (sender, PEER[sender], early)
        assert all(seen.got_count[(sender, n)] == 1 for n in during), \
            '%s -> %s: what was sent during the cut did not all arrive after the heal' % (sender, PEER[sender])
    print('\ncut %.0f s; a1/b1 back %.2f s after the heal' % (PARTITION_SECONDS, max(
        min(p[3] for p in seen.presence_changes(True, healed) if p[0] == a) - healed for a in ACROSS)))
