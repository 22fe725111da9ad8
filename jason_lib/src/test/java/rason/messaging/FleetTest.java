package rason.messaging;

import rason.core.Clock;
import rason.core.InputLimits;
import rason.core.RateLimitedLog;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.logging.Logger;

import org.junit.jupiter.api.Test;

class FleetTest {

    private final List<String> stops = new ArrayList<>();
    private final Logger logger = Logger.getLogger("test.fleet");
    private final Fleet fleet = new Fleet(logger, SigningPeer.stopsInto(stops), new RateLimitedLog(logger),
            SigningPeer.authWithKeyA(), new InputLimits(), Clock.WALL);

    private void hosting(String masId, long incarnation, String... agents) {
        fleet.setMasId(masId);
        fleet.setIncarnation(incarnation);
        fleet.localAgentsChanged(Set.of(agents));
    }

    @Test
    void theLaterOfTwoProcessesHostingAnAgentInOneNamespaceStopsOnce() {
        hosting("/faulty/rason_mas_2", 200, "faulty");
        SigningPeer first = new SigningPeer("/faulty/rason_mas", 100);
        first.announce(fleet, false, "faulty");
        first.announce(fleet, false, "faulty");
        assertEquals(1, stops.size());
        assertTrue(stops.get(0).contains("'faulty' is already hosted by /faulty/rason_mas"), stops.get(0));
    }

    @Test
    void theEarlierOneGoesOn() {
        hosting("/faulty/rason_mas", 100, "faulty");
        new SigningPeer("/faulty/rason_mas_2", 200).announce(fleet, false, "faulty");
        assertTrue(stops.isEmpty());
    }

    @Test
    void theSameNameInAnotherNamespaceIsAClashNotAStop() {
        hosting("/robot1/rason_mas", 200, "scout");
        new SigningPeer("/robot2/rason_mas", 100).announce(fleet, false, "scout");
        assertTrue(stops.isEmpty());
    }

    @Test
    void namespaces() {
        assertEquals("/robot1", Fleet.namespaceOf("/robot1/rason_mas"));
        assertEquals("/a/b", Fleet.namespaceOf("/a/b/rason_mas"));
        assertEquals("", Fleet.namespaceOf("/rason_mas"));
    }
}
