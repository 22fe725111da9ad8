#!/usr/bin/python3
"""Fleet authentication between rason_mas processes: a node without the fleet key cannot make
another robot's agent believe, do, stop or reveal anything, nor hide a robot or add an agent with a
forged presence; a genuine message played again is dropped; a robot with another key is refused;
a missing key stops the node with a clear error; the opt-out is announced. Each drop is a warning
naming the claimed sender.

Negative checks use markers: the receiver's drop line proves the forged message was refused before
delivery, and a genuine message sent afterwards must be handled before the test checks that the
forged one was not."""
import os
import re
import subprocess
import sys
import tempfile
import threading
import time
import unittest

import rospy
import rostest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), 'nodes'))
from rason_testing import (MULTI_AGENTS, LogWatcher, Robot, run, start_mas, stop_mas,  # noqa: E402
                           wait_for, wait_for_subscribers)
from rason_bridge.fleet_key import generate_key, write_key  # noqa: E402
from rason_msgs.msg import AgentMessage, Presence  # noqa: E402

ALICE_MAS = '/robot1/rason_mas'
BOB_MAS = '/robot2/rason_mas'
MAS_OF = {'alice': ALICE_MAS, 'bob': BOB_MAS}


class TestFleetAuth(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        rospy.init_node('test_fleet_auth')
        cls.log = LogWatcher()
        cls.r1 = Robot('robot1')
        cls.r2 = Robot('robot2')
        cls._lock = threading.Lock()
        cls.heard = []          # every AgentMessage on /rason/messages
        cls.incarnations = {}   # mas_id -> incarnation, from the presence heard
        rospy.Subscriber('/rason/messages', AgentMessage, cls._on_message, queue_size=None)
        rospy.Subscriber('/rason/presence', Presence, cls._on_presence, queue_size=100)
        # what the node without the key publishes: plain messages, no mac
        cls.messages = rospy.Publisher('/rason/messages', AgentMessage, queue_size=100)
        cls.presence = rospy.Publisher('/rason/presence', Presence, queue_size=100)
        cls.r1.wait_connected()
        cls.r2.wait_connected()
        assert wait_for_subscribers(cls.messages, 2, timeout=30)
        assert wait_for_subscribers(cls.presence, 2, timeout=30)
        assert cls.log.wait_ready()
        assert cls.log.wait_for(r'^\[alice\] present bob$', timeout=30)
        assert cls.log.wait_for(r'^\[bob\] present alice$', timeout=30)
        cls.procs = []
        cls.tmp = tempfile.mkdtemp(prefix='fleet_auth_test_')

    @classmethod
    def tearDownClass(cls):
        for p in cls.procs:
            stop_mas(p)

    @classmethod
    def _on_message(cls, msg):
        with cls._lock:
            cls.heard.append(msg)

    @classmethod
    def _on_presence(cls, msg):
        with cls._lock:
            cls.incarnations[msg.mas_id] = msg.incarnation

    # ---- helpers -----------------------------------------------------------------------

    def forged(self, performative, content, sender='bob', to='alice', msg_id='', in_reply_to='', **fields):
        """A message as a node without the key makes it: every field right (the sender's real
        incarnation, a fresh stamp, a high sequence) but the mac."""
        values = dict(sender_mas=MAS_OF[sender], sender=sender, receiver_mas=MAS_OF[to], receiver=to,
                      performative=performative, content=content, msg_id=msg_id, in_reply_to=in_reply_to,
                      incarnation=self.incarnation(MAS_OF[sender]), sequence=2 ** 40, stamp=time.time_ns())
        values.update(fields)
        return AgentMessage(**values)

    def incarnation(self, mas):
        """The incarnation mas announces (heard on /rason/presence)."""
        def heard():
            with self._lock:
                return self.incarnations.get(mas)
        return wait_for(heard, 10, 'the presence of %s' % mas)

    def dropped(self, publish, pattern, node, count=1, timeout=10.0):
        """Publish (a callable) and wait until ``node`` logs ``count`` more lines matching pattern."""
        before = len(self.log.lines(pattern, node=node))
        publish()
        found = self.log.wait_for(pattern, timeout=timeout, count=before + count, node=node)
        self.assertTrue(found, '%s never logged %r (%d times)' % (node, pattern, count))
        return found[-1][3]

    def captured(self, content, sender, timeout=10.0):
        """The genuine AgentMessage with this content from sender, heard on /rason/messages."""
        def heard():
            with self._lock:
                return next((m for m in self.heard if m.content == content and m.sender == sender and m.mac), None)
        return wait_for(heard, timeout, '%s from %s on /rason/messages' % (content, sender))

    def expect(self, line, timeout=10.0, node=None):
        found = self.log.wait_for(line, timeout=timeout, node=node)
        self.assertTrue(found, 'never saw %r' % line)
        return found

    def absent(self, line):
        self.assertFalse(self.log.lines(line), 'saw %r' % line)

    def replies_to(self, msg_id):
        with self._lock:
            return [m for m in self.heard if m.in_reply_to == msg_id]

    def start(self, ns, name, output=None, **params):
        proc = start_mas(ns, os.path.join(MULTI_AGENTS, name + '.mas2j'), output=output, **params)
        self.procs.append(proc)
        return proc

    # ---- believe, do, stop, reveal -------------------------------------------------------

    def test_a_forged_tell_is_not_believed(self):
        line = self.dropped(lambda: self.messages.publish(self.forged('tell', 'hello(666)')),
                            r'^dropped message tell from bob \(/robot2/rason_mas\) to alice: unauthenticated',
                            ALICE_MAS)
        self.assertIn('no mac', line)
        run(self.log, self.r2, 'bob', 'send(alice, tell, hello(667))', 'sent')
        self.expect(r'^\[alice\] told hello\(667\) by bob$')
        self.absent(r'^\[alice\] told hello\(666\)')

    def test_a_forged_achieve_is_not_done(self):
        self.dropped(lambda: self.messages.publish(self.forged('achieve', 'greet(forged)')),
                     r'^dropped message achieve from bob \(/robot2/rason_mas\) to alice: unauthenticated', ALICE_MAS)
        run(self.log, self.r2, 'bob', 'send(alice, achieve, greet(marker2))', 'sent')
        self.expect(r'^\[alice\] asked to greet marker2 by bob$')
        self.absent(r'^\[alice\] asked to greet forged')

    def test_a_forged_plan_is_neither_learned_nor_run(self):
        def publish():
            self.messages.publish(self.forged('tellHow', '+!evil <- .print("evil ran").', sender='alice', to='bob'))
            self.messages.publish(self.forged('achieve', 'evil', sender='alice', to='bob'))
        self.dropped(publish, r'^dropped message (tellHow|achieve) from alice \(/robot1/rason_mas\) to bob: '
                     r'unauthenticated', BOB_MAS, count=2)
        run(self.log, self.r1, 'alice', 'send(bob, achieve, greet(marker3))', 'sent')
        self.expect(r'^\[bob\] asked to greet marker3 by alice$')
        self.absent(r'evil ran')
        self.absent(r'^\[bob\].*evil')  # not even a failure: the achieve never reached bob

    def test_a_forged_stop_stops_nothing(self):
        run(self.log, self.r1, 'alice', 'send(bob, achieve, linger)', 'sent')
        self.expect(r'^\[bob\] lingering for alice$')

        def publish():
            self.messages.publish(self.forged('unachieve', 'linger', sender='alice', to='bob'))
            self.messages.publish(self.forged('tellHow', '+!halt <- .stopMAS.', sender='alice', to='bob'))
            self.messages.publish(self.forged('achieve', 'halt', sender='alice', to='bob'))
        self.dropped(publish, r'^dropped message (unachieve|tellHow|achieve) from alice \(/robot1/rason_mas\) to bob: '
                     r'unauthenticated', BOB_MAS, count=3)
        # bob's process still runs and bob still lingers: the goal was not dropped
        self.assertEqual(run(self.log, self.r2, 'bob', 'desire(linger)', r'.*desire.*'), 'desires linger')
        self.absent(r'^\[bob\] lingered$')
        run(self.log, self.r1, 'alice', 'send(bob, unachieve, linger)', 'sent')  # the genuine one works

    def test_a_forged_ask_reveals_nothing(self):
        def publish():
            self.messages.publish(self.forged('askOne', 'secret(X)', msg_id='forged_ask'))
            self.messages.publish(self.forged('askAll', 'secret(X)', msg_id='forged_ask_all'))
            self.messages.publish(self.forged('askHow', '+!greet(X)', msg_id='forged_how'))
        self.dropped(publish, r'^dropped message ask(One|All|How) from bob \(/robot2/rason_mas\) to alice: '
                     r'unauthenticated', ALICE_MAS, count=3)
        # the genuine ask is answered (alice's answers go out on /rason/messages, which this test hears)
        self.assertEqual(run(self.log, self.r2, 'bob', 'ask(alice, askOne, secret)', r'answer .*'),
                         'answer secret(alice_secret)[source(alice)]')
        for msg_id in ('forged_ask', 'forged_ask_all', 'forged_how'):
            self.assertEqual(self.replies_to(msg_id), [], 'alice answered %s' % msg_id)

    # ---- replay and tampering --------------------------------------------------------------

    def test_a_genuine_message_played_again_is_dropped(self):
        run(self.log, self.r2, 'bob', 'send(alice, achieve, greet(replay6))', 'sent')
        self.expect(r'^\[alice\] asked to greet replay6 by bob$')
        genuine = self.captured('greet(replay6)', 'bob')
        line = self.dropped(lambda: self.messages.publish(genuine),
                            r'^dropped message achieve from bob \(/robot2/rason_mas\) to alice: replayed', ALICE_MAS)
        self.assertIn('sequence %d already seen' % genuine.sequence, line)
        run(self.log, self.r2, 'bob', 'send(alice, achieve, greet(marker6))', 'sent')
        self.expect(r'^\[alice\] asked to greet marker6 by bob$')
        self.assertEqual(len(self.log.lines(r'^\[alice\] asked to greet replay6 by bob$')), 1)

    def test_a_changed_or_guessed_mac_is_refused(self):
        run(self.log, self.r2, 'bob', 'send(alice, tell, hello(7))', 'sent')
        self.expect(r'^\[alice\] told hello\(7\) by bob$')
        genuine = self.captured('hello(7)', 'bob')
        tampered = AgentMessage(**{f: getattr(genuine, f) for f in genuine.__slots__})
        tampered.content = 'hello(777)'
        tampered.sequence = genuine.sequence + 1000  # as if it were new
        guessed = self.forged('tell', 'hello(778)', key_id=genuine.key_id, mac=os.urandom(32))

        def publish():
            self.messages.publish(tampered)
            self.messages.publish(guessed)
        self.dropped(publish, r'^dropped message tell from bob \(/robot2/rason_mas\) to alice: bad mac', ALICE_MAS,
                     count=2)
        run(self.log, self.r2, 'bob', 'send(alice, tell, hello(779))', 'sent')
        self.expect(r'^\[alice\] told hello\(779\) by bob$')
        self.absent(r'^\[alice\] told hello\(77[78]\)')

    # ---- presence ----------------------------------------------------------------------------

    def test_a_forged_presence_neither_hides_a_robot_nor_adds_an_agent(self):
        now = time.time_ns()

        def publish():
            # a higher incarnation: as if bob's robot had restarted with eve instead
            self.presence.publish(Presence(mas_id=BOB_MAS, incarnation=2 ** 63 - 1, agents=['eve'], period=0.5,
                                           sequence=2 ** 40, stamp=now))
            # bob's robot leaving, and a robot that does not exist
            self.presence.publish(Presence(mas_id=BOB_MAS, incarnation=self.incarnation(BOB_MAS), agents=['bob'],
                                           period=0.5, leaving=True, sequence=2 ** 40 + 1, stamp=now))
            self.presence.publish(Presence(mas_id='/robot9/rason_mas', incarnation=now, agents=['mallory'],
                                           period=0.5, sequence=1, stamp=now))
        self.dropped(publish, r'^dropped presence of (/robot2|/robot9)/rason_mas.*: unauthenticated', ALICE_MAS, count=3)
        lines = [line[3] for line in self.log.lines(r'^dropped presence of', node=ALICE_MAS)]
        self.assertTrue(any(l.startswith('dropped presence of /robot2/rason_mas announcing [eve]: unauthenticated')
                            for l in lines), lines)
        self.assertTrue(any(l.startswith('dropped presence of /robot2/rason_mas (leaving): unauthenticated')
                            for l in lines), lines)
        # the drop lines prove nothing reached the presence table; alice's view and links are unchanged
        self.assertEqual(run(self.log, self.r1, 'alice', 'present', r'present .*'), 'present [alice,bob]')
        self.assertEqual(run(self.log, self.r1, 'alice', 'names', r'names .*'), 'names [alice,bob]')
        run(self.log, self.r1, 'alice', 'send(bob, tell, hello(8))', 'sent')
        self.expect(r'^\[bob\] told hello\(8\) by alice$')
        self.absent(r'^\[alice\] (absent bob|present (eve|mallory))$')
        self.absent(r'presence: .*(robot9|restarted|eve)')

    # ---- keys and the opt-out ------------------------------------------------------------------

    def test_a_robot_with_another_key_is_refused(self):
        key_file = os.path.join(self.tmp, 'other_fleet.key')
        write_key(key_file, generate_key())
        stranger = Robot('robot3')
        proc = self.start('robot3', 'stranger', fleet_key_file=key_file)
        try:
            found = self.log.wait_for(r'^dropped presence of /robot3/rason_mas announcing \[stranger\]: unknown key',
                                      timeout=60, node=ALICE_MAS)
            self.assertTrue(found, 'alice never refused the stranger\'s presence')
            self.assertIsNone(proc.poll())
            self.expect(r'^dropped presence of /robot1/rason_mas announcing \[alice\]: unknown key',
                        node='/robot3/rason_mas')
            stranger.wait_connected()
            self.assertTrue(self.log.wait_ready())
            self.assertEqual(run(self.log, stranger, 'stranger', 'names', r'names .*'), 'names [stranger]')
            self.dropped(lambda: run(self.log, stranger, 'stranger', 'broadcast(tell, hello(9))', 'broadcast'),
                         r'^dropped message tell from stranger \(/robot3/rason_mas\) to everyone: unknown key',
                         ALICE_MAS)
            self.assertEqual(run(self.log, self.r1, 'alice', 'present', r'present .*'), 'present [alice,bob]')
            self.absent(r'^\[alice\] told hello\(9\)')
            self.absent(r'^\[alice\] present stranger$')
        finally:
            stop_mas(proc)

    def test_a_missing_key_stops_the_node_with_a_clear_error(self):
        missing = os.path.join(self.tmp, 'nowhere', 'fleet.key')
        proc = self.start('robot5', 'stranger', output=subprocess.PIPE, fleet_key_file=missing)
        out, _ = proc.communicate(timeout=90)
        self.assertEqual(proc.returncode, 1, out)
        self.assertRegex(out, r'fleet authentication is required \(~fleet_auth\) but there is no usable fleet key: '
                         + re.escape(missing) + ' does not exist')
        self.assertIn('rosrun rason_bridge fleet_key %s' % missing, out)

    def test_the_opt_out_is_announced_and_its_unsigned_traffic_refused(self):
        labbot = Robot('robot4')
        # message_ttl 2 s: alice drops labbot's tell, so no receipt comes and labbot's send fails then
        proc = self.start('robot4', 'labbot', fleet_auth='off', message_ttl=2.0)
        try:
            self.expect(r'^fleet authentication is OFF', timeout=60, node='/robot4/rason_mas')
            found = self.log.wait_for(r'^dropped presence of /robot4/rason_mas announcing \[labbot\]: unauthenticated',
                                      timeout=30, node=BOB_MAS)
            self.assertTrue(found, 'bob never refused the unsigned presence')
            labbot.wait_connected()
            self.assertTrue(self.log.wait_ready())
            # labbot checks nothing, so it believes alice is there; alice refuses what it sends
            wait_for(lambda: run(self.log, labbot, 'labbot', 'names', r'names .*') == 'names [alice,bob,labbot]',
                     20, 'labbot to list alice and bob', interval=0.2)
            self.dropped(lambda: run(self.log, labbot, 'labbot', 'send(alice, tell, hello(11))',
                                     r'failed undelivered: no receipt from \[alice\] .*'),
                         r'^dropped message tell from labbot \(/robot4/rason_mas\) to alice: unauthenticated',
                         ALICE_MAS)
            self.assertEqual(run(self.log, self.r1, 'alice', 'present', r'present .*'), 'present [alice,bob]')
            self.absent(r'^\[alice\] told hello\(11\)')
        finally:
            stop_mas(proc)


if __name__ == '__main__':
    rostest.rosrun('rason', 'fleet_auth', TestFleetAuth)
