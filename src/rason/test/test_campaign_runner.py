"""The private master of campaign runs and benchmarks: free ports, the is-it-up check, and
starting and stopping it (a stand-in for roscore: no ROS needed)."""
import socket
import sys
import threading
import time
from xmlrpc.server import SimpleXMLRPCServer

import pytest

from rason_campaign import runner

# A stand-in for `roscore -p PORT`: answers getPid like a master until SIGINT.
FAKE_MASTER = '''
import os, sys
from xmlrpc.server import SimpleXMLRPCServer
server = SimpleXMLRPCServer(('127.0.0.1', int(sys.argv[1])), logRequests=False)
server.register_function(lambda caller: [1, 'pid', os.getpid()], 'getPid')
try:
    server.serve_forever()
except KeyboardInterrupt:
    pass
'''


@pytest.fixture
def listener():
    s = socket.socket()
    s.bind(('127.0.0.1', 0))
    s.listen(1)
    yield s.getsockname()[1]
    s.close()


def test_a_port_someone_listens_on_is_not_free_and_is_skipped(listener):
    assert not runner.port_free(listener)
    assert runner.pick_port(listener, span=5) != listener
    with pytest.raises(RuntimeError):
        runner.pick_port(listener, span=1)


def test_without_a_base_the_system_picks_a_free_port():
    port = runner.pick_port()
    assert runner.port_free(port)


def test_master_is_up_only_when_get_pid_answers(listener):
    server = SimpleXMLRPCServer(('127.0.0.1', 0), logRequests=False)
    server.register_function(lambda caller: [1, 'pid', 42], 'getPid')
    threading.Thread(target=server.serve_forever, daemon=True).start()
    try:
        assert runner.master_is_up('http://127.0.0.1:%d' % server.server_address[1])
    finally:
        server.shutdown()
        server.server_close()
    assert not runner.master_is_up('http://127.0.0.1:%d' % runner.pick_port())
    # listening but never answering: the timeout, not a hang
    t0 = time.monotonic()
    assert not runner.master_is_up('http://127.0.0.1:%d' % listener, timeout=0.3)
    assert time.monotonic() - t0 < 3.0


def test_private_master_starts_answers_and_stops(tmp_path):
    port = runner.pick_port()
    master = runner.PrivateMaster(str(tmp_path / 'master.log'), port,
                                  command=[sys.executable, '-c', FAKE_MASTER, str(port)])
    assert master.uri == 'http://127.0.0.1:%d' % port
    assert master.env({'A': '1'}) == {'A': '1', 'ROS_MASTER_URI': master.uri}
    with master:
        assert master.running
        assert runner.master_is_up(master.uri)
        with pytest.raises(RuntimeError, match='already runs'):
            runner.PrivateMaster(str(tmp_path / 'other.log'), port).start()
    assert not master.running
    assert not runner.master_is_up(master.uri)


def test_a_master_that_ends_at_once_is_an_error_not_a_wait(tmp_path):
    master = runner.PrivateMaster(str(tmp_path / 'master.log'), command=['false'])
    t0 = time.monotonic()
    with pytest.raises(RuntimeError, match='did not start'):
        master.start(timeout=20.0)
    assert time.monotonic() - t0 < 5.0
    assert not master.running


def test_a_run_s_jvm_options_lead_and_the_shell_s_come_last():
    uri = 'http://127.0.0.1:11999'
    env = runner.launch_env(uri, {'RASON_JVM_OPTIONS': '-XX:TieredStopAtLevel=4',
                                  'ROS_MASTER_URI': 'http://elsewhere:11311'})
    assert env['ROS_MASTER_URI'] == uri
    assert env['RASON_JVM_OPTIONS'].split() == runner.RUN_JVM_OPTIONS.split() + ['-XX:TieredStopAtLevel=4']
    assert runner.launch_env(uri, {})['RASON_JVM_OPTIONS'] == runner.RUN_JVM_OPTIONS


def test_a_run_stopped_by_ctrl_c_raises_and_leaves_no_record(tmp_path):
    # stop_all (the campaign's Ctrl-C) stops the launch under way: the run must not count as
    # made. By SIGINT, also when this runs as a shell's background job (SIGINT ignored).
    sleeper = [sys.executable, '-c', 'import time; time.sleep(60)']
    log = str(tmp_path / 'run.log')
    t0 = time.monotonic()
    def ctrl_c_once_running(proc):
        def press():
            while proc not in runner._live:     # _launch lists it right after on_start
                time.sleep(0.01)
            runner.stop_all()
        threading.Thread(target=press, daemon=True).start()

    with pytest.raises(runner.RunInterrupted):
        runner._launch(sleeper, 'http://127.0.0.1:1', log, 60.0, on_start=ctrl_c_once_running)
    assert time.monotonic() - t0 < 15     # by SIGINT, not SIGTERM after _stop's 20 s grace
    # a run that ends by itself is unaffected
    timed_out, code, _ = runner._launch([sys.executable, '-c', 'raise SystemExit(3)'], 'http://127.0.0.1:1', log, 60.0)
    assert (timed_out, code) == (False, 3)
