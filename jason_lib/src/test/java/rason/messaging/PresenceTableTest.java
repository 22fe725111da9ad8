package rason.messaging;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Collection;
import java.util.List;

import org.junit.jupiter.api.Test;

class PresenceTableTest {

    private static final long S = 1_000_000_000L;
    private static final long TIMEOUT = 2 * S;
    private static final String R2 = "/r2/rason_mas";
    private static final String R3 = "/r3/rason_mas";

    private static List<String> sorted(Collection<String> names) {
        List<String> out = new ArrayList<>(names);
        out.sort(null);
        return out;
    }

    private static List<String> names(PresenceTable t) {
        return sorted(t.reachable());
    }

    private static void assertChanged(List<String> joined, List<String> left, PresenceTable.Changes c) {
        assertEquals(joined, sorted(c.joined), "joined");
        assertEquals(left, sorted(c.left), "left");
    }

    /** mas announces agents and is linked, at now. */
    private static PresenceTable.Changes joined(PresenceTable t, String mas, List<String> agents, long now, long incarnation) {
        t.announced(mas, incarnation, agents, false, now);
        return t.tick(List.of(mas), now, TIMEOUT);
    }

    private static PresenceTable.Changes joined(PresenceTable t, String mas, List<String> agents) {
        return joined(t, mas, agents, 0, 1);
    }

    private static boolean anyContains(Collection<String> lines, String part) {
        return lines.stream().anyMatch(l -> l.contains(part));
    }

    @Test
    void announcedAgentIsReachableOnlyOnceLinked() {
        PresenceTable t = new PresenceTable();
        PresenceTable.Changes c = t.announced(R2, 1, List.of("bob"), false, 0);
        assertChanged(List.of(), List.of(), c);
        assertNull(t.masOf("bob")); // heard is not connected
        assertEquals(R2, t.sendableMasOf("bob")); // a message may wait for the link
        c = t.tick(List.of(R2), 1, TIMEOUT);
        assertChanged(List.of("bob"), List.of(), c);
        assertEquals(R2, t.masOf("bob"));
        assertEquals(List.of("bob"), names(t));
    }

    @Test
    void linkedPeersCountsTheProcessesReachableNow() {
        PresenceTable t = new PresenceTable();
        assertEquals(0, t.linkedPeers());
        t.announced(R2, 1, List.of("bob"), false, 0);
        assertEquals(0, t.linkedPeers(), "heard of, not linked");
        joined(t, R3, List.of("carol"), 0, 1);
        t.tick(List.of(R2, R3), 0, TIMEOUT);
        assertEquals(2, t.linkedPeers());
        t.announced(R2, 1, List.of("bob"), true, S);
        assertEquals(1, t.linkedPeers(), "R2 left");
    }

    @Test
    void silentPeerLeavesAfterTheTimeoutAndItsAgentsAreLost() {
        PresenceTable t = new PresenceTable();
        joined(t, R2, List.of("bob", "bea"));
        PresenceTable.Changes c = t.tick(List.of(R2), TIMEOUT, TIMEOUT);
        assertChanged(List.of(), List.of(), c); // exactly the timeout: still there
        c = t.tick(List.of(R2), TIMEOUT + 1, TIMEOUT);
        assertChanged(List.of(), List.of("bea", "bob"), c);
        assertEquals(List.of("bea", "bob"), sorted(c.lost));
        assertNull(t.masOf("bob"));
        assertTrue(t.whyUnreachable("bob").contains("has left"), t.whyUnreachable("bob"));
        assertTrue(t.whyUnreachable("bob").contains("not heard for 2.0 s"), t.whyUnreachable("bob"));
    }

    @Test
    void announcementsKeepAPeerPresent() {
        PresenceTable t = new PresenceTable();
        joined(t, R2, List.of("bob"));
        for (int k = 1; k < 10; k++) {
            t.announced(R2, 1, List.of("bob"), false, k * S);
            assertChanged(List.of(), List.of(), t.tick(List.of(R2), k * S + S / 2, TIMEOUT));
        }
        assertEquals(List.of("bob"), names(t));
    }

    @Test
    void leavingAnnouncementRemovesAtOnce() {
        PresenceTable t = new PresenceTable();
        joined(t, R2, List.of("bob"));
        PresenceTable.Changes c = t.announced(R2, 1, List.of("bob"), true, S);
        assertChanged(List.of(), List.of("bob"), c);
        assertTrue(t.whyUnreachable("bob").contains("announced it is leaving"), t.whyUnreachable("bob"));
    }

    @Test
    void lostLinkMakesAgentsUnreachableUntilItIsBack() {
        PresenceTable t = new PresenceTable();
        joined(t, R2, List.of("bob"));
        assertChanged(List.of(), List.of("bob"), t.tick(List.of(), S / 2, TIMEOUT));
        assertNull(t.sendableMasOf("bob")); // a send would be lost: it fails instead
        assertTrue(t.whyUnreachable("bob").contains("connection to its process is down"), t.whyUnreachable("bob"));
        assertChanged(List.of("bob"), List.of(), t.tick(List.of(R2), S, TIMEOUT));
        assertEquals(R2, t.sendableMasOf("bob"));
    }

    @Test
    void restartWithinTheTimeoutLosesPendingAnswersButStaysPresent() {
        PresenceTable t = new PresenceTable();
        joined(t, R2, List.of("bob"), 0, 100);
        PresenceTable.Changes c = t.announced(R2, 200, List.of("bob"), false, S);
        assertEquals(List.of("bob"), sorted(c.lost));
        assertTrue(anyContains(c.events, "restarted"), c.events.toString());
        assertEquals(List.of("bob"), names(t));
    }

    @Test
    void restartAfterDepartureIsANewJoin() {
        PresenceTable t = new PresenceTable();
        joined(t, R2, List.of("bob"), 0, 100);
        t.tick(List.of(), 3 * S, TIMEOUT);
        assertEquals(List.of(), names(t));
        PresenceTable.Changes c = joined(t, R2, List.of("bob"), 4 * S, 200);
        assertChanged(List.of("bob"), List.of(), c);
    }

    @Test
    void staleAnnouncementOfAnEarlierRunIsIgnored() {
        PresenceTable t = new PresenceTable();
        joined(t, R2, List.of("bob"), 0, 200);
        PresenceTable.Changes c = t.announced(R2, 100, List.of("bob"), true, S);
        assertTrue(c.isEmpty());
        assertEquals(List.of("bob"), names(t));
    }

    @Test
    void messageBeforeAnnouncementCountsAsPresence() {
        PresenceTable t = new PresenceTable();
        t.messageFrom(R2, "bob", 0);
        t.tick(List.of(R2), 1, TIMEOUT);
        assertEquals(List.of("bob"), names(t));
        // its announcement then brings the full list, and is not taken for a restart
        PresenceTable.Changes c = t.announced(R2, 7, List.of("bob", "bea"), false, 2);
        assertEquals(0, c.lost.size());
        t.tick(List.of(R2), 3, TIMEOUT);
        assertEquals(List.of("bea", "bob"), names(t));
    }

    @Test
    void agentListFollowsTheAnnouncements() {
        PresenceTable t = new PresenceTable();
        joined(t, R2, List.of("bob", "bea"));
        t.announced(R2, 1, List.of("bob"), false, 1);
        assertChanged(List.of(), List.of(), t.tick(List.of(R2), 2, TIMEOUT));
        assertEquals(List.of("bob"), names(t));
    }

    @Test
    void clashWithALocalAgentIsReportedOnceAndTheNameStaysLocal() {
        PresenceTable t = new PresenceTable();
        t.setLocal(List.of("alice"));
        PresenceTable.Changes c = t.announced(R2, 1, List.of("alice", "bob"), false, 0);
        assertEquals(1, c.clashes.size());
        assertTrue(c.clashes.get(0).contains("hosted here and also announced by " + R2), c.clashes.get(0));
        assertTrue(c.clashes.get(0).contains("agent_prefix"), c.clashes.get(0));
        t.tick(List.of(R2), 1, TIMEOUT);
        assertNull(t.masOf("alice"));
        assertEquals(List.of("bob"), names(t));
        c = t.announced(R2, 1, List.of("alice", "bob"), false, 2);
        assertEquals(0, c.clashes.size()); // once
    }

    @Test
    void clashBetweenTwoPeersKeepsTheFirstClaimer() {
        PresenceTable t = new PresenceTable();
        joined(t, R2, List.of("bob"));
        PresenceTable.Changes c = t.announced(R3, 1, List.of("bob", "carl"), false, 1);
        assertEquals(1, c.clashes.size());
        assertTrue(c.clashes.get(0).contains("both " + R2 + " and " + R3), c.clashes.get(0));
        t.tick(List.of(R2, R3), 2, TIMEOUT);
        assertEquals(R2, t.masOf("bob"));
        // when the first claimer leaves, the other one gets the name
        t.announced(R2, 1, List.of(), true, 3);
        assertEquals(R3, t.masOf("bob"));
    }

    @Test
    void unknownAgentHasAReason() {
        PresenceTable t = new PresenceTable();
        assertTrue(t.whyUnreachable("nobody").contains("no agent"), t.whyUnreachable("nobody"));
    }

    // ---- beyond the cases ported from Python --------------------------------------

    @Test
    void restartWithAnotherAgentListSwapsTheAgents() {
        PresenceTable t = new PresenceTable();
        joined(t, R2, List.of("bob"), 0, 100);
        PresenceTable.Changes c = t.announced(R2, 200, List.of("bea"), false, S);
        assertChanged(List.of("bea"), List.of("bob"), c);
        assertEquals(List.of("bob"), sorted(c.lost));
        assertNull(t.sendableMasOf("bob"));
    }

    @Test
    void staleAnnouncementNeitherChangesTheAgentsNorKeepsThePeerAlive() {
        PresenceTable t = new PresenceTable();
        joined(t, R2, List.of("bob"), 0, 200);
        assertTrue(t.announced(R2, 100, List.of("carl"), false, 3 * S / 2).isEmpty());
        assertEquals(List.of("bob"), names(t));
        assertNull(t.sendableMasOf("carl"));
        assertChanged(List.of(), List.of("bob"), t.tick(List.of(R2), 5 * S / 2, TIMEOUT)); // last heard at 0
    }

    @Test
    void leavingAnnouncementOfAnUnknownPeerChangesNothing() {
        PresenceTable t = new PresenceTable();
        joined(t, R2, List.of("bob"));
        assertTrue(t.announced(R3, 1, List.of("carl"), true, S).isEmpty());
        assertEquals(List.of(R2), t.peerIds());
        assertEquals(List.of("bob"), names(t));
    }

    @Test
    void peerKnownOnlyFromAMessageCanLeave() {
        PresenceTable t = new PresenceTable();
        t.messageFrom(R2, "bob", 0);
        t.tick(List.of(R2), 1, TIMEOUT);
        PresenceTable.Changes c = t.announced(R2, 5, List.of(), true, 2);
        assertChanged(List.of(), List.of("bob"), c);
        assertEquals(List.of("bob"), sorted(c.lost));
        assertTrue(t.whyUnreachable("bob").contains("announced it is leaving"), t.whyUnreachable("bob"));
    }

    @Test
    void messageFromAKnownAgentKeepsItsPeerPresentAndChangesNothingElse() {
        PresenceTable t = new PresenceTable();
        joined(t, R2, List.of("bob"));
        assertTrue(t.messageFrom(R2, "bob", 3 * S / 2).isEmpty());
        assertChanged(List.of(), List.of(), t.tick(List.of(R2), 3 * S, TIMEOUT));
        assertEquals(List.of("bob"), names(t));
        assertChanged(List.of(), List.of("bob"), t.tick(List.of(R2), 7 * S / 2 + 1, TIMEOUT));
    }

    @Test
    void messageFromANewAgentOfALinkedPeerMakesItReachableAtOnce() {
        PresenceTable t = new PresenceTable();
        joined(t, R2, List.of("bob"));
        PresenceTable.Changes c = t.messageFrom(R2, "bea", 1);
        assertChanged(List.of("bea"), List.of(), c);
        assertEquals(R2, t.masOf("bea"));
    }

    @Test
    void aNameTakenLocallyLaterIsNoLongerRemoteUntilFreedAgain() {
        PresenceTable t = new PresenceTable();
        joined(t, R2, List.of("bob"));
        PresenceTable.Changes c = t.setLocal(List.of("bob"));
        assertChanged(List.of(), List.of("bob"), c);
        assertEquals(1, c.clashes.size());
        assertTrue(c.clashes.get(0).contains("hosted here"), c.clashes.get(0));
        assertNull(t.masOf("bob"));
        c = t.setLocal(List.of());
        assertChanged(List.of("bob"), List.of(), c);
        assertEquals(R2, t.masOf("bob"));
    }

    @Test
    void clashBetweenTwoPeersIsReportedOnce() {
        PresenceTable t = new PresenceTable();
        joined(t, R2, List.of("bob"));
        assertEquals(1, t.announced(R3, 1, List.of("bob"), false, 1).clashes.size());
        assertEquals(0, t.announced(R3, 1, List.of("bob"), false, 2).clashes.size());
        assertEquals(0, t.tick(List.of(R2, R3), 3, TIMEOUT).clashes.size());
    }

    @Test
    void aLostLinkIsNotADeparture() {
        PresenceTable t = new PresenceTable();
        joined(t, R2, List.of("bob"));
        PresenceTable.Changes c = t.tick(List.of(), S / 2, TIMEOUT);
        assertEquals(List.of("bob"), sorted(c.left));
        assertTrue(c.lost.isEmpty()); // the process may still answer once the link is back
        assertTrue(c.events.isEmpty());
        assertEquals(List.of(R2), t.peerIds());
    }

    @Test
    void peerThatLeftIsForgotten() {
        PresenceTable t = new PresenceTable();
        joined(t, R2, List.of("bob"));
        PresenceTable.Changes c = t.tick(List.of(R2), 3 * S, TIMEOUT);
        assertTrue(anyContains(c.events, R2 + " left: not heard for 3.0 s"), c.events.toString());
        assertEquals(List.of(), t.peerIds());
        assertNull(t.sendableMasOf("bob"));
    }

    @Test
    void joinsAreReportedAsEvents() {
        PresenceTable t = new PresenceTable();
        PresenceTable.Changes c = t.announced(R2, 1, List.of("bob"), false, 0);
        assertEquals(List.of(R2 + " joined with [bob]"), c.events);
        c = t.messageFrom(R3, "carl", 0);
        assertEquals(1, c.events.size());
        assertTrue(c.events.get(0).startsWith(R3 + " heard from (message from carl)"), c.events.get(0));
    }

    @Test
    void reachabilityChangedOnlyWhenAnAgentJoinsOrLeaves() {
        PresenceTable t = new PresenceTable();
        PresenceTable.Changes c = t.announced(R2, 1, List.of("bob"), false, 0);
        assertFalse(c.reachabilityChanged());
        assertFalse(c.isEmpty()); // the join event
        assertTrue(t.tick(List.of(R2), 1, TIMEOUT).reachabilityChanged());
        assertFalse(t.tick(List.of(R2), 2, TIMEOUT).reachabilityChanged());
        assertTrue(t.tick(List.of(), 3, TIMEOUT).reachabilityChanged());
    }
}
