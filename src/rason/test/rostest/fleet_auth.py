#!/usr/bin/python3
"""Fleet authentication between rason_mas processes, on the test's fleet channel (ROS topics, or
MQTT with fleet_channel:=mqtt): a node without the fleet key (a plain rospy publisher, or a broker
client) cannot make another robot's agent believe, do, stop or reveal anything, by a message to it
or a broadcast, nor hide a robot or add an agent with a forged presence (or, over MQTT, a forged
last will); a genuine message or presence played again, and an altered copy, are dropped; a robot
with another key is refused; a missing key stops the node with a clear error; the opt-out is
announced. Each drop is a warning naming the claimed sender; over MQTT, payloads that cannot be
read are logged at most 10 to the 10 s.

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

import rason_rospy

import rospy
import rostest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), 'nodes'))
from fleet_wire import MQTT, Will, encode_message, encode_presence, fleet_tap, inbox_topic, presence_topic  # noqa: E402
from rason_testing import MULTI_AGENTS, LogWatcher, Robot, run, start_mas, stop_mas, wait_for  # noqa: E402
from rason_bridge.fleet_key import generate_key, write_key  # noqa: E402
from rason_msgs.msg import AgentMessage, Presence  # noqa: E402

ALICE_MAS = '/robot1/rason_mas'
BOB_MAS = '/robot2/rason_mas'
MAS_OF = {'alice': ALICE_MAS, 'bob': BOB_MAS}


class TestFleetAuth(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        rason_rospy.init_node('test_fleet_auth')
        cls.log = LogWatcher()
        cls.r1 = Robot('robot1')
        cls.r2 = Robot('robot2')
        cls._lock = threading.Lock()
        cls.incarnations = {}   # mas_id -> incarnation, from the presence heard
        cls.presences = {}      # mas_id -> the last presence heard from it (not leaving)
        # the node without the key: publishes plain messages, no mac; hears every message
        cls.tap = fleet_tap(on_presence=cls._on_presence)
        cls.mqtt = cls.tap.channel == MQTT
        cls.r1.wait_connected()
        cls.r2.wait_connected()
        assert cls.tap.wait_ready(2), 'the robots do not hear this node on the fleet channel'
        assert cls.log.wait_ready()
        assert cls.log.wait_for(r'^\[alice\] present bob$', timeout=30)
        assert cls.log.wait_for(r'^\[bob\] present alice$', timeout=30)
        cls.procs = []
        cls.tmp = tempfile.mkdtemp(prefix='fleet_auth_test_')

    @classmethod
    def tearDownClass(cls):
        for p in cls.procs:
            stop_mas(p)
        if cls.mqtt:
            cls.tap.close()

    @classmethod
    def _on_presence(cls, msg):
        if not msg.mac:
            return  # what this node forged, heard back
        with cls._lock:
            cls.incarnations[msg.mas_id] = msg.incarnation
            if not msg.leaving:
                cls.presences[msg.mas_id] = msg

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
        """The incarnation mas announces (heard on the fleet channel)."""
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
        """The genuine AgentMessage with this content from sender, heard on the fleet channel."""
        def heard():
            return next(iter(self.tap.heard(lambda m: m.content == content and m.sender == sender and m.mac)), None)
        return wait_for(heard, timeout, '%s from %s on the fleet channel' % (content, sender))

    def captured_payload(self, msg):
        """Over MQTT: the (topic, payload) that carried the genuine msg, as it arrived."""
        return self.tap.captured(lambda m: isinstance(m, AgentMessage) and m.sender_mas == msg.sender_mas
                                 and m.sequence == msg.sequence and m.incarnation == msg.incarnation)[0]

    def publish(self, *messages):
        for m in messages:
            self.tap.publish_message(m)

    def play_again(self, genuine):
        """Publish a copy of a genuine message as it was heard (over MQTT: its very bytes, on its topic)."""
        if self.mqtt:
            self.tap.publish_raw(*self.captured_payload(genuine))
        else:
            self.publish(genuine)

    def expect(self, line, timeout=10.0, node=None):
        found = self.log.wait_for(line, timeout=timeout, node=node)
        self.assertTrue(found, 'never saw %r' % line)
        return found

    def skip_because(self, reason):
        print('skipped on the %s channel: %s' % (self.tap.channel, reason))
        self.skipTest(reason)

    def absent(self, line):
        self.assertFalse(self.log.lines(line), 'saw %r' % line)

    def replies_to(self, msg_id):
        return self.tap.heard(lambda m: m.in_reply_to == msg_id)

    def start(self, ns, name, output=None, **params):
        proc = start_mas(ns, os.path.join(MULTI_AGENTS, name + '.mas2j'), output=output, **params)
        self.procs.append(proc)
        return proc

    # ---- believe, do, stop, reveal -------------------------------------------------------

    def test_a_forged_tell_is_not_believed(self):
        line = self.dropped(lambda: self.publish(self.forged('tell', 'hello(666)')),
                            r'^dropped message tell from bob \(/robot2/rason_mas\) to alice: unauthenticated',
                            ALICE_MAS)
        self.assertIn('no mac', line)
        run(self.log, self.r2, 'bob', 'send(alice, tell, hello(667))', 'sent')
        self.expect(r'^\[alice\] told hello\(667\) by bob$')
        self.absent(r'^\[alice\] told hello\(666\)')

    def test_a_forged_achieve_is_not_done(self):
        self.dropped(lambda: self.publish(self.forged('achieve', 'greet(forged)')),
                     r'^dropped message achieve from bob \(/robot2/rason_mas\) to alice: unauthenticated', ALICE_MAS)
        run(self.log, self.r2, 'bob', 'send(alice, achieve, greet(marker2))', 'sent')
        self.expect(r'^\[alice\] asked to greet marker2 by bob$')
        self.absent(r'^\[alice\] asked to greet forged')

    def test_a_forged_plan_is_neither_learned_nor_run(self):
        def publish():
            self.publish(self.forged('tellHow', '+!evil <- .print("evil ran").', sender='alice', to='bob'))
            self.publish(self.forged('achieve', 'evil', sender='alice', to='bob'))
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
            self.publish(self.forged('unachieve', 'linger', sender='alice', to='bob'))
            self.publish(self.forged('tellHow', '+!halt <- .stopMAS.', sender='alice', to='bob'))
            self.publish(self.forged('achieve', 'halt', sender='alice', to='bob'))
        self.dropped(publish, r'^dropped message (unachieve|tellHow|achieve) from alice \(/robot1/rason_mas\) to bob: '
                     r'unauthenticated', BOB_MAS, count=3)
        # bob's process still runs and bob still lingers: the goal was not dropped
        self.assertEqual(run(self.log, self.r2, 'bob', 'desire(linger)', r'.*desire.*'), 'desires linger')
        self.absent(r'^\[bob\] lingered$')
        run(self.log, self.r1, 'alice', 'send(bob, unachieve, linger)', 'sent')  # the genuine one works

    def test_a_forged_ask_reveals_nothing(self):
        def publish():
            self.publish(self.forged('askOne', 'secret(X)', msg_id='forged_ask'))
            self.publish(self.forged('askAll', 'secret(X)', msg_id='forged_ask_all'))
            self.publish(self.forged('askHow', '+!greet(X)', msg_id='forged_how'))
        self.dropped(publish, r'^dropped message ask(One|All|How) from bob \(/robot2/rason_mas\) to alice: '
                     r'unauthenticated', ALICE_MAS, count=3)
        # the genuine ask is answered (alice's answers go out on the fleet channel, which this test hears)
        self.assertEqual(run(self.log, self.r2, 'bob', 'ask(alice, askOne, secret)', r'answer .*'),
                         'answer secret(alice_secret)[source(alice)]')
        for msg_id in ('forged_ask', 'forged_ask_all', 'forged_how'):
            self.assertEqual(self.replies_to(msg_id), [], 'alice answered %s' % msg_id)

    def test_a_forged_broadcast_is_believed_by_nobody(self):
        forged = AgentMessage(sender_mas='/robot9/rason_mas', sender='mallory', performative='tell',
                              content='hello(606)', incarnation=time.time_ns(), sequence=1, stamp=time.time_ns())
        pattern = r'^dropped message tell from mallory \(/robot9/rason_mas\) to everyone: unauthenticated'
        before = len(self.log.lines(pattern, node=BOB_MAS))
        self.dropped(lambda: self.publish(forged), pattern, ALICE_MAS)
        self.assertTrue(self.log.wait_for(pattern, count=before + 1, node=BOB_MAS), 'bob never dropped the broadcast')
        run(self.log, self.r1, 'alice', 'broadcast(tell, hello(607))', 'broadcast')
        self.expect(r'^\[bob\] told hello\(607\) by alice$')
        run(self.log, self.r2, 'bob', 'broadcast(tell, hello(608))', 'broadcast')
        self.expect(r'^\[alice\] told hello\(608\) by bob$')
        self.absent(r'told hello\(606\)')

    # ---- replay and tampering --------------------------------------------------------------

    def test_a_genuine_message_played_again_is_dropped(self):
        run(self.log, self.r2, 'bob', 'send(alice, achieve, greet(replay6))', 'sent')
        self.expect(r'^\[alice\] asked to greet replay6 by bob$')
        genuine = self.captured('greet(replay6)', 'bob')
        line = self.dropped(lambda: self.play_again(genuine),
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
        altered = []
        if self.mqtt:  # and the payload as it was heard with one byte of its content changed
            topic, payload = self.captured_payload(genuine)
            self.assertEqual(payload.count(b'hello(7)'), 1)
            altered.append((topic, payload.replace(b'hello(7)', b'hello(5)')))

        def publish():
            self.publish(tampered, guessed)
            for topic, payload in altered:
                self.tap.publish_raw(topic, payload)
        self.dropped(publish, r'^dropped message tell from bob \(/robot2/rason_mas\) to alice: bad mac', ALICE_MAS,
                     count=2 + len(altered))
        run(self.log, self.r2, 'bob', 'send(alice, tell, hello(779))', 'sent')
        self.expect(r'^\[alice\] told hello\(779\) by bob$')
        self.absent(r'^\[alice\] told hello\((77[78]|5)\)')

    # ---- presence ----------------------------------------------------------------------------

    def test_a_forged_presence_neither_hides_a_robot_nor_adds_an_agent(self):
        now = time.time_ns()

        def publish():
            # a higher incarnation: as if bob's robot had restarted with eve instead
            self.tap.publish_presence(Presence(mas_id=BOB_MAS, incarnation=2 ** 63 - 1, agents=['eve'], period=0.5,
                                           sequence=2 ** 40, stamp=now))
            # bob's robot leaving, and a robot that does not exist
            self.tap.publish_presence(Presence(mas_id=BOB_MAS, incarnation=self.incarnation(BOB_MAS), agents=['bob'],
                                           period=0.5, leaving=True, sequence=2 ** 40 + 1, stamp=now))
            self.tap.publish_presence(Presence(mas_id='/robot9/rason_mas', incarnation=now, agents=['mallory'],
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

    def test_a_genuine_presence_played_again_is_dropped(self):
        self.incarnation(BOB_MAS)
        with self._lock:
            genuine = self.presences[BOB_MAS]
        pattern = r'^dropped presence of /robot2/rason_mas announcing \[bob\]: replayed'
        if self.mqtt:
            # its very bytes, on bob's presence topic and on another robot's
            _, payload = self.tap.captured(lambda p: isinstance(p, Presence) and p.mas_id == BOB_MAS
                                           and p.sequence == genuine.sequence)[0]
            copies = [(presence_topic(BOB_MAS), payload), (presence_topic('/robot9/rason_mas'), payload)]
            self.dropped(lambda: [self.tap.publish_raw(t, p) for t, p in copies], pattern, ALICE_MAS, count=2)
        else:
            self.dropped(lambda: self.tap.publish_presence(genuine), pattern, ALICE_MAS)
        self.assertEqual(run(self.log, self.r1, 'alice', 'names', r'names .*'), 'names [alice,bob]')
        self.absent(r'presence: .*robot9')

    def test_a_forged_last_will_does_not_make_a_robot_look_gone(self):
        if not self.mqtt:
            self.skip_because('a last will is MQTT\'s: over ROS topics a robot is gone when its link drops')
        will = Will(BOB_MAS, '00' * 16, incarnation=self.incarnation(BOB_MAS), stamp=time.time_ns())
        self.dropped(lambda: self.tap.publish_will(will),
                     r'^dropped last will of /robot2/rason_mas: unauthenticated', ALICE_MAS)
        self.assertEqual(run(self.log, self.r1, 'alice', 'present', r'present .*'), 'present [alice,bob]')
        self.absent(r'^\[alice\] absent bob$')
        self.absent(r'presence: the connection of /robot2/rason_mas ended')

    def test_what_cannot_be_read_is_dropped_with_at_most_ten_lines(self):
        if not self.mqtt:
            self.skip_because('ROS topics carry typed rason_msgs: there is no payload to garble')
        inbox = inbox_topic(ALICE_MAS)
        forged = encode_message(self.forged('tell', 'hello(609)'))
        odd = [(inbox, b'\x07nonsense'), (inbox, forged[:20]), (presence_topic(BOB_MAS), forged),
               (inbox, encode_presence(Presence(mas_id=BOB_MAS, agents=['bob'], period=0.5)))]
        flood = odd + [(inbox, b'\x00%d' % i) for i in range(21)]
        pattern = r'^mqtt: dropped (what arrived on|a \w+ on) rason/'
        self.assertEqual(self.log.lines(pattern, node=ALICE_MAS), [])
        for topic, payload in flood:
            self.tap.publish_raw(topic, payload)
        self.expect(pattern, node=ALICE_MAS)
        # bob's tell comes after the flood in alice's queue at the broker
        run(self.log, self.r2, 'bob', 'send(alice, tell, hello(610))', 'sent')
        self.expect(r'^\[alice\] told hello\(610\) by bob$')
        lines = [l[3] for l in self.log.wait_for(pattern, count=10, node=ALICE_MAS)]
        for expected in (r'on rason/inbox/robot1/rason_mas: not a version 1 payload$',
                         r'on rason/inbox/robot1/rason_mas: a field of 17 bytes, with 14 left$',
                         r'^mqtt: dropped a Message on rason/presence/robot2/rason_mas$',
                         r'^mqtt: dropped a Presence on rason/inbox/robot1/rason_mas$'):
            self.assertTrue(any(re.search(expected, l) for l in lines), (expected, lines))
        self.log.wait_quiet(0.5, pattern)
        self.assertEqual(len(self.log.lines(pattern, node=ALICE_MAS)), 10, '25 payloads, at most 10 lines')
        self.absent(r'told hello\(609\)')

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
