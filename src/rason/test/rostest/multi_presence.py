#!/usr/bin/python3
"""Presence: a robot joining is noticed, one killed with SIGKILL is noticed within the
configured timeout while the survivor keeps running, an ask waiting for it ends with a
reason, a send to it fails with a reason, it rejoins when restarted, and one that stops
cleanly says so at once."""
import os
import signal
import sys
import threading
import time
import unittest

import rason_rospy

import rospy
import rostest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), 'nodes'))
from fleet_wire import MQTT, fleet_channel, fleet_tap  # noqa: E402
from rason_testing import MULTI_AGENTS, LogWatcher, Robot, run, start_mas, stop_mas, wait_for  # noqa: E402

TIMEOUT = 1.5          # presence_timeout of every process in this test
PARAMS = dict(presence_period=0.3, presence_timeout=TIMEOUT)
MESSAGE_TTL = 3.0  # alice's ~message_ttl in multi_presence.test
SLACK = 1.5            # rosout, a busy 2-core machine


class TestPresence(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        rason_rospy.init_node('test_multi_presence')
        cls.log = LogWatcher()
        cls.alice = Robot('robot1')
        cls.bob = Robot('robot2')
        cls.carol = Robot('robot3')
        cls.alice.wait_connected()
        assert cls.log.wait_ready()
        cls.heard = {}  # mas_id -> monotonic time of its first announcement
        cls._lock = threading.Lock()
        cls.tap = fleet_tap(on_presence=cls._on_presence)  # hears the announcements on the fleet channel
        assert cls.tap.wait_ready(1), 'not connected to the fleet channel'
        cls.procs = {}  # namespace -> the last rason_mas this test started there

    @classmethod
    def tearDownClass(cls):
        for p in cls.procs.values():
            stop_mas(p)

    @classmethod
    def _on_presence(cls, msg):
        with cls._lock:
            cls.heard.setdefault(msg.mas_id, time.monotonic())

    # Each test brings the robots to the state it needs with these helpers, so it does not
    # depend on what an earlier test left running.

    def running(self, robot):
        """The robot's rason_mas if this test started it and it still runs, else None."""
        proc = self.procs.get(robot.ns)
        return proc if proc is not None and proc.poll() is None else None

    def count(self, line):
        return len(self.log.lines(line))

    def start(self, robot, name):
        with self._lock:
            self.heard.pop(robot.mas, None)
        proc = start_mas(robot.ns, os.path.join(MULTI_AGENTS, name + '.mas2j'), **PARAMS)
        self.procs[robot.ns] = proc
        wait_for(lambda: robot.mas in self.heard or proc.poll() is not None, 60,
                 '%s to announce itself' % robot.mas, interval=0.05)
        self.assertIsNone(proc.poll(), '%s exited' % robot.mas)
        robot.wait_connected()
        self.assertTrue(self.log.wait_ready())
        return proc

    def joined(self, robot, name):
        """The robot's rason_mas, running and present for alice: started when it is not."""
        proc = self.running(robot)
        if proc is None:
            before = self.count(r'^\[alice\] present %s$' % name)
            proc = self.start(robot, name)
            self.expect(r'^\[alice\] present %s$' % name, timeout=TIMEOUT + SLACK, count=before + 1)
        return proc

    def away(self, robot, name):
        """The robot's rason_mas stopped, if this test class started it and it still runs."""
        if self.running(robot):
            self.stop(robot, name)

    def kill(self, robot, name):
        """SIGKILL the robot's rason_mas; returns when it was killed and when alice saw it absent."""
        proc = self.running(robot)
        before = self.count(r'^\[alice\] absent %s$' % name)
        killed = time.monotonic()
        proc.send_signal(signal.SIGKILL)
        proc.wait()
        return killed, self.expect(r'^\[alice\] absent %s$' % name, timeout=TIMEOUT + SLACK, count=before + 1)

    def stop(self, robot, name):
        """Stop the robot's rason_mas cleanly; returns when it was stopped and when alice saw it absent."""
        proc = self.running(robot)
        left = r'presence: %s left: announced it is leaving' % robot.mas
        before, left_before = self.count(r'^\[alice\] absent %s$' % name), self.count(left)
        stopped = time.monotonic()
        self.assertEqual(stop_mas(proc), 0)
        self.expect(left, count=left_before + 1)
        return stopped, self.expect(r'^\[alice\] absent %s$' % name, count=before + 1)

    def expect(self, line, timeout=10.0, count=1):
        found = self.log.wait_for(line, timeout=timeout, count=count)
        self.assertTrue(found, 'never saw %r (%d times)' % (line, count))
        return found[count - 1][0]

    def test_a_join_is_noticed_and_messages_flow(self):
        self.away(self.carol, 'carol')
        self.away(self.bob, 'bob')  # a join needs bob away first
        before = self.count(r'^\[alice\] present bob$')
        self.start(self.bob, 'bob')
        seen = self.expect(r'^\[alice\] present bob$', timeout=TIMEOUT + SLACK, count=before + 1)
        print('join: alice perceived present(bob) %.2f s after bob\'s first announcement'
              % (seen - self.heard[self.bob.mas]))
        self.assertLess(seen - self.heard[self.bob.mas], TIMEOUT + SLACK)
        # and bob notices alice, who was there first, just as fast
        wait_for(lambda: run(self.log, self.bob, 'bob', 'names', r'names .*') == 'names [alice,bob]',
                 TIMEOUT + SLACK, 'bob to see alice', interval=0.1)
        run(self.log, self.alice, 'alice', 'send(bob, tell, hello(1))', 'sent')
        self.expect(r'^\[bob\] told hello\(1\) by alice$')

    def test_a_sigkill_is_noticed_and_the_survivor_keeps_running(self):
        self.away(self.carol, 'carol')
        self.joined(self.bob, 'bob')
        slow = r'^\[bob\] slow answer for alice$'
        before = self.count(slow)
        n = self.alice.command('ask(bob, askOne, slow)')
        self.expect(slow, count=before + 1)
        killed, absent = self.kill(self.bob, 'bob')
        # over MQTT bob's broker session would keep the ask for him until alice's message_ttl
        # (3 s): a robot whose connection ends may be one whose link stalled, and come back
        owed = TIMEOUT + (MESSAGE_TTL if fleet_channel() == MQTT else 0)
        ended = self.expect(r'^\[alice\] %d failed receiver_departed: bob left before answering$' % n,
                            timeout=owed + SLACK)
        print('SIGKILL: absent(bob) after %.2f s, the pending askOne failed after %.2f s (timeout %.1f s)'
              % (absent - killed, ended - killed, TIMEOUT))
        self.assertLess(absent - killed, TIMEOUT + SLACK)
        self.assertLess(ended - killed, owed + SLACK)
        out = run(self.log, self.alice, 'alice', 'send(bob, tell, hello(2))', r'failed .*')
        self.assertIn('failed receiver_not_found', out)
        self.assertIn("agent 'bob' has left", out)
        self.assertEqual(run(self.log, self.alice, 'alice', 'names', r'names .*'), 'names [alice]')

    def test_a_restarted_robot_rejoins(self):
        self.away(self.carol, 'carol')
        # bob has been there and was killed
        self.joined(self.bob, 'bob')
        self.kill(self.bob, 'bob')
        before = self.count(r'^\[alice\] present bob$')
        self.start(self.bob, 'bob')
        self.expect(r'^\[alice\] present bob$', timeout=TIMEOUT + SLACK, count=before + 1)
        self.assertEqual(run(self.log, self.alice, 'alice', 'names', r'names .*'), 'names [alice,bob]')
        run(self.log, self.alice, 'alice', 'send(bob, tell, hello(3))', 'sent')
        self.expect(r'^\[bob\] told hello\(3\) by alice$')
        self.assertEqual(run(self.log, self.bob, 'bob', 'ask(alice, askOne, secret)', r'answer .*'),
                         'answer secret(alice_secret)[source(alice)]')

    def test_a_clean_stop_is_announced(self):
        self.joined(self.bob, 'bob')
        self.joined(self.carol, 'carol')
        stopped, absent = self.stop(self.carol, 'carol')
        print('SIGTERM: absent(carol) %.2f s after the signal' % (absent - stopped))
        self.assertLess(absent - stopped, TIMEOUT + SLACK)
        # bob, who stayed, is unaffected
        self.assertEqual(run(self.log, self.alice, 'alice', 'names', r'names .*'), 'names [alice,bob]')


if __name__ == '__main__':
    rostest.rosrun('rason', 'multi_presence', TestPresence)
