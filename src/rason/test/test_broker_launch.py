"""broker.launch starts mosquitto on loopback and stops it with the launch (needs the workspace)."""
import os
import shutil
import signal
import socket
import subprocess

import pytest

from rason_hosts import read_line, stop_process


def _rason_found():
    if not shutil.which('roslaunch') or not shutil.which('rospack'):
        return False
    return subprocess.run(['rospack', 'find', 'rason'], capture_output=True).returncode == 0


pytestmark = [
    pytest.mark.skipif(not _rason_found(), reason='needs roslaunch and the built workspace'),
    pytest.mark.skipif(not shutil.which('mosquitto_sub')
                       or not os.path.exists('/usr/sbin/mosquitto'),
                       reason='mosquitto / mosquitto-clients not installed'),
]


def _free_port():
    with socket.socket() as sock:
        sock.bind(('127.0.0.1', 0))
        return sock.getsockname()[1]


def _accepts(port):
    with socket.socket() as sock:
        return sock.connect_ex(('127.0.0.1', port)) == 0


def test_broker_launch_serves_mqtt_and_stops_with_the_launch():
    master, port = _free_port(), _free_port()
    env = dict(os.environ, ROS_MASTER_URI='http://127.0.0.1:%d' % master)
    launch = subprocess.Popen(['roslaunch', '-p', str(master), 'rason', 'broker.launch',
                               'port:=%d' % port],
                              stdout=subprocess.PIPE, stderr=subprocess.STDOUT, env=env,
                              start_new_session=True)
    try:
        read_line(launch, 60, ' running')
        sub = subprocess.Popen(['stdbuf', '-oL', 'mosquitto_sub', '-V', '5', '-p', str(port),
                                '-t', 'rason/launch', '-C', '1', '-W', '30', '-d'],
                               stdout=subprocess.PIPE)
        try:
            read_line(sub, 10, 'SUBACK')
            subprocess.run(['mosquitto_pub', '-V', '5', '-p', str(port), '-t', 'rason/launch',
                            '-m', 'from-launch'], check=True, timeout=10)
            read_line(sub, 10, 'from-launch')
        finally:
            stop_process(sub)
        launch.send_signal(signal.SIGINT)
        assert launch.wait(60) == 0
        assert not _accepts(port)
    finally:
        stop_process(launch)
