package rason.messaging;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Set;
import java.util.logging.Logger;

import org.junit.jupiter.api.Test;

import rason.core.RateLimitedLog;

/**
 * A channel's last will makes its process leave only if it names the connection that
 * process's current run last announced itself over: a copy of an earlier connection's
 * will, or one without a valid MAC, changes nothing.
 */
class LastWillTest {

    private static final String ME = "/robot1/rason_mas";
    private static final String ROBOT2 = "/robot2/rason_mas";

    private final Logger logger = Logger.getLogger("test.fleet.will." + System.identityHashCode(this));
    private final rason.core.RateLimitedLogTest.Lines lines = rason.core.RateLimitedLogTest.Lines.of(logger);
    private final RateLimitedLog limited = new RateLimitedLog(logger, 50, 3_600_000_000_000L);
    private final Fleet fleet = SigningPeer.fleet(logger, limited, ME, FleetAuth.wallNanos() - 1_000_000_000L);
    private final SigningPeer robot2 = new SigningPeer(ROBOT2, FleetAuth.wallNanos() - 2_000_000_000L);

    /** robot2 announces bob over its connection named link. */
    private void announceOver(String link) {
        FleetAuth.Signed s = robot2.auth.signPresence(ROBOT2, List.of("bob"), List.of(), List.of(), 0.5f, false, link);
        fleet.presenceAnnounced(ROBOT2, new String[] { "bob" }, new String[0], new String[0], false, 0.5f, s, ROBOT2,
                link);
        fleet.presenceTickAllLinked();
    }

    private String lastLine() {
        List<String> t = lines.texts();
        return t.isEmpty() ? "" : t.get(t.size() - 1);
    }

    @Test
    void theWillOfTheCurrentConnectionMakesTheRobotLeave() {
        FleetAuth.Signed will = robot2.auth.signWill(ROBOT2, "c1"); // signed at connect, before the presence
        announceOver("c1");
        announceOver("c1");
        assertEquals(Set.of("bob"), fleet.reachable());
        fleet.willArrived(ROBOT2, "c1", will, ROBOT2);
        assertEquals(Set.of(), fleet.reachable());
    }

    @Test
    void theWillOfARobotThatLeftOrIsUnknownIsIgnoredWithoutALine() {
        FleetAuth.Signed will = robot2.auth.signWill(ROBOT2, "c1");
        announceOver("c1");
        robot2.announce(fleet, true, "bob");
        int before = lines.texts().size();
        fleet.willArrived(ROBOT2, "c1", will, ROBOT2); // the broker's retained will, heard after the leaving
        fleet.willArrived("/robot7/rason_mas", "c7", new SigningPeer("/robot7/rason_mas", 1).auth
                .signWill("/robot7/rason_mas", "c7"), "/robot7/rason_mas");
        assertEquals(before, lines.texts().size(), String.valueOf(lines.texts()));
        assertEquals(Set.of(), fleet.reachable());
    }

    @Test
    void aCopyOfAnEarlierConnectionsWillChangesNothing() {
        FleetAuth.Signed first = robot2.auth.signWill(ROBOT2, "c1");
        announceOver("c1");
        robot2.auth.signWill(ROBOT2, "c2"); // reconnected: a new link and will
        announceOver("c2");
        fleet.willArrived(ROBOT2, "c1", first, ROBOT2);
        assertEquals(Set.of("bob"), fleet.reachable());
        assertTrue(lastLine().startsWith("dropped last will of /robot2/rason_mas: replayed: the will of connection c1"),
                lastLine());
    }

    @Test
    void aWillWithoutAValidMacOrOnAnotherRobotsTopicChangesNothing() {
        FleetAuth.Signed will = robot2.auth.signWill(ROBOT2, "c1");
        announceOver("c1");
        fleet.willArrived(ROBOT2, "c1", new FleetAuth.Signed(will.incarnation(), 0, will.stamp(), will.keyId(),
                new byte[FleetAuth.MAC_BYTES]), ROBOT2);
        assertTrue(lastLine().contains("bad mac"), lastLine());
        fleet.willArrived(ROBOT2, "c2", will, ROBOT2);
        assertTrue(lastLine().contains("bad mac"), "the mac covers the link: " + lastLine());
        fleet.willArrived(ROBOT2, "c1", will, "/robot3/rason_mas");
        assertTrue(lastLine().contains("forged"), lastLine());
        assertEquals(Set.of("bob"), fleet.reachable());
    }

    @Test
    void aPresenceWhoseLinkWasAlteredIsNotAuthentic() {
        FleetAuth.Signed s = robot2.auth.signPresence(ROBOT2, List.of("bob"), List.of(), List.of(), 0.5f, false, "c1");
        fleet.presenceAnnounced(ROBOT2, new String[] { "bob" }, new String[0], new String[0], false, 0.5f, s, ROBOT2,
                "c9");
        fleet.presenceTickAllLinked();
        assertEquals(Set.of(), fleet.reachable());
        assertTrue(lastLine().contains("bad mac"), lastLine());
    }
}
