package rason.messaging;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Set;

import org.junit.jupiter.api.Test;

/**
 * Pulses come over a connection of their own: they keep a peer present while its other
 * connection (messages, presence, will) stalls, bring back a peer that went away, and make a
 * last will wait for the pulses to stop; they never introduce a peer or speak for another run.
 */
class PresencePulseTest {

    private static final long S = 1_000_000_000L;
    private static final long TIMEOUT = 2 * S;
    private static final String R2 = "/r2/rason_mas";
    private final PresenceTable t = new PresenceTable();

    PresencePulseTest() {
        t.setAwayHoldNanos(60 * S);
        t.setPulseGraceNanos(S);
        t.announced(R2, 7, List.of("bob"), false, 0);
        t.tick(List.of(R2), 0, TIMEOUT);
    }

    private PresenceTable.Changes tick(double seconds) {
        return t.tick(List.of(R2), (long) (seconds * S), TIMEOUT);
    }

    private void pulse(double seconds) {
        t.pulse(R2, 7, (long) (seconds * S));
    }

    @Test
    void pulsesKeepAPeerPresentWhileItsOtherConnectionIsSilent() {
        for (double s = 0.5; s <= 5; s += 0.5) {
            pulse(s);
            assertTrue(tick(s + 0.25).left.isEmpty(), "at " + s);
        }
        assertEquals(Set.of("bob"), t.reachable());
        assertEquals(Set.of("bob"), Set.copyOf(tick(7.1).left), "no pulse since 5 s: silent for the timeout");
    }

    @Test
    void aWillWhilePulsesComeIsNoDeparture() {
        pulse(2.8);
        assertTrue(t.connectionEnded(R2, 7, 3 * S).left.isEmpty());
        pulse(3.3);
        assertTrue(tick(4.2).left.isEmpty());
        assertEquals(Set.of("bob"), t.reachable());
    }

    @Test
    void aWillIsADepartureOnceThePulsesStop() {
        pulse(2.8);
        t.connectionEnded(R2, 7, 3 * S);
        assertTrue(tick(3.75).left.isEmpty(), "the last pulse is 0.95 s old: within the grace");
        PresenceTable.Changes c = tick(3.85);
        assertEquals(Set.of("bob"), Set.copyOf(c.left), "the last pulse is 1.05 s old");
        assertTrue(c.events.stream().anyMatch(e -> e.contains("its connection ended and its pulse stopped")), c.events.toString());
        assertEquals(R2, t.sendableMasOf("bob"), "away, as after a will: what was sent may still arrive");
    }

    @Test
    void aWillAfterThePulsesStoppedIsADepartureAtOnce() {
        pulse(1);
        assertEquals(Set.of("bob"), Set.copyOf(t.connectionEnded(R2, 7, (long) (2.1 * S)).left));
    }

    @Test
    void aPeerNeverPulsingDepartsOnItsWillAtOnce() {
        assertEquals(Set.of("bob"), Set.copyOf(t.connectionEnded(R2, 7, S / 10).left));
    }

    @Test
    void aPresenceOverItsNewConnectionEndsTheWaitForThePulses() {
        pulse(2.8);
        t.connectionEnded(R2, 7, 3 * S);
        t.announced(R2, 7, List.of("bob"), false, (long) (3.2 * S)); // reconnected
        assertTrue(tick(4.5).left.isEmpty(), "heard at 3.2 s, and its connection is back");
    }

    @Test
    void aPulseBringsBackAPeerThatWentAway() {
        assertEquals(Set.of("bob"), Set.copyOf(tick(2.1).left));
        t.pulse(R2, 7, (long) (2.2 * S));
        assertEquals(Set.of("bob"), t.reachable());
        assertTrue(tick(2.3).joined.isEmpty(), "joined when the pulse came, not again");
    }

    @Test
    void aPulseIntroducesNobodyAndSpeaksOnlyForItsOwnRun() {
        PresenceTable.Changes c = t.pulse("/r3/rason_mas", 1, S);
        assertTrue(c.joined.isEmpty() && c.events.isEmpty());
        t.pulse(R2, 6, S); // an earlier run's
        assertEquals(Set.of("bob"), Set.copyOf(tick(2.1).left), "the other run's pulse kept nothing");
        assertTrue(t.pulse(R2, 8, (long) (2.2 * S)).joined.isEmpty(), "nor brings back another run");
    }

    @Test
    void aRestartedPeersWillIsNotHeldByTheEarlierRunsPulse() {
        pulse(1);
        t.announced(R2, 8, List.of("bob"), false, (long) (1.1 * S));
        assertEquals(Set.of("bob"), Set.copyOf(t.connectionEnded(R2, 8, (long) (1.2 * S)).left));
    }
}
