"""rason_hosts pieces that need no root: rule text, addresses, broker configs, the delay relay."""
import os
import signal
import socket
import subprocess
import sys
import threading

import pytest

import rason_hosts
from rason_hosts import rules
from rason_hosts.addresses import check_bind_address, host_address
from rason_hosts.broker import render
from rason_hosts.hosts import HostsError, read_line, stop_process
from rason_hosts.probe import tcp_rtt
from rason_hosts.relay import get_relay_delay, set_relay_delay

PACKAGE_PARENT = os.path.dirname(os.path.dirname(os.path.abspath(rason_hosts.__file__)))
CONFIGS = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'config', 'mosquitto')


def test_loss_rules_drop_ip_frames_both_ways_on_the_hosts_port():
    text = rules.link_ruleset('r1', 'p3', loss_percent=20)
    assert 'table bridge rason_link_r1 {' in text
    assert 'iifname "p3" ether type { ip, ip6 } numgen random mod 100 < 20 drop' in text
    assert 'oifname "p3" ether type { ip, ip6 } numgen random mod 100 < 20 drop' in text


def test_a_cut_drops_every_frame_and_outranks_loss():
    text = rules.link_ruleset('r1', 'p0', loss_percent=20, cut=True)
    assert 'iifname "p0" drop' in text and 'oifname "p0" drop' in text
    assert 'numgen' not in text


def test_a_clear_link_has_an_empty_chain_replaced_atomically():
    text = rules.link_ruleset('robot_a', 'p1')
    assert text.index('add table bridge rason_link_robot_a') < \
        text.index('delete table bridge rason_link_robot_a')
    assert 'drop' not in text


@pytest.mark.parametrize('loss', [-1, 101])
def test_loss_outside_a_percentage_is_refused(loss):
    with pytest.raises(ValueError):
        rules.link_ruleset('r1', 'p0', loss_percent=loss)


def test_rate_arguments():
    assert rules.parse_rate_bits('1mbit') == 1000000
    assert rules.parse_rate_bits('500kbit') == 500000
    assert rules.parse_rate_bits(64000) == 64000
    args = rules.tbf_args('eth0', '8mbit')
    assert args[:6] == ['qdisc', 'replace', 'dev', 'eth0', 'root', 'tbf']
    assert args[args.index('rate') + 1] == '8000000bit'
    assert int(args[args.index('burst') + 1]) == 20000   # 20 ms of 1 MB/s
    small = rules.tbf_args('eth0', '10kbit')
    assert int(small[small.index('burst') + 1]) == 3028  # never below two frames
    with pytest.raises(ValueError):
        rules.parse_rate_bits('0mbit')


@pytest.mark.parametrize('address', ['127.0.0.1', '198.18.0.1', '198.19.255.254', '::1'])
def test_loopback_and_benchmark_addresses_may_be_bound(address):
    assert check_bind_address(address) == address


@pytest.mark.parametrize('address', ['0.0.0.0', '10.0.0.1', '172.16.0.1', '192.168.1.1',
                                     '8.8.8.8', '198.20.0.1'])
def test_other_addresses_are_refused(address):
    with pytest.raises(ValueError):
        check_bind_address(address)


def test_host_addresses_come_from_the_benchmark_range():
    assert [host_address(i) for i in range(3)] == ['198.18.0.1', '198.18.0.2', '198.18.0.3']
    with pytest.raises(ValueError):
        host_address(254)


def _config(name):
    with open(os.path.join(CONFIGS, name)) as f:
        return f.read()


def test_fleet_config_renders_a_listener_and_needs_address_and_port():
    text = render(_config('fleet.conf'), {'LISTEN': '198.18.0.1', 'PORT': 1883})
    assert 'listener 1883 198.18.0.1' in text
    assert '@' not in text.replace('# ', '')
    assert 'persistence false' in text and 'allow_anonymous true' in text
    with pytest.raises(ValueError, match='--port'):
        render(_config('fleet.conf'), {'LISTEN': '127.0.0.1'})


def test_bridge_config_bridges_the_robot_to_the_fleet_with_a_kept_session():
    text = render(_config('robot_bridge.conf'), {'LISTEN': '127.0.0.1', 'PORT': 1883,
                                                 'FLEET': '198.18.0.1:1883', 'ROBOT': 'r1'})
    lines = [line.strip() for line in text.splitlines()]
    for expected in ('connection rason-bridge-r1', 'address 198.18.0.1:1883',
                     'bridge_protocol_version mqttv311', 'cleansession false',
                     'topic rason/# both 1'):
        assert expected in lines
    with pytest.raises(ValueError, match='--fleet'):
        render(_config('robot_bridge.conf'), {'LISTEN': '127.0.0.1', 'PORT': 1, 'ROBOT': 'r1'})


class _Echo:
    """A TCP echo server on loopback, in a thread."""

    def __init__(self):
        self.sock = socket.create_server(('127.0.0.1', 0))
        self.port = self.sock.getsockname()[1]
        threading.Thread(target=self._serve, daemon=True).start()

    def _serve(self):
        while True:
            try:
                conn, _ = self.sock.accept()
            except OSError:
                return
            threading.Thread(target=self._echo, args=(conn,), daemon=True).start()

    @staticmethod
    def _echo(conn):
        with conn:
            conn.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
            while True:
                data = conn.recv(65536)
                if not data:
                    return
                conn.sendall(data)


@pytest.fixture
def echo():
    server = _Echo()
    yield server
    server.sock.close()


@pytest.fixture
def start_relay(tmp_path):
    procs = []

    def start(target_port, delay_ms):
        control = str(tmp_path / 'relay.sock')
        env = dict(os.environ, PYTHONPATH=PACKAGE_PARENT)
        proc = subprocess.Popen([sys.executable, '-m', 'rason_hosts.relay', '--listen',
                                 '127.0.0.1:0', '--target', '127.0.0.1:%d' % target_port,
                                 '--delay-ms', str(delay_ms), '--control', control],
                                stdout=subprocess.PIPE, text=True, env=env,
                                start_new_session=True)
        procs.append(proc)
        port = int(read_line(proc, 10, 'listening ').split()[2])
        return proc, port, control
    yield start
    for proc in procs:
        stop_process(proc)


def _rtts(port, count=7):
    return tcp_rtt(('127.0.0.1', port), count)


# A round trip through the relay crosses it twice: it takes at least 2*D (timers fire late,
# never early), and the median gains 2*D plus at most a loaded machine's scheduling delays.
def _assert_delayed(via_relay, direct, delay_ms):
    assert min(via_relay['rtts_ms']) >= 2 * delay_ms, via_relay
    assert via_relay['median_ms'] - direct['median_ms'] <= 2 * delay_ms + 60, (via_relay, direct)


def test_relay_adds_its_delay_each_way_and_changes_it_at_run_time(echo, start_relay):
    direct = _rtts(echo.port)
    _, port, control = start_relay(echo.port, 60)
    _assert_delayed(_rtts(port), direct, 60)
    assert set_relay_delay(control, 10) == 10
    assert get_relay_delay(control) == 10
    _assert_delayed(_rtts(port), direct, 10)


def test_relay_keeps_order_and_every_byte(echo, start_relay):
    _, port, _ = start_relay(echo.port, 5)
    payload = b''.join(b'%06d;' % i for i in range(20000))   # many chunks of odd sizes
    received = bytearray()
    with socket.create_connection(('127.0.0.1', port), timeout=10) as sock:
        def send():
            for i in range(0, len(payload), 777):
                sock.sendall(payload[i:i + 777])
            sock.shutdown(socket.SHUT_WR)
        sender = threading.Thread(target=send)
        sender.start()
        while True:
            data = sock.recv(65536)
            if not data:
                break
            received += data
        sender.join()
    assert bytes(received) == payload


def test_relay_refuses_to_listen_outside_loopback_and_the_benchmark_range(echo):
    env = dict(os.environ, PYTHONPATH=PACKAGE_PARENT)
    result = subprocess.run([sys.executable, '-m', 'rason_hosts.relay', '--listen',
                             '10.1.2.3:0', '--target', '127.0.0.1:%d' % echo.port],
                            capture_output=True, text=True, env=env, timeout=10)
    assert result.returncode != 0 and 'refusing to bind 10.1.2.3' in result.stderr


def _free_port():
    with socket.socket() as sock:
        sock.bind(('127.0.0.1', 0))
        return sock.getsockname()[1]


@pytest.mark.skipif(not os.path.exists('/usr/sbin/mosquitto'), reason='mosquitto not installed')
def test_broker_wrapper_serves_on_loopback_and_stops_on_sigint():
    port = _free_port()
    env = dict(os.environ, PYTHONPATH=PACKAGE_PARENT)
    broker = subprocess.Popen([sys.executable, '-m', 'rason_hosts.broker', '--config',
                               os.path.join(CONFIGS, 'fleet.conf'), '--port', str(port),
                               '__name:=mqtt_broker'],
                              stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                              env=env, start_new_session=True)
    try:
        read_line(broker, 10, ' running')
        sub = subprocess.Popen(['stdbuf', '-oL', 'mosquitto_sub', '-V', '5', '-p', str(port),
                                '-t', 'rason/t', '-C', '1', '-W', '20', '-d'],
                               stdout=subprocess.PIPE)
        read_line(sub, 10, 'SUBACK')
        subprocess.run(['mosquitto_pub', '-V', '5', '-p', str(port), '-t', 'rason/t', '-m',
                        'hello'], check=True, timeout=10)
        read_line(sub, 10, 'hello')
        sub.wait(10)
        broker.send_signal(signal.SIGINT)
        assert broker.wait(10) == 0
    finally:
        stop_process(broker)


def test_a_line_that_never_comes_is_reported_with_the_lines_that_came_instead():
    proc = subprocess.Popen([sys.executable, '-c', 'import sys, time\nfor i in range(12): print("line", i)\n'
                             'sys.stdout.flush(); time.sleep(30)'], stdout=subprocess.PIPE)
    try:
        assert read_line(proc, 10, 'line 1') == 'line 1'
        with pytest.raises(HostsError) as failed:
            read_line(proc, 0.5, 'never printed')
        report = str(failed.value)
        assert "no line with 'never printed'" in report
        assert 'line 11' in report and 'line 4' in report and 'line 3' not in report, report
    finally:
        stop_process(proc)


@pytest.mark.parametrize('names, run_id', [(['switch'], None), (['a', 'a'], None),
                                           (['Bad-Name'], None), (['a'], 'not-hex')])
def test_host_names_and_run_ids_are_checked_before_anything_is_made(names, run_id):
    with pytest.raises(ValueError):
        rason_hosts.Hosts(names, run_id=run_id)


def test_hosts_name_their_namespaces_after_the_run():
    hosts = rason_hosts.Hosts(['broker', 'r1'], run_id='00beef')
    assert hosts.namespaces == ['rason-00beef-switch', 'rason-00beef-broker', 'rason-00beef-r1']
    assert (hosts.address('broker'), hosts.address('r1')) == ('198.18.0.1', '198.18.0.2')
    with pytest.raises(KeyError):
        hosts.namespace('r9')


def test_a_run_is_owned_while_its_recording_process_lives(tmp_path):
    from rason_hosts.owners import owner_alive, owner_file, record_owner
    folder = str(tmp_path / 'owners')
    assert not owner_alive(folder, 'rason', 'abc123')               # never recorded
    record_owner(folder, 'rason', 'abc123')
    assert owner_alive(folder, 'rason', 'abc123')
    with open(owner_file(folder, 'rason', 'abc123'), 'w') as f:    # the pid reused by another process
        f.write('%d 1\n' % os.getpid())
    assert not owner_alive(folder, 'rason', 'abc123')
