"""run_in_slots (the campaign's --jobs): values in order, at most N at once, a slot held by
one run at a time, the first error stops what has not started, Ctrl-C stops the rest."""
import threading
import time

import pytest

from rason_campaign.slots import run_in_slots


class Tracker(object):
    """Work that takes a little while and records who ran where and how many at once."""

    def __init__(self, seconds=0.02):
        self.lock = threading.Lock()
        self.running = 0
        self.most = 0
        self.slots_in_use = set()
        self.clashes = []
        self.started = []
        self.seconds = seconds

    def __call__(self, item, slot):
        with self.lock:
            if slot in self.slots_in_use:
                self.clashes.append((item, slot))
            self.slots_in_use.add(slot)
            self.running += 1
            self.most = max(self.most, self.running)
            self.started.append(item)
        time.sleep(self.seconds * (1 + item % 3))
        with self.lock:
            self.running -= 1
            self.slots_in_use.discard(slot)
        return item * 10


def test_values_come_in_the_items_order_and_done_sees_each_once():
    work = Tracker()
    seen = []
    values = run_in_slots(list(range(12)), 3, work, lambda i, item, v: seen.append((i, item, v)))
    assert values == [i * 10 for i in range(12)]
    assert sorted(seen) == [(i, i, i * 10) for i in range(12)]


def test_at_most_that_many_at_once_each_slot_held_by_one():
    work = Tracker()
    run_in_slots(list(range(12)), 3, work)
    assert work.most == 3
    assert work.clashes == []


def test_one_slot_runs_one_after_the_other_in_order():
    work = Tracker(seconds=0.001)
    run_in_slots(list(range(6)), 1, work)
    assert work.most == 1
    assert work.started == list(range(6))


def test_an_error_is_raised_and_nothing_starts_after_it():
    started = []

    def work(item, slot):
        started.append(item)
        if item == 1:
            raise RuntimeError('run 1 broke')
        time.sleep(0.05)
        return item

    with pytest.raises(RuntimeError, match='run 1 broke'):
        run_in_slots(list(range(20)), 2, work)
    assert len(started) < 20


def test_ctrl_c_calls_interrupted_and_goes_on():
    calls = []

    def work(item, slot):
        if item == 2:
            raise KeyboardInterrupt
        return item

    with pytest.raises(KeyboardInterrupt):
        run_in_slots(list(range(5)), 2, work, interrupted=lambda: calls.append('stop'))
    assert calls == ['stop']


def test_no_slots_is_an_error():
    with pytest.raises(ValueError):
        run_in_slots([1], 0, lambda item, slot: item)


class FakeRunner(object):
    """runner's interface: run() records the master port each run was given."""

    def __init__(self):
        self.lock = threading.Lock()
        self.ports_in_use = set()
        self.clashes = 0
        self.ports = []

    def run(self, spec, bags, timeout, port):
        with self.lock:
            self.clashes += port in self.ports_in_use
            self.ports_in_use.add(port)
            self.ports.append(port)
        time.sleep(0.02)
        with self.lock:
            self.ports_in_use.discard(port)
        return 'record of %s' % spec

    def stop_all(self):
        pass


def test_campaign_runs_jobs_at_once_on_port_ranges_of_their_own(capsys):
    from rason_campaign import cli
    args = cli.parse_args(['--out', 'o', '--jobs', '2', '--port', '12000'])
    fake = FakeRunner()
    results = cli.run_all(args, ['a', 'b', 'c', 'd', 'e'], 'bags', fake,
                          lambda index, spec: '[%d] %s ... ' % (index, spec),
                          lambda spec, record: (spec, record), lambda result: 'done')
    assert results == [(s, 'record of %s' % s) for s in 'abcde']
    assert set(fake.ports) == {12000, 12100} and fake.clashes == 0
    lines = sorted(capsys.readouterr().out.splitlines())
    assert lines == ['[%d] %s ... done' % (i, s) for i, s in enumerate('abcde', 1)]


def test_campaign_refuses_fewer_than_one_job(capsys):
    from rason_campaign import cli
    with pytest.raises(SystemExit):
        cli.parse_args(['--out', 'o', '--jobs', '0'])
    assert '--jobs' in capsys.readouterr().err


def test_resume_makes_only_the_runs_without_a_record(tmp_path, capsys):
    from rason_campaign import cli, runner
    bags = tmp_path / 'bags'
    bags.mkdir()
    runner.RunRecord(0, 12.0, False, 'b.bag', 'b.log').save(str(bags / 'b.run.json'))

    class Spec(object):
        def __init__(self, name):
            self.name = name

        def __str__(self):
            return self.name

    class Runner(FakeRunner):
        RunRecord = runner.RunRecord

    args = cli.parse_args(['--out', str(tmp_path), '--resume'])
    fake = Runner()
    results = cli.run_all(args, [Spec('a'), Spec('b')], str(bags), fake,
                          lambda index, spec: '', lambda spec, record: (spec.name, record), lambda r: '')
    assert results[0] == ('a', 'record of a')      # made
    assert results[1][0] == 'b' and results[1][1].to_dict() == runner.RunRecord(0, 12.0, False, 'b.bag', 'b.log').to_dict()
    assert len(fake.ports) == 1                     # b was not made again


def test_sigterm_stops_a_campaign_as_ctrl_c_does():
    import subprocess
    import sys
    code = ('import os, signal\n'
            'from rason_campaign import cli\n'
            'cli.stop_on_sigterm()\n'
            'try:\n'
            '    os.kill(os.getpid(), signal.SIGTERM)\n'
            'except KeyboardInterrupt:\n'
            '    print("interrupted")\n')
    out = subprocess.run([sys.executable, '-c', code], capture_output=True, text=True, timeout=60)
    assert out.stdout.split() == ['interrupted']
