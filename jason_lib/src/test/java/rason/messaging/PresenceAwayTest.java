package rason.messaging;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Set;

import org.junit.jupiter.api.Test;

/**
 * A peer that goes silent, or whose broker connection ends, is gone from present/1 at once but
 * stays a place to send to for the hold (its broker session keeps what is sent): it owes what
 * was sent to it until it comes back, restarts, leaves for good, or the hold passes.
 */
class PresenceAwayTest {

    private static final long S = 1_000_000_000L;
    private static final long TIMEOUT = 2 * S;
    private static final String R2 = "/r2/rason_mas";
    private final PresenceTable t = new PresenceTable();

    PresenceAwayTest() {
        t.setAwayHoldNanos(60 * S);
        t.announced(R2, 7, List.of("bob"), false, 0);
        t.tick(List.of(R2), 0, TIMEOUT);
    }

    private PresenceTable.Changes silentUntil(long now) {
        return t.tick(List.of(R2), now, TIMEOUT);
    }

    @Test
    void aSilentPeerLeavesPresenceButStaysSendableAndOwesNothingYet() {
        PresenceTable.Changes c = silentUntil(3 * S);
        assertEquals(Set.of("bob"), Set.copyOf(c.left));
        assertTrue(c.lost.isEmpty(), "nothing is lost yet: " + c.lost);
        assertTrue(t.reachable().isEmpty());
        assertEquals(R2, t.sendableMasOf("bob"));
    }

    @Test
    void comingBackInTheSameRunLosesNothing() {
        silentUntil(3 * S);
        assertTrue(t.announced(R2, 7, List.of("bob"), false, 4 * S).lost.isEmpty());
        assertEquals(Set.of("bob"), Set.copyOf(t.tick(List.of(R2), 4 * S, TIMEOUT).joined));
    }

    @Test
    void comingBackRestartedLosesWhatTheEarlierRunOwed() {
        silentUntil(3 * S);
        assertEquals(Set.of("bob"), t.announced(R2, 8, List.of("bob"), false, 4 * S).lost);
    }

    @Test
    void aMessageBeforeItsAnnouncementBringsItBackAndASecondSilenceStillLosesNothing() {
        // after a cut, a robot's broker may flush its queued messages before its presence
        silentUntil(3 * S);
        assertTrue(t.messageFrom(R2, "bob", 9 * S).lost.isEmpty());
        assertEquals(R2, t.sendableMasOf("bob"));
        assertTrue(silentUntil(12 * S).lost.isEmpty(), "silent again: what was sent to it stays owed");
        assertEquals(R2, t.sendableMasOf("bob"));
        assertTrue(t.announced(R2, 7, List.of("bob"), false, 13 * S).lost.isEmpty(), "the same run: nothing lost");
        assertEquals(Set.of("bob"), t.announced(R2, 8, List.of("bob"), false, 14 * S).lost, "a new run: lost");
    }

    @Test
    void leavingForGoodLosesIt() {
        silentUntil(3 * S);
        assertEquals(Set.of("bob"), t.announced(R2, 7, List.of(), true, 4 * S).lost);
        assertNull(t.sendableMasOf("bob"));
    }

    @Test
    void afterTheHoldItIsLost() {
        silentUntil(3 * S);
        assertTrue(silentUntil(63 * S).lost.isEmpty());
        assertEquals(Set.of("bob"), silentUntil(63 * S + 1).lost);
        assertNull(t.sendableMasOf("bob"));
    }

    @Test
    void anEndedConnectionCountsAsAway() {
        PresenceTable.Changes c = t.connectionEnded(R2, 7, S);
        assertEquals(Set.of("bob"), Set.copyOf(c.left));
        assertTrue(c.lost.isEmpty());
        assertEquals(R2, t.sendableMasOf("bob"));
        assertTrue(t.connectionEnded(R2, 6, S).left.isEmpty(), "the end of an earlier run's connection");
    }

    @Test
    void withoutAHoldSilenceLosesAtOnce() {
        t.setAwayHoldNanos(0);
        assertEquals(Set.of("bob"), silentUntil(3 * S).lost);
        assertNull(t.sendableMasOf("bob"));
    }
}
