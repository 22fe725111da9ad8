package rason.messaging;

import rason.core.Clock;
import rason.core.InputLimits;
import rason.core.RateLimitedLog;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.logging.Logger;

import org.junit.jupiter.api.Test;

import rason.messaging.FleetDirectory.Entry;
import rason.messaging.FleetDirectory.Notice;

/** The directory facilitator over the fleet: what counts, what subscribers hear, what announcements are taken. */
class FleetDirectoryTest {

    private static final String R2 = "/robot2/rason_mas", R3 = "/robot3/rason_mas";

    private final Map<String, String> owners = new HashMap<>(); // remote agent -> its process
    private final List<Notice> heard = new ArrayList<>();
    private final FleetDirectory df = new FleetDirectory(owners::get, heard::addAll);

    private static Notice told(String subscriber, String provider, String service) {
        return new Notice(subscriber, true, provider, service);
    }

    private static Notice untold(String subscriber, String provider, String service) {
        return new Notice(subscriber, false, provider, service);
    }

    @Test
    void localRegistrationsAreFoundAndSubscribersHearOfEachOneThatComesOrGoes() {
        assertTrue(df.register("p1", "paint"));
        assertFalse(df.register("p1", "paint"), "registering twice changes nothing");
        df.register("p2", "weld");
        assertEquals(List.of("p1"), df.search("paint"));
        df.subscribe("boss", "paint");
        assertEquals(List.of(told("boss", "p1", "paint")), heard, "the present providers first, as in Jason");
        heard.clear();
        df.register("p3", "paint");
        df.register("p3", "weld"); // not boss's service
        assertTrue(df.deregister("p1", "paint"));
        assertFalse(df.deregister("p1", "paint"));
        assertEquals(List.of(told("boss", "p3", "paint"), untold("boss", "p1", "paint")), heard);
        assertEquals(List.of("p3"), df.search("paint"));
        assertEquals(List.of("p2", "p3"), df.search("weld"));
        assertEquals(Map.of("p2", Set.of("weld"), "p3", Set.of("paint", "weld")), df.byAgent());
    }

    @Test
    void aStoppedAgentLeavesTheDirectoryAndHearsNoMore() {
        df.register("p1", "paint");
        df.subscribe("boss", "paint");
        df.subscribe("p1", "paint");
        heard.clear();
        assertTrue(df.agentGone("p1"));
        assertEquals(List.of(untold("boss", "p1", "paint")), heard);
        heard.clear();
        df.register("p2", "paint");
        assertEquals(List.of(told("boss", "p2", "paint")), heard, "p1's subscription went with it");
    }

    @Test
    void ourRegistrationsAreAnnouncedAsParallelArrays() {
        df.register("p2", "weld");
        df.register("p1", "paint");
        df.register("p1", "weld");
        FleetDirectory.Announced a = df.announced();
        assertEquals(List.of("p1", "p1", "p2"), List.of(a.agents()));
        assertEquals(List.of("paint", "weld", "weld"), List.of(a.services()));
    }

    @Test
    void aRemoteRegistrationCountsWhileItsAgentIsReachedThroughTheProcessThatAnnouncedIt() {
        df.subscribe("boss", "paint");
        owners.put("bob", R2);
        df.remote(R2, List.of(new Entry("bob", "paint")));
        df.register("p1", "paint");
        assertEquals(List.of("bob", "p1"), df.search("paint"), "merged with ours");
        assertEquals(List.of(told("boss", "bob", "paint"), told("boss", "p1", "paint")), heard);
        heard.clear();
        // robot3 announces a bob too (a clash): robot2 keeps the name, robot3's registration does not count
        df.remote(R3, List.of(new Entry("bob", "weld")));
        assertEquals(List.of(), df.search("weld"));
        // robot2 leaves: its bob goes, robot3's takes over the name
        owners.put("bob", R3);
        df.fleetChanged(List.of(R2));
        assertEquals(List.of("p1"), df.search("paint"));
        assertEquals(List.of("bob"), df.search("weld"));
        assertEquals(List.of(untold("boss", "bob", "paint")), heard);
    }

    @Test
    void anAnnouncementReplacesWhatItsProcessAnnouncedBefore() {
        df.subscribe("boss", "paint");
        owners.put("bob", R2);
        owners.put("dave", R2);
        df.remote(R2, List.of(new Entry("bob", "paint"), new Entry("dave", "paint")));
        heard.clear();
        df.remote(R2, List.of(new Entry("dave", "paint")));
        assertEquals(List.of(untold("boss", "bob", "paint")), heard);
        df.remote(R2, List.of());
        assertEquals(List.of(), df.search("paint"));
        heard.clear();
        df.remote(R2, List.of());
        df.fleetChanged(List.of());
        assertEquals(List.of(), heard, "nothing changed, nothing said");
    }

    @Test
    void aProcessThatBecomesUnreachableTakesItsRegistrationsAlong() {
        df.subscribe("boss", "paint");
        owners.put("bob", R2);
        df.remote(R2, List.of(new Entry("bob", "paint")));
        owners.remove("bob"); // its link went down
        df.fleetChanged(List.of());
        assertEquals(List.of(), df.search("paint"));
        owners.put("bob", R2); // back
        df.fleetChanged(List.of());
        assertEquals(List.of(told("boss", "bob", "paint"), untold("boss", "bob", "paint"), told("boss", "bob", "paint")),
                heard);
    }

    @Test
    void onlyWellFormedRegistrationsOfAnnouncedAgentsAreTaken() {
        List<String> why = new ArrayList<>();
        List<Entry> ok = FleetDirectory.valid(List.of("bob", "dave"),
                new String[] { "bob", "mallory", "dave", "dave" },
                new String[] { "paint", "paint", "", "x".repeat(FleetDirectory.MAX_SERVICE_LENGTH + 1) },
                (entry, reason) -> why.add(entry + ": " + reason));
        assertEquals(List.of(new Entry("bob", "paint")), ok);
        assertEquals(3, why.size(), why.toString());
        assertTrue(why.get(0).contains("does not list agent mallory"), why.get(0));
        why.clear();
        assertEquals(List.of(), FleetDirectory.valid(List.of("bob"), new String[] { "bob" }, new String[0],
                (entry, reason) -> why.add(reason)));
        assertTrue(why.get(0).contains("as long as each other"), why.toString());
        int n = FleetDirectory.MAX_REMOTE_ENTRIES + 5;
        String[] agents = new String[n], services = new String[n];
        for (int i = 0; i < n; i++) {
            agents[i] = "bob";
            services[i] = "s" + i;
        }
        why.clear();
        assertEquals(FleetDirectory.MAX_REMOTE_ENTRIES,
                FleetDirectory.valid(List.of("bob"), agents, services, (e, r) -> why.add(e + ": " + r)).size());
        assertEquals(List.of("5 more: more than " + FleetDirectory.MAX_REMOTE_ENTRIES + " registrations"), why);
    }

    // ---- through the fleet's presence ---------------------------------------------------------

    private final List<Notice> fleetHeard = new ArrayList<>();
    private final Logger logger = Logger.getLogger("test.fleet.directory");

    private Fleet fleet() {
        Fleet f = new Fleet(logger, SigningPeer.recording(new ArrayList<>(), fleetHeard), new RateLimitedLog(logger),
                SigningPeer.authWithKeyA(), new InputLimits(), Clock.WALL);
        f.setMasId("/robot1/rason_mas");
        f.setIncarnation(System.currentTimeMillis() * 1_000_000L - 1_000_000_000L);
        f.localAgentsChanged(Set.of("boss"));
        return f;
    }

    @Test
    void registrationsArriveWithPresenceAndLeaveWithTheirRobot() {
        Fleet f = fleet();
        f.directory().subscribe("boss", "paint");
        SigningPeer r2 = new SigningPeer(R2, 100), r3 = new SigningPeer(R3, 100);
        r2.announce(f, new String[] { "bob" }, new String[] { "bob" }, new String[] { "paint" });
        r3.announce(f, new String[] { "carol" }, new String[] { "carol", "mallory" }, new String[] { "paint", "paint" });
        assertEquals(List.of("bob", "carol"), f.directory().search("paint"), "mallory is not carol's robot's agent");
        r2.announce(f, false); // robot2 leaves cleanly
        assertEquals(List.of("carol"), f.directory().search("paint"));
        f.setPresenceTimeoutNanos(1); // robot3 falls silent
        f.presenceTick(new String[] { R3 });
        assertEquals(List.of(), f.directory().search("paint"));
        assertEquals(List.of(told("boss", "bob", "paint"), told("boss", "carol", "paint"), untold("boss", "bob", "paint"),
                untold("boss", "carol", "paint")), fleetHeard);
    }

    @Test
    void aPresenceWhoseRegistrationsWereAlteredChangesNothing() {
        Fleet f = fleet();
        SigningPeer r2 = new SigningPeer(R2, 100);
        FleetAuth.Signed s = r2.auth.signPresence(R2, List.of("bob"), List.of("bob"), List.of("paint"), 0.5f, false);
        f.presenceAnnounced(R2, new String[] { "bob" }, new String[] { "bob" }, new String[] { "steal" }, false, 0.5f, s,
                R2, "");
        assertEquals(List.of(), f.directory().search("steal"));
        assertEquals(Set.of(), f.reachable());
    }
}
