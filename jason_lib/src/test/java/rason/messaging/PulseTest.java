package rason.messaging;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Set;
import java.util.logging.Logger;

import org.junit.jupiter.api.Test;

import rason.core.RateLimitedLog;

/**
 * A pulse counts only if it is authentic, fresh and published by the process it names: a
 * client without the key, a copy played again or another robot's client cannot hold up a
 * departure with one.
 */
class PulseTest {

    private static final String ME = "/robot1/rason_mas";
    private static final String ROBOT2 = "/robot2/rason_mas";

    private final Logger logger = Logger.getLogger("test.fleet.pulse." + System.identityHashCode(this));
    private final rason.core.RateLimitedLogTest.Lines lines = rason.core.RateLimitedLogTest.Lines.of(logger);
    private final RateLimitedLog limited = new RateLimitedLog(logger, 50, 3_600_000_000_000L);
    private final Fleet fleet = SigningPeer.fleet(logger, limited, ME, FleetAuth.wallNanos() - 1_000_000_000L);
    private final SigningPeer robot2 = new SigningPeer(ROBOT2, FleetAuth.wallNanos() - 2_000_000_000L);

    PulseTest() {
        fleet.setAwayHoldNanos(60_000_000_000L);
    }

    private FleetAuth.Signed announceOverC1() {
        FleetAuth.Signed will = robot2.auth.signWill(ROBOT2, "c1");
        FleetAuth.Signed s = robot2.auth.signPresence(ROBOT2, List.of("bob"), List.of(), List.of(), 0.5f, false, "c1");
        fleet.presenceAnnounced(ROBOT2, new String[] { "bob" }, new String[0], new String[0], false, 0.5f, s, ROBOT2,
                "c1");
        fleet.presenceTickAllLinked();
        return will;
    }

    private String lastLine() {
        List<String> t = lines.texts();
        return t.isEmpty() ? "" : t.get(t.size() - 1);
    }

    @Test
    void anAuthenticPulseHoldsUpTheWillOfAConnectionThatStalled() {
        FleetAuth.Signed will = announceOverC1();
        fleet.pulseArrived(ROBOT2, robot2.auth.signPulse(ROBOT2), ROBOT2);
        fleet.willArrived(ROBOT2, "c1", will, ROBOT2);
        assertEquals(Set.of("bob"), fleet.reachable());
    }

    @Test
    void pulsesThatAreNotAuthenticFreshOrPublishedByTheirProcessCountForNothing() {
        FleetAuth.Signed will = announceOverC1();
        FleetAuth.Signed pulse = robot2.auth.signPulse(ROBOT2);
        fleet.pulseArrived(ROBOT2, new FleetAuth.Signed(pulse.incarnation(), pulse.sequence(), pulse.stamp(),
                pulse.keyId(), new byte[FleetAuth.MAC_BYTES]), ROBOT2);
        assertTrue(lastLine().startsWith("dropped pulse of /robot2/rason_mas: bad mac"), lastLine());
        fleet.pulseArrived(ROBOT2, pulse, "/robot3/rason_mas");
        assertTrue(lastLine().contains("forged"), lastLine());
        FleetAuth.Signed presenceMac = robot2.auth.signPresence(ROBOT2, List.of(), 0.5f, false);
        fleet.pulseArrived(ROBOT2, presenceMac, ROBOT2);
        assertTrue(lastLine().contains("bad mac"), "a presence's MAC is no pulse's: " + lastLine());
        fleet.pulseArrived(ROBOT2, new FleetAuth.Signed(pulse.incarnation(), pulse.sequence(), pulse.stamp(), "", new byte[0]),
                ROBOT2);
        assertTrue(lastLine().contains("unauthenticated"), lastLine());
        fleet.willArrived(ROBOT2, "c1", will, ROBOT2);
        assertEquals(Set.of(), fleet.reachable(), "no pulse counted: the will is a departure at once");
    }

    @Test
    void aPulsePlayedAgainIsReplayed() {
        announceOverC1();
        FleetAuth.Signed pulse = robot2.auth.signPulse(ROBOT2);
        fleet.pulseArrived(ROBOT2, pulse, ROBOT2);
        fleet.pulseArrived(ROBOT2, pulse, ROBOT2);
        assertTrue(lastLine().contains("replayed"), lastLine());
    }

    @Test
    void pulsesHaveTheirOwnSequenceApartFromPresenceAndMessages() {
        announceOverC1();
        fleet.pulseArrived(ROBOT2, robot2.auth.signPulse(ROBOT2), ROBOT2);
        fleet.pulseArrived(ROBOT2, robot2.auth.signPulse(ROBOT2), ROBOT2);
        int before = lines.texts().size();
        robot2.announce(fleet, false, "bob"); // its second presence after two pulses
        fleet.presenceTickAllLinked();
        assertEquals(before, lines.texts().size(), String.valueOf(lines.texts()));
        assertEquals(Set.of("bob"), fleet.reachable());
    }
}
