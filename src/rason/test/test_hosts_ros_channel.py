"""The ROS fleet channel on hosts of their own (issue 30, item 6): needs root, skipped otherwise.

Two robots, r1 and r2, each in a network namespace, share ONE ROS master, which runs on r1
(where a user without a third machine would put it): r2's nodes reach it, and r1's nodes,
across r2's link. Both rason_mas keep the default ``~fleet_channel: ros``. Agents a1, a2 on r1
and b1, b2 on r2 (agents/hosts/r1_ros.mas2j, r2_ros.mas2j, peer.asl) each send their peer a
message every 0.3 s (tell, achieve, askOne in turn), each from an intention of its own that
waits for the delivery receipt. Each robot's link loses frames in each direction. One run
(the module fixture, 60-90 s) plays two phases:

  (loss) 10 % loss for LOSS_SECONDS: every send ends, every message arrives at most once, in
         order, and one that does not arrived had its send fail: refused before it was published
         (receiver_not_found, while the peer was dropped), or still on a connection stalled into
         the cut, which is reset after the heal; a send may fail receiver_departed or undelivered
         although its message arrived (a receipt still on its way); present/1 is never lost (pulses);
  (cut)  no loss (as in the MQTT acceptance; RASON_ROS_CUT_LOSS=10 to measure with loss), r2
         cut off for 5 s: every send since the end of (loss) is received or failed with a
         documented reason, never silently lost, and every agent gets a message of its peer
         sent after the heal within 5 s (a publisher resets a connection stuck in TCP's
         backoff once it hears its peer again, and the subscriber makes a new one).

There is no delay here: the delay relay of rason_hosts relays one TCP port, and ROS opens a
connection per topic, publisher and subscriber on ports it picks. The agents' output is read
with the acceptance tests' parser (hosts_agents.FleetLog).
"""
import os
import subprocess
import time

import pytest

from rason_hosts import read_line
from hosts_agents import ALLOWED_FAILURES, NEEDS_HOSTS_AND_WORKSPACE, drain, run_on_hosts

HERE = os.path.dirname(os.path.abspath(__file__))
AGENTS_DIR = os.path.join(HERE, 'agents', 'hosts')

pytestmark = NEEDS_HOSTS_AND_WORKSPACE

MASTER_HOST = 'r1'
MASTER_PORT = 11311
LOSS = 10                 # % of frames lost in each direction of each robot's link
CUT_LOSS = int(os.environ.get('RASON_ROS_CUT_LOSS', '0'))   # % during and after the cut
LOSS_SECONDS = float(os.environ.get('RASON_ROS_LOSS_SECONDS', '40'))
PARTITION_SECONDS = 5.0
RESUME_LIMIT = 5.0        # s from the heal to the first message sent after it arriving (the goal)
RESUME_WAIT = 45.0        # s the run waits for that (the report says how long it took)
MESSAGE_TTL = 15
IN_FLIGHT = 3.0           # sends this long before a phase's end may still be on their way
ROBOTS = {'r1': ['a1', 'a2'], 'r2': ['b1', 'b2']}
PEER = {'a1': 'b1', 'a2': 'b2', 'b1': 'a1', 'b2': 'a2'}
AGENTS = sorted(PEER)


def _env(hosts, robot, folder):
    env = dict(os.environ, ROS_LOG_DIR=os.path.join(folder, robot), PYTHONUNBUFFERED='1',
               ROS_MASTER_URI='http://%s:%d' % (hosts.address(MASTER_HOST), MASTER_PORT),
               ROS_IP=hosts.address(robot))
    env.pop('ROS_HOSTNAME', None)
    return env


@pytest.fixture(scope='module')
def ros_run(tmp_path_factory):
    return run_on_hosts(tmp_path_factory, 'hosts_ros_channel', list(ROBOTS), _play)


def _play(hosts, log, marks, folder):
    envs = {}
    for robot in ROBOTS:
        os.makedirs(os.path.join(folder, robot))
        envs[robot] = _env(hosts, robot, folder)
    core = hosts.run(MASTER_HOST, ['roscore', '-p', MASTER_PORT], env=envs[MASTER_HOST],
                     stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
    read_line(core, 60, 'started core service')
    drain(core, os.path.join(folder, 'roscore.out'))
    masses = []
    for robot in ROBOTS:
        mas = hosts.run(robot, [
            'rosrun', 'rason_bridge', 'rason_mas', os.path.join(AGENTS_DIR, robot + '_ros.mas2j'),
            '__ns:=/' + robot, '_await_robots:=1', '_await_timeout:=120', '_message_ttl:=%d' % MESSAGE_TTL],
            env=envs[robot], stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
        log.follow(robot, mas)
        masses.append(mas)
    marks['launched'] = time.time()
    log.wait(lambda seen: len(seen.presence_changes(True, 0)) >= len(AGENTS), 90,
             'every agent to see its peer')
    marks['met'] = time.time()

    for robot in ROBOTS:
        hosts.shape(robot, loss=LOSS)
    marks['loss_start'] = time.time()
    log.watch(lambda seen: False, LOSS_SECONDS)
    marks['loss_end'] = time.time()

    # (cut) as in the MQTT acceptance: the loss goes, then r2 is cut off
    for robot in ROBOTS:
        hosts.shape(robot, loss=CUT_LOSS)
    marks['cut'] = time.time()
    timer = hosts.partition('r2', PARTITION_SECONDS)
    timer.join(PARTITION_SECONDS + 10)
    assert not hosts.link('r2')['cut']
    marks['healed'] = time.time()
    # not asserted here: the test reads how long it took
    log.watch(lambda seen: all(seen.resumed_since(a, marks['healed']) for a in AGENTS), RESUME_WAIT)
    marks['resumed'] = time.time()

    for robot in ROBOTS:
        hosts.run(robot, ['rostopic', 'pub', '-r', '2', '/%s/jason/perception' % robot,
                          'rason_msgs/Perception', '{source: hosts_test, perception: [stop]}'],
                  env=envs[robot], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    log.watch(lambda seen: len(seen.stream_ended) == len(AGENTS), MESSAGE_TTL + 15)
    marks['stopped'] = time.time()
    log.watch(lambda seen: not seen.unresolved(), MESSAGE_TTL + 5)
    marks['settled'] = time.time()
    for mas in masses:
        hosts.stop(mas, timeout=15)


# ---- checks ------------------------------------------------------------------------------

def _arrivals(seen):
    arrival = {}
    for sender, lines in seen.got.items():
        for n, _, at in lines:
            arrival.setdefault((sender, n), at)
    return arrival


def _problems(seen, keys, must_deliver):
    """Each of keys received at most once, in order, and ended in the sender; must_deliver:
    received and not failed; otherwise received or failed with an allowed reason."""
    problems = []
    for key in sorted(keys):
        kind, sent_at = seen.sends[key]
        what = '%s -> %s #%d (%s, sent %.3f)' % (key[0], PEER[key[0]], key[1], kind, sent_at)
        received, failures = seen.got_count[key], seen.failures(key)
        if received > 1:
            problems.append('%s received %d times' % (what, received))
        if not seen.outcomes.get(key):
            problems.append('%s never ended in the sender' % what)
        if must_deliver and (received == 0 or failures):
            problems.append('%s received %d times, failed %s' % (what, received, failures))
        if not must_deliver and kind != 'ask' and received == 0 and not failures:
            problems.append('%s silently lost: neither received nor failed' % what)
        problems += ['%s failed with %s' % (what, f) for f in failures if f not in ALLOWED_FAILURES]
    wanted = set(keys)
    for sender in AGENTS:
        numbers = [n for n, _, _ in seen.got[sender] if (sender, n) in wanted]
        problems += ['%s: #%d received after #%d' % (sender, b, a) for a, b in zip(numbers, numbers[1:]) if b <= a]
    return problems


def _timed_out(seen, key):
    return seen.sends[key][0] == 'ask' and ('answer', 'timeout') in seen.outcomes.get(key, ())


def _stats(seen, keys):
    received = sum(1 for k in keys if seen.got_count[k])
    failed = {}
    for k in keys:
        for f in seen.failures(k):
            failed[f] = failed.get(f, 0) + 1
    return 'sent %d, received %d, failed %s' % (len(keys), received, failed or 0)


def test_10_percent_loss_never_drops_presence_nor_a_message_silently(ros_run):
    seen, marks = ros_run.seen, ros_run.marks
    assert marks['loss_end'] - marks['loss_start'] >= LOSS_SECONDS - 0.5, 'a robot ended during the loss'
    drops = [p for p in seen.presence if not p[2] and marks['met'] <= p[3] <= marks['cut']]
    sent = [k for k, (_, at) in seen.sends.items() if marks['loss_start'] <= at < marks['loss_end'] - IN_FLIGHT]
    print('\n(loss) %.1f s at %d %% loss: %s; presence drops %d' % (
        marks['loss_end'] - marks['loss_start'], LOSS, _stats(seen, sent), len(drops)))
    # A presence drop (under this loss, or the cut's own for receipts still on their way) fails
    # what waits for the peer's receipts (receiver_departed), and a receipt later than
    # message_ttl fails its send (undelivered), though those messages arrive. A message may be
    # missing only if its send failed: refused before it was published (receiver_not_found), or
    # still unacknowledged on a connection stalled into the cut, which the repair resets after
    # the heal (docs/guides/fleet-channel.md, the ROS channel across hosts).
    problems = _problems(seen, sent, must_deliver=False)
    # an ask whose answer timed out ended visibly too: its asker got timeout, as the
    # semantics table says an ask may end (a connection stalled by the loss holds asks too)
    problems += ['%s -> %s #%d never received and never failed' % (k[0], PEER[k[0]], k[1]) for k in sorted(sent)
                 if seen.got_count[k] == 0 and not seen.failures(k) and not _timed_out(seen, k)]
    missing = [k for k in sent if seen.got_count[k] == 0 and 'receiver_not_found' not in seen.failures(k)]
    print('(loss) failed and never received (reset after the heal): %d' % len(missing))
    assert not problems, '\n'.join(problems[:40])
    assert not drops, 'present/1 dropped: %s' % [
        '%s lost %s at +%.2f s' % (a, peer, t - marks['loss_start']) for a, peer, _, t in drops]


def test_messages_flow_again_within_5_s_of_the_heal_and_none_is_lost_silently(ros_run):
    seen, marks = ros_run.seen, ros_run.marks
    heal = marks['healed']
    arrival = _arrivals(seen)
    resumed = {}
    for sender in AGENTS:
        after = [arrival[(sender, n)] for n in seen.order[sender]
                 if seen.sends[(sender, n)][1] >= heal and (sender, n) in arrival]
        resumed[sender] = min(after) - heal if after else None
    back = {a: min([t for ag, _, present, t in seen.presence if ag == a and present and t >= marks['cut']],
                   default=heal - 1) - heal for a in AGENTS}
    rest = [k for k, (_, at) in seen.sends.items() if at >= marks['loss_end'] - IN_FLIGHT]
    during = [k for k in rest if marks['cut'] <= seen.sends[k][1] <= heal]
    print('\n(cut) %g s partition of r2 at %d %% loss: first message sent after the heal arrived '
          '%s s after it; present/1 back %s s after it; sends during the cut: %s; since (loss): %s; '
          'unresolved %d' % (PARTITION_SECONDS, CUT_LOSS, _fmt(resumed), _fmt(back), _stats(seen, during),
                             _stats(seen, rest), len(seen.unresolved())))
    problems = _problems(seen, rest, must_deliver=False)
    assert not problems, '\n'.join(problems[:40])
    never = sorted(a for a, r in resumed.items() if r is None or r > RESUME_WAIT)
    assert not never, 'no message of %s sent after the heal arrived within %g s' % (never, RESUME_WAIT)
    late = {a: round(r, 2) for a, r in resumed.items() if r > RESUME_LIMIT}
    assert not late, 'messages did not flow again within %g s of the heal: %s' % (RESUME_LIMIT, late)


def _fmt(values):
    return ', '.join('%s %s' % (k, 'never' if v is None else '%.2f' % v) for k, v in sorted(values.items()))
