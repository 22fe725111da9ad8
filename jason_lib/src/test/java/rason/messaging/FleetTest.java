package rason.messaging;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import java.util.Set;
import java.util.logging.Logger;

import org.junit.jupiter.api.Test;

class FleetTest {

    private final List<String> stops = new ArrayList<>();
    private final Fleet fleet = new Fleet(Logger.getLogger("test.fleet"), new Fleet.Listener() {
        @Override
        public void reachableChanged() {
        }

        @Override
        public void receiversLost(Collection<String> names) {
        }

        @Override
        public void mustStop(String why) {
            stops.add(why);
        }
    });

    private void hosting(String masId, long incarnation, String... agents) {
        fleet.setMasId(masId);
        fleet.setIncarnation(incarnation);
        fleet.localAgentsChanged(Set.of(agents));
    }

    @Test
    void theLaterOfTwoProcessesHostingAnAgentInOneNamespaceStopsOnce() {
        hosting("/faulty/rason_mas_2", 200, "faulty");
        fleet.presenceAnnounced("/faulty/rason_mas", 100, new String[] { "faulty" }, false);
        fleet.presenceAnnounced("/faulty/rason_mas", 100, new String[] { "faulty" }, false);
        assertEquals(1, stops.size());
        assertTrue(stops.get(0).contains("'faulty' is already hosted by /faulty/rason_mas"), stops.get(0));
    }

    @Test
    void theEarlierOneGoesOn() {
        hosting("/faulty/rason_mas", 100, "faulty");
        fleet.presenceAnnounced("/faulty/rason_mas_2", 200, new String[] { "faulty" }, false);
        assertTrue(stops.isEmpty());
    }

    @Test
    void theSameNameInAnotherNamespaceIsAClashNotAStop() {
        hosting("/robot1/rason_mas", 200, "scout");
        fleet.presenceAnnounced("/robot2/rason_mas", 100, new String[] { "scout" }, false);
        assertTrue(stops.isEmpty());
    }

    @Test
    void namespaces() {
        assertEquals("/robot1", Fleet.namespaceOf("/robot1/rason_mas"));
        assertEquals("/a/b", Fleet.namespaceOf("/a/b/rason_mas"));
        assertEquals("", Fleet.namespaceOf("/rason_mas"));
    }
}
