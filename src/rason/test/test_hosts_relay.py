"""topic_relay across hosts (rason_relay): needs root (CI runs as root) and the built workspace,
skipped otherwise.

Two robots, `seer` and `seen`, each with its own ROS master in a network namespace, and a
broker on a third host behind 20 % loss each way on each robot's link and 100 ms added each
way. `seer` publishes a pose on /seer/located/seen at 10 Hz; `seen`'s relay publishes it on
its own master. A broker client without the fleet key cannot make it publish anything: junk,
a message sealed with another key and a replayed real one are each dropped with a reason.
"""
import os
import subprocess
import sys

from rason_hosts import Hosts
from rason_hosts.case_study import BROKER_PORT, FLEET_CONF, tune_broker_host
from rason_hosts.hosts import read_line

from hosts_agents import NEEDS_HOSTS_AND_WORKSPACE

pytestmark = NEEDS_HOSTS_AND_WORKSPACE

LOSS, DELAY_MS = 20, 100
TOPIC = '/seer/located/seen'
BROKER_TOPIC = 'rason/topics' + TOPIC
POSE = "{header: {stamp: now, frame_id: seer/odom}, pose: {position: {x: 1.5}, orientation: {w: 1.0}}}"


def _ros(hosts, name, argv, logs):
    env = hosts.ros_env(dict(os.environ, ROS_LOG_DIR=os.path.join(logs, name), ROS_HOME=logs))
    return hosts.run(name, argv, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT)


def _relay(hosts, name, url, key, logs, **lists):
    params = ['_%s:=%s' % (k, v) for k, v in lists.items()]
    return _ros(hosts, name, ['rosrun', 'rason', 'topic_relay', '__ns:=' + name, '_mqtt_url:=' + url,
                              '_fleet_key_file:=' + key] + params, logs)


def test_a_pose_crosses_a_lossy_slow_link_and_nothing_forged_is_published(tmp_path):
    logs = str(tmp_path)
    key, other_key = os.path.join(logs, 'fleet.key'), os.path.join(logs, 'other.key')
    for path in (key, other_key):
        subprocess.run(['rosrun', 'rason_bridge', 'fleet_key', path], check=True, stdout=subprocess.DEVNULL)
    with Hosts(['broker', 'seer', 'seen']) as hosts:
        address = hosts.address('broker')
        tune_broker_host(hosts)
        broker = hosts.run_python('broker', 'rason_hosts.broker', ['--config', FLEET_CONF, '--listen', address,
                                                                   '--port', BROKER_PORT],
                                  stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=False)
        read_line(broker, 15, ' running')
        delayed = hosts.relay('broker', (address, BROKER_PORT), DELAY_MS)
        url = 'tcp://%s:%d' % (delayed.address, delayed.port)
        for name in ('seer', 'seen'):
            read_line(_ros(hosts, name, ['roscore', '-p', '11311'], logs), 60, 'started core service')
            hosts.shape(name, loss=LOSS)
        sender = _relay(hosts, 'seer', url, key, logs, send=TOPIC)
        receiver = _relay(hosts, 'seen', url, key, logs, receive=TOPIC)
        for relay in (sender, receiver):
            read_line(relay, 30, 'connected to')
        _ros(hosts, 'seer', ['rostopic', 'pub', '-s', '-r', '10', TOPIC, 'geometry_msgs/PoseStamped', POSE], logs)

        # on the other robot's master: the poses, fresh
        echo = _ros(hosts, 'seen', ['rostopic', 'echo', '-n', '20', TOPIC + '/pose/position/x'], logs)
        received = [float(read_line(echo, 30, '.')) for _ in range(20)]
        assert received == [1.5] * 20
        delay = _ros(hosts, 'seen', ['rostopic', 'delay', '-w', '10', TOPIC], logs)
        line = read_line(delay, 30, 'average delay:')
        assert float(line.split(':')[1]) < 1.0, line

        # a broker client without the fleet key
        def publish(payload):
            done = hosts.call('broker', ['mosquitto_pub', '-h', address, '-p', BROKER_PORT, '-t', BROKER_TOPIC,
                                         '-s'], input=payload, text=False)
            assert done.returncode == 0, done.stderr

        publish(b'junk')
        read_line(receiver, 20, 'not a relayed ROS message')
        wrong = subprocess.run(
            [sys.executable, '-c',
             'import sys, time; from rason_bridge.fleet_key import read_keys; from rason_relay.envelope import seal; '
             'sys.stdout.buffer.write(seal(read_keys(sys.argv[1])[0], "seer", sys.argv[2], '
             '"geometry_msgs/PoseStamped", "x", "b", 1, time.time(), b""))', other_key, TOPIC],
            capture_output=True, check=True).stdout
        publish(wrong)
        read_line(receiver, 20, 'key files differ')
        captured = hosts.call('broker', ['mosquitto_sub', '-h', address, '-p', BROKER_PORT, '-t', BROKER_TOPIC,
                                         '-C', '1', '-N', '-W', '10'], text=False)
        assert captured.returncode == 0 and captured.stdout, captured.stderr
        publish(captured.stdout)
        read_line(receiver, 20, 'seen before or out of order')
