"""topic_relay across hosts (rason_relay): needs root (CI runs as root) and the built workspace,
skipped otherwise.

Two robots, `seer` and `seen`, each with its own ROS master in a network namespace, and a
broker on a third host behind 20 % loss each way on each robot's link and 100 ms added each
way. `seer` publishes a pose on /seer/located/seen at 10 Hz; `seen`'s relay publishes it on
its own master, in order, each pose once, none older than the relay's `~max_age` (5 s). How
late they come is a speed, not checked here: on a quiet machine half the poses were 0.20 to
0.33 s late (six runs, 2026-12-07), but beside the other tests of `make test` once 1.5 s (at
20 % loss each way a retransmission is itself lost now and then, and TCP then holds back
every pose behind it; a busy CPU delays the relays and the delay relay on top).

Then, on clean links, a broker client without the fleet key cannot make it publish anything:
junk, a message sealed with another key and a replayed real one are each dropped with a
reason.
"""
import os
import subprocess
import sys

from rason_hosts import Hosts
from rason_hosts.case_study import BROKER_PORT, FLEET_CONF
from rason_hosts.hosts import read_line

from hosts_agents import NEEDS_HOSTS_AND_WORKSPACE

pytestmark = NEEDS_HOSTS_AND_WORKSPACE

LOSS, DELAY_MS = 20, 100
MAX_AGE = 5.0   # the relay's ~max_age: an older message is dropped as stale
TOPIC = '/seer/located/seen'
BROKER_TOPIC = 'rason/topics' + TOPIC
POSE = "{header: {stamp: now, frame_id: seer/odom}, pose: {position: {x: 1.5}, orientation: {w: 1.0}}}"
POSES = 40
# prints each pose it hears: x, the stamp, and how late it is
LISTENER = '''import sys, rason_rospy, rospy
from geometry_msgs.msg import PoseStamped
def heard(msg):
    late = (rospy.get_rostime() - msg.header.stamp).to_sec()
    print('pose', msg.pose.position.x, msg.header.stamp.to_sec(), late, flush=True)
rason_rospy.init_node('listener', anonymous=True)
rospy.Subscriber(sys.argv[1], PoseStamped, heard)
rospy.spin()
'''


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

        # on the other robot's master: the poses, in order and fresh
        listener = _ros(hosts, 'seen', [sys.executable, '-c', LISTENER, TOPIC], logs)
        heard = [read_line(listener, 30, 'pose ').split()[1:] for _ in range(POSES)]
        assert [float(x) for x, _, _ in heard] == [1.5] * POSES
        stamps = [float(stamp) for _, stamp, _ in heard]
        assert stamps == sorted(stamps) and len(set(stamps)) == POSES, stamps
        delays = sorted(float(late) for _, _, late in heard)
        assert delays[-1] < MAX_AGE, delays
        print('poses late: median %.2f s, most %.2f s' % (delays[POSES // 2], delays[-1]))

        # a broker client without the fleet key; the links are clean again, so that a replay
        # reaches the receiver well within max_age and is refused as a replay, not as stale
        for name in ('seer', 'seen'):
            hosts.shape(name, loss=0)

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
