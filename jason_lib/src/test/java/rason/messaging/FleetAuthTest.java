package rason.messaging;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.DataOutputStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.function.UnaryOperator;

import javax.crypto.Mac;
import javax.crypto.spec.SecretKeySpec;

import org.junit.jupiter.api.Test;

import rason.messaging.FleetAuth.Kind;
import rason.messaging.FleetAuth.Problem;
import rason.messaging.FleetAuth.Refusal;
import rason.messaging.FleetAuth.Signed;

class FleetAuthTest {

    private static final long S = 1_000_000_000L;
    /** Wall clock of the tests: 2026-01-01, in ns since the epoch. */
    private static final long T0 = 1_767_225_600L * S;
    private static final String ROBOT2 = "/robot2/rason_mas";

    private final long[] wall = { T0 };
    private final FleetKeys keysA = SigningPeer.keys(SigningPeer.KEY_A);
    private final FleetKeys keysB = SigningPeer.keys(SigningPeer.KEY_B);

    /** A process with keys, started at incarnation, on the tests' wall clock. */
    private FleetAuth process(FleetKeys keys, long incarnation) {
        FleetAuth a = new FleetAuth(() -> wall[0]);
        a.require(keys);
        a.setIncarnation(incarnation);
        return a;
    }

    private final FleetAuth sender = process(keysA, T0 - 10 * S);
    private final FleetAuth receiver = process(keysA, T0 - 20 * S);

    private static WireMessage tell(String content) {
        return new WireMessage(ROBOT2, "bob", "/robot1/rason_mas", "alice", "tell", content, "mid7", "");
    }

    /** The receiver's full check of one message: MAC and clock, then replay. */
    private Refusal receive(FleetAuth to, WireMessage m, Signed s) {
        Refusal r = to.verify(m, s);
        return r != null ? r : to.admit(Kind.MESSAGE, m.senderMas(), s, wall[0], null);
    }

    private static Problem problem(Refusal r) {
        return r == null ? null : r.problem();
    }

    @Test
    void aSignedMessageIsAcceptedOnce() {
        WireMessage m = tell("hello(1)");
        Signed s = sender.sign(m);
        assertEquals(FleetAuth.MAC_BYTES, s.mac().length);
        assertEquals(keysA.signing().id(), s.keyId());
        assertEquals(T0 - 10 * S, s.incarnation());
        assertEquals(1, s.sequence());
        assertEquals(T0, s.stamp());
        assertNull(receive(receiver, m, s));
        Refusal again = receive(receiver, m, s);
        assertEquals(Problem.REPLAYED, problem(again));
        assertEquals("replayed: sequence 1 already seen (the last accepted is 1)", again.text());
    }

    @Test
    void sequencesStartAtOneAndGrowPerTopic() {
        assertEquals(1, sender.sign(tell("a")).sequence());
        assertEquals(2, sender.sign(tell("b")).sequence());
        assertEquals(1, sender.signPresence(ROBOT2, List.of("bob"), 0.5f, false).sequence());
        assertEquals(3, sender.sign(tell("c")).sequence());
        assertEquals(2, sender.signPresence(ROBOT2, List.of("bob"), 0.5f, false).sequence());
    }

    @Test
    void changingAnyFieldOfAMessageBreaksItsMac() {
        WireMessage m = tell("hello(1)");
        Signed s = sender.sign(m);
        List<UnaryOperator<WireMessage>> edits = List.of(
                x -> new WireMessage("/robot3/rason_mas", x.sender(), x.receiverMas(), x.receiver(), x.performative(), x.content(), x.msgId(), x.inReplyTo()),
                x -> new WireMessage(x.senderMas(), "carol", x.receiverMas(), x.receiver(), x.performative(), x.content(), x.msgId(), x.inReplyTo()),
                x -> new WireMessage(x.senderMas(), x.sender(), "", x.receiver(), x.performative(), x.content(), x.msgId(), x.inReplyTo()),
                x -> new WireMessage(x.senderMas(), x.sender(), x.receiverMas(), "alicf", x.performative(), x.content(), x.msgId(), x.inReplyTo()),
                x -> new WireMessage(x.senderMas(), x.sender(), x.receiverMas(), x.receiver(), "achieve", x.content(), x.msgId(), x.inReplyTo()),
                x -> new WireMessage(x.senderMas(), x.sender(), x.receiverMas(), x.receiver(), x.performative(), "hello(2)", x.msgId(), x.inReplyTo()),
                x -> new WireMessage(x.senderMas(), x.sender(), x.receiverMas(), x.receiver(), x.performative(), x.content(), "mid8", x.inReplyTo()),
                x -> new WireMessage(x.senderMas(), x.sender(), x.receiverMas(), x.receiver(), x.performative(), x.content(), x.msgId(), "mid1"));
        for (UnaryOperator<WireMessage> edit : edits)
            assertEquals(Problem.BAD_MAC, problem(receiver.verify(edit.apply(m), s)), edit.apply(m).toString());
        List<Signed> altered = List.of(
                new Signed(s.incarnation() + 1, s.sequence(), s.stamp(), s.keyId(), s.mac()),
                new Signed(s.incarnation(), s.sequence() + 1, s.stamp(), s.keyId(), s.mac()),
                new Signed(s.incarnation(), s.sequence(), s.stamp() + 1, s.keyId(), s.mac()),
                new Signed(s.incarnation(), s.sequence(), s.stamp(), s.keyId(), flipped(s.mac(), 31)),
                new Signed(s.incarnation(), s.sequence(), s.stamp(), s.keyId(), java.util.Arrays.copyOf(s.mac(), 31)));
        for (Signed a : altered)
            assertEquals(Problem.BAD_MAC, problem(receiver.verify(m, a)));
        assertNull(receiver.verify(m, s), "the original still verifies");
    }

    @Test
    void changingAnyFieldOfAPresenceBreaksItsMac() {
        List<String> agents = List.of("bob", "dave");
        Signed s = sender.signPresence(ROBOT2, agents, 0.5f, false);
        assertNull(receiver.verifyPresence(ROBOT2, agents, 0.5f, false, s));
        assertEquals(Problem.BAD_MAC, problem(receiver.verifyPresence("/robot3/rason_mas", agents, 0.5f, false, s)));
        assertEquals(Problem.BAD_MAC, problem(receiver.verifyPresence(ROBOT2, List.of("bob", "dave", "eve"), 0.5f, false, s)));
        assertEquals(Problem.BAD_MAC, problem(receiver.verifyPresence(ROBOT2, List.of("bob"), 0.5f, false, s)));
        assertEquals(Problem.BAD_MAC, problem(receiver.verifyPresence(ROBOT2, List.of("dave", "bob"), 0.5f, false, s)));
        assertEquals(Problem.BAD_MAC, problem(receiver.verifyPresence(ROBOT2, List.of("bobdave"), 0.5f, false, s)));
        assertEquals(Problem.BAD_MAC, problem(receiver.verifyPresence(ROBOT2, agents, 0.25f, false, s)));
        assertEquals(Problem.BAD_MAC, problem(receiver.verifyPresence(ROBOT2, agents, 0.5f, true, s)));
        assertEquals(Problem.BAD_MAC, problem(receiver.verifyPresence(ROBOT2, agents, 0.5f, false,
                new Signed(Long.MAX_VALUE, s.sequence(), s.stamp(), s.keyId(), s.mac()))));
    }

    @Test
    void changingADirectoryRegistrationOfAPresenceBreaksItsMac() {
        List<String> agents = List.of("bob", "dave"), dfAgents = List.of("bob", "dave"), services = List.of("paint", "x");
        Signed s = sender.signPresence(ROBOT2, agents, dfAgents, services, 0.5f, false);
        assertNull(receiver.verifyPresence(ROBOT2, agents, dfAgents, services, 0.5f, false, s));
        assertEquals(Problem.BAD_MAC, problem(receiver.verifyPresence(ROBOT2, agents, 0.5f, false, s)), "dropped");
        assertEquals(Problem.BAD_MAC, problem(receiver.verifyPresence(ROBOT2, agents, List.of("dave", "bob"), services,
                0.5f, false, s)), "swapped providers");
        assertEquals(Problem.BAD_MAC, problem(receiver.verifyPresence(ROBOT2, agents, dfAgents, List.of("paint", "y"),
                0.5f, false, s)), "another service");
        assertEquals(Problem.BAD_MAC, problem(receiver.verifyPresence(ROBOT2, agents, List.of("bob", "dave", "bob"),
                List.of("paint", "x", "z"), 0.5f, false, s)), "one more");
        assertEquals(Problem.BAD_MAC, problem(receiver.verifyPresence(ROBOT2, agents, List.of("bob"), List.of("paint"),
                0.5f, false, s)), "one less");
        // a presence without registrations is not one with an empty registration
        Signed none = sender.signPresence(ROBOT2, agents, 0.5f, false);
        assertNull(receiver.verifyPresence(ROBOT2, agents, List.of(), List.of(), 0.5f, false, none));
        assertEquals(Problem.BAD_MAC, problem(receiver.verifyPresence(ROBOT2, agents, List.of(""), List.of(""), 0.5f,
                false, none)));
    }

    @Test
    void fieldsCannotBeShiftedIntoEachOther() {
        // "ab" + "c" and "a" + "bc" must not sign alike: every string carries its length
        WireMessage m1 = new WireMessage(ROBOT2, "ab", "", "c", "tell", "x", "", "");
        WireMessage m2 = new WireMessage(ROBOT2, "a", "", "bc", "tell", "x", "", "");
        assertEquals(Problem.BAD_MAC, problem(receiver.verify(m2, sender.sign(m1))));
        assertFalse(java.util.Arrays.equals(CanonicalForm.message(m1, sender.sign(m1)),
                CanonicalForm.message(m2, sender.sign(m1))));
    }

    @Test
    void aPresenceMacNeverPassesForAMessage() {
        // a presence and a message whose fields line up as closely as the types allow
        Signed p = sender.signPresence(ROBOT2, List.of(), 0.0f, false);
        WireMessage m = new WireMessage(ROBOT2, "", "", "", "", "", "", "");
        assertEquals(Problem.BAD_MAC, problem(receiver.verify(m, p)));
        Signed msg = sender.sign(m);
        assertEquals(Problem.BAD_MAC, problem(receiver.verifyPresence(ROBOT2, List.of(), 0.0f, false, msg)));
    }

    @Test
    void theMacIsHmacSha256OverTheDocumentedEncoding() throws Exception {
        WireMessage m = new WireMessage(ROBOT2, "bob", "", "", "tell", "héllo", "m1", "");
        Signed s = sender.sign(m);
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        DataOutputStream out = new DataOutputStream(bytes);
        for (String field : new String[] { "rason_msgs/AgentMessage", s.keyId(), ROBOT2 })
            writeString(out, field);
        out.writeLong(s.incarnation());
        out.writeLong(s.sequence());
        out.writeLong(s.stamp());
        for (String field : new String[] { "bob", "", "", "tell", "héllo", "m1", "" })
            writeString(out, field);
        Mac mac = Mac.getInstance("HmacSHA256");
        mac.init(new SecretKeySpec(SigningPeer.KEY_A.getBytes(StandardCharsets.UTF_8), "HmacSHA256"));
        assertArrayEquals(bytes.toByteArray(), CanonicalForm.message(m, s));
        assertArrayEquals(mac.doFinal(bytes.toByteArray()), s.mac());
    }

    private static void writeString(DataOutputStream out, String s) throws Exception {
        byte[] b = s.getBytes(StandardCharsets.UTF_8);
        out.writeInt(b.length);
        out.write(b);
    }

    @Test
    void unsignedTrafficIsUnauthenticated() {
        Signed none = new Signed(0, 0, 0, "", new byte[0]);
        Refusal r = receiver.verify(tell("hello(1)"), none);
        assertEquals(Problem.UNAUTHENTICATED, problem(r));
        assertEquals("unauthenticated: no mac (is ~fleet_auth off on the sender's robot?)", r.text());
        assertEquals(Problem.UNAUTHENTICATED, problem(receiver.verifyPresence(ROBOT2, List.of("bob"), 0.5f, false, none)));
    }

    @Test
    void anotherFleetsKeyIsUnknownAndAGuessedMacUnderOurKeyIdIsBad() {
        FleetAuth stranger = process(keysB, T0 - 5 * S);
        WireMessage m = tell("hello(1)");
        Signed s = stranger.sign(m);
        Refusal r = receiver.verify(m, s);
        assertEquals(Problem.UNKNOWN_KEY, problem(r));
        // what both robots log when their key files differ: the two keys and what to do
        assertEquals("unknown key: signed with key '" + keysB.signing().id() + "', which is not in this robot's fleet keys "
                + keysA.ids() + ": the robots' key files differ (put the same file on both; docs: Security)", r.text());
        Signed guessed = new Signed(s.incarnation(), s.sequence(), s.stamp(), keysA.signing().id(), s.mac());
        assertEquals(Problem.BAD_MAC, problem(receiver.verify(m, guessed)));
    }

    @Test
    void aMessageOvertakenByALaterOneIsDropped() {
        WireMessage m1 = tell("hello(1)"), m2 = tell("hello(2)");
        Signed s1 = sender.sign(m1), s2 = sender.sign(m2);
        assertNull(receive(receiver, m2, s2));
        Refusal late = receive(receiver, m1, s1);
        assertEquals(Problem.OUT_OF_ORDER, problem(late), "never seen: not called a replay");
        assertEquals("out of order: sequence 1 came after 2 (reordered or held back on the way; dropped to keep the "
                + "sender's order)", late.text());
        assertEquals(Problem.REPLAYED, problem(receive(receiver, m2, s2)), "accepted before: a replay");
        WireMessage m3 = tell("hello(3)");
        assertNull(receive(receiver, m3, sender.sign(m3)), "gaps are fine: the receiver hears only what is for it");
    }

    @Test
    void aRestartStartsANewSequenceAndTheEarlierRunIsReplayed() {
        WireMessage m = tell("hello(1)");
        Signed old1 = sender.sign(m), old2 = sender.sign(m), old3 = sender.sign(m);
        assertNull(receive(receiver, m, old1));
        assertNull(receive(receiver, m, old2));
        FleetAuth restarted = process(keysA, T0 - S);
        assertNull(receive(receiver, m, restarted.sign(m)), "sequence 1 of the new run");
        Refusal r = receive(receiver, m, old3);
        assertEquals(Problem.REPLAYED, problem(r));
        assertEquals("replayed: from an earlier run of /robot2/rason_mas (incarnation " + (T0 - 10 * S)
                + "; it now runs " + (T0 - S) + ")", r.text());
    }

    @Test
    void sequencesAreComparedAsUnsigned() {
        Signed low = new Signed(T0 - 10 * S, 5, T0, "", new byte[0]);
        Signed high = new Signed(T0 - 10 * S, Long.MIN_VALUE, T0, "", new byte[0]); // 2^63 as uint64
        assertNull(receiver.admit(Kind.MESSAGE, ROBOT2, low, 0, null));
        assertNull(receiver.admit(Kind.MESSAGE, ROBOT2, high, 0, null));
        assertEquals(Problem.REPLAYED, problem(receiver.admit(Kind.MESSAGE, ROBOT2, low, 0, null)));
    }

    @Test
    void messagesAndPresenceHaveSeparateSequences() {
        Signed p = sender.signPresence(ROBOT2, List.of("bob"), 0.5f, false);
        WireMessage m = tell("x");
        Signed s = sender.sign(m);
        assertEquals(p.sequence(), s.sequence());
        assertNull(receiver.admit(Kind.PRESENCE, ROBOT2, p, 0, null));
        assertNull(receive(receiver, m, s));
    }

    @Test
    void theCallersChecksRunInTheSameStepAndARefusalRecordsNothing() {
        WireMessage m = tell("x");
        Signed s = sender.sign(m);
        Refusal forged = new Refusal(Problem.FORGED, "test");
        assertEquals(forged, receiver.admit(Kind.MESSAGE, ROBOT2, s, 0, () -> forged));
        assertEquals(0, receiver.sendersKept());
        assertNull(receiver.admit(Kind.MESSAGE, ROBOT2, s, 0, () -> null), "the refused copy was not recorded");
        List<String> calls = new ArrayList<>();
        assertEquals(Problem.REPLAYED, problem(receiver.admit(Kind.MESSAGE, ROBOT2, s, 0, () -> {
            calls.add("more");
            return null;
        })));
        assertTrue(calls.isEmpty(), "a replay is refused before the caller's checks");
    }

    @Test
    void stampsOutsideTheWindowAreStale() {
        WireMessage m = tell("x");
        Signed s = sender.sign(m); // stamped T0
        wall[0] = T0 + 61 * S;
        Refusal r = receiver.verify(m, s);
        assertEquals(Problem.STALE, problem(r));
        assertEquals("stale: stamped 61.0 s ago, outside the 60 s window", r.text());
        wall[0] = T0 + 59 * S;
        assertNull(receiver.verify(m, s));
        wall[0] = T0 - 61 * S;
        assertTrue(receiver.verify(m, s).text().startsWith("stale: stamped 61.0 s in the future"));
        receiver.setWindowNanos(10 * S);
        wall[0] = T0 + 11 * S;
        assertEquals(Problem.STALE, problem(receiver.verify(m, s)));
    }

    @Test
    void aWindowOfZeroTurnsTheClockChecksOff() {
        WireMessage m = tell("x");
        Signed s = sender.sign(m);
        receiver.setWindowNanos(0);
        wall[0] = T0 + 3600 * S;
        assertNull(receiver.verify(m, s));
        FleetAuth late = process(keysA, T0 + 5 * S);
        late.setWindowNanos(0);
        assertNull(late.verify(m, s), "nor is the start of the process checked");
    }

    @Test
    void trafficStampedBeforeTheReceiverStartedIsStale() {
        // a process that just started has no sequence state: a recording from before its start must not pass
        WireMessage m = tell("x");
        Signed s = sender.sign(m); // T0
        wall[0] = T0 + 5 * S;
        FleetAuth fresh = process(keysA, T0 + 2 * S);
        Refusal r = fresh.verify(m, s);
        assertEquals(Problem.STALE, problem(r));
        assertEquals("stale: stamped 2.0 s before this process started", r.text());
        assertNull(fresh.verify(m, sender.sign(m)), "what is signed now passes");
    }

    @Test
    void rotationKeepsTheFleetTalkingAtEveryStep() {
        String a = SigningPeer.KEY_A, b = SigningPeer.KEY_B;
        WireMessage m = tell("x");
        // step 1: every robot has the new key second: still signs with A, accepts B too
        FleetAuth r1 = process(SigningPeer.keys(a, b), 1);
        // step 2 on one robot: B moved first, so it signs with B; robots still at step 1 accept it
        FleetAuth r2 = process(SigningPeer.keys(b, a), 1);
        assertEquals(keysB.signing().id(), r2.sign(m).keyId());
        assertNull(r1.verify(m, r2.sign(m)));
        assertNull(r2.verify(m, r1.sign(m)));
        // a robot that skipped step 1 (only A) cannot read the robot at step 2: why step 1 comes first everywhere
        FleetAuth skipped = process(keysA, 1);
        assertEquals(Problem.UNKNOWN_KEY, problem(skipped.verify(m, r2.sign(m))));
        // step 3: A removed; what A signs is refused from now on
        FleetAuth r3 = process(keysB, 1);
        assertNull(r3.verify(m, r2.sign(m)));
        assertEquals(Problem.UNKNOWN_KEY, problem(r3.verify(m, r1.sign(m))));
    }

    @Test
    void offSignsNothingAndChecksNothing() {
        FleetAuth off = new FleetAuth(() -> wall[0]);
        off.off();
        assertFalse(off.required());
        Signed s = off.sign(tell("x"));
        assertEquals(0, s.mac().length);
        assertEquals("", s.keyId());
        assertEquals(1, s.sequence());
        Signed none = new Signed(0, 0, 0, "", new byte[0]);
        assertNull(off.verify(tell("x"), none));
        assertNull(off.admit(Kind.MESSAGE, ROBOT2, none, 0, () -> new Refusal(Problem.FORGED, "unused")));
        assertNull(off.admit(Kind.MESSAGE, ROBOT2, none, 0, null), "no replay state either");
        assertEquals(Problem.UNAUTHENTICATED, problem(receiver.verify(tell("x"), s)), "a keyed robot refuses it");
    }

    @Test
    void requiredWithoutAKeyRefusesToSignAndAcceptsNothing() {
        FleetAuth nokey = new FleetAuth(() -> wall[0]);
        assertTrue(nokey.required(), "required by default");
        assertThrows(IllegalStateException.class, () -> nokey.sign(tell("x")));
        WireMessage m = tell("x");
        assertEquals(Problem.UNKNOWN_KEY, problem(nokey.verify(m, sender.sign(m))));
    }

    @Test
    void theReplayStateIsBounded() {
        Signed s = new Signed(1, 1, T0, "", new byte[0]);
        for (int i = 0; i < FleetAuth.MAX_SENDERS + 500; i++)
            assertNull(receiver.admit(Kind.MESSAGE, "/r" + i + "/rason_mas", s, i, null));
        assertEquals(FleetAuth.MAX_SENDERS, receiver.sendersKept());
        // the most recently heard are kept
        assertEquals(Problem.REPLAYED, problem(receiver.admit(Kind.MESSAGE, "/r" + (FleetAuth.MAX_SENDERS + 499)
                + "/rason_mas", s, 0, null)));
    }

    @Test
    void sendersSilentForTwiceTheWindowAreForgotten() {
        Signed s = new Signed(1, 1, T0, "", new byte[0]);
        assertNull(receiver.admit(Kind.MESSAGE, "/a/rason_mas", s, 0, null));
        assertNull(receiver.admit(Kind.MESSAGE, "/b/rason_mas", s, 100 * S, null));
        assertEquals(2, receiver.sendersKept(), "a was heard 100 s ago, within twice the 60 s window");
        assertNull(receiver.admit(Kind.MESSAGE, "/c/rason_mas", s, 121 * S, null));
        assertEquals(2, receiver.sendersKept(), "a is forgotten: any copy of its traffic is stale by now");
        assertNull(receiver.admit(Kind.MESSAGE, "/a/rason_mas", s, 122 * S, null));
    }

    private static byte[] flipped(byte[] b, int i) {
        byte[] c = b.clone();
        c[i] ^= 1;
        return c;
    }
}
