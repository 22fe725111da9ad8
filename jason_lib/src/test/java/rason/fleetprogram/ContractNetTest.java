package rason.fleetprogram;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static rason.bridge.RunningAgents.believes;

import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.Map;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;

import jason.runtime.RuntimeServicesFactory;
import rason.bridge.Bridge;
import rason.bridge.RunningAgents;

/**
 * The fleet program's contract net (agents/fleet/contract_net.asl) on real Jason: callers and
 * bidders in one MAS, each bidder registered as an observer with a cost the test gives it.
 * The test stops agents (a robot that leaves) and says when a contractor's work ends, and how.
 */
class ContractNetTest {

    private static final Path CONTRACT_NET = Path.of("..", "src", "rason", "agents", "fleet", "contract_net.asl")
            .toAbsolutePath().normalize();

    private final Bridge bridge = new Bridge();
    @RegisterExtension
    final RunningAgents agents = new RunningAgents(bridge);

    @TempDir
    Path dir;
    private long now = 100 * RunningAgents.SECOND;

    /** A caller: on call(Me) it contracts find(Me) from the observers, and notes the outcome. */
    private static String caller() {
        return include()
                + "+call(Me) : .my_name(Me) <- !contract(\"observer\", find(Me)).\n"
                + "+!contracted(find(_), P) <- +helpedBy(P).\n"
                + "+!uncontracted(find(_), Reason) <- +gaveUp(Reason).\n"
                + "+failedBy(Me, P) : .my_name(Me) & helpedBy(P) <- -helpedBy(P); !contractFailed(find(Me)).\n";
    }

    /**
     * A bidder whose cost is Cost (none: it never bids); its work lasts until the test
     * perceives stop(Me, ok) or stop(Me, fail).
     */
    private static String bidder(Integer cost) {
        return include()
                + (cost == null ? "" : "cost(" + cost + ").\n")
                + "bid(find(_), _, B) :- cost(B).\n"
                + "!register.\n"
                + "+!register <- .df_register(\"observer\"); +registered.\n"
                + "+!carryOut(Task, C) <- .my_name(Me); +working(Task, C); .wait(stop(Me, Outcome)); !end(Outcome).\n"
                + "+!end(ok) <- true.\n"
                + "+!end(fail) <- .fail.\n";
    }

    /** The contract net with shorter waits than a fleet's, set before the test goes on ({@code tuned}). */
    private static String include() {
        return "{ include(\"" + CONTRACT_NET + "\") }\n"
                + "!tune.\n"
                + "+!tune <- -+awardTimeout(1000); -+callerGrace(300); +tuned.\n";
    }

    private void start(Map<String, String> programs) throws Exception {
        agents.startAll(dir, programs);
        for (Map.Entry<String, String> agent : programs.entrySet()) {
            RunningAgents.await(agent.getKey() + " to be tuned", () -> believes(agents.arch(agent.getKey()), "tuned"));
            if (agent.getValue().contains("df_register"))
                RunningAgents.await(agent.getKey() + " to register",
                        () -> believes(agents.arch(agent.getKey()), "registered"));
        }
    }

    /** The agent stops (its robot's process died): the others' present/1 of it drops. */
    private void leave(String agent) throws Exception {
        assertTrue(RuntimeServicesFactory.get().killAgent(agent, "test", 0), agent + " killed");
    }

    /** Each perception stamped later than the one before (an older stamp is not news). */
    private void perceive(String source, String... literals) {
        now += RunningAgents.SECOND / 10;
        bridge.tick(now);
        bridge.perception().perceive(source, literals, now);
    }

    private boolean helpedBy(String caller, String helper) {
        return believes(agents.arch(caller), "helpedBy(" + helper + ")");
    }

    private boolean committed(String bidder) {
        return believes(agents.arch(bidder), "committed(_,_,_)");
    }

    private static Map<String, String> fleet(String callers, Integer... costs) {
        Map<String, String> programs = new LinkedHashMap<>();
        for (String caller : callers.split(" "))
            programs.put(caller, caller());
        for (int i = 0; i < costs.length; i++)
            programs.put("b" + (i + 1), bidder(costs[i]));
        return programs;
    }

    @Test
    void theLowestBidIsAwardedAndOnlyItsBidderWorks() throws Exception {
        start(fleet("c", 5, 2, 9));
        perceive("test", "call(c)");
        RunningAgents.await("c to get a contractor", () -> helpedBy("c", "b2"));
        RunningAgents.await("b2 to work for c", () -> believes(agents.arch("b2"), "working(find(c),c)"));
        assertTrue(committed("b2"));
        assertFalse(committed("b1") || committed("b3"), "the others are not committed");
    }

    @Test
    void aRobotNeverWorksForTwoCallersAtOnce() throws Exception {
        start(fleet("c1 c2", 1, 2));
        perceive("test", "call(c1)", "call(c2)");
        RunningAgents.await("both callers to get a contractor",
                () -> (helpedBy("c1", "b1") || helpedBy("c1", "b2")) && (helpedBy("c2", "b1") || helpedBy("c2", "b2")));
        String first = helpedBy("c1", "b1") ? "b1" : "b2";
        String second = helpedBy("c2", "b1") ? "b1" : "b2";
        assertNotEquals(first, second, "each caller has a contractor of its own");
    }

    @Test
    void aContractorThatFailsIsReplacedByTheNextBidder() throws Exception {
        start(fleet("c", 5, 2, 9));
        perceive("test", "call(c)");
        RunningAgents.await("b2 to work for c", () -> believes(agents.arch("b2"), "working(find(c),c)"));
        perceive("test", "stop(b2, fail)");
        RunningAgents.await("c to award the next bid, b1", () -> helpedBy("c", "b1"));
        RunningAgents.await("b2 to be free again", () -> !committed("b2"));
        assertTrue(believes(agents.arch("b1"), "working(find(c),c)"));
        assertFalse(committed("b3"));
    }

    @Test
    void aContractorThatLeavesIsReplacedWithinFiveSeconds() throws Exception {
        start(fleet("c", 5, 2, 9));
        perceive("test", "call(c)");
        RunningAgents.await("b2 to work for c", () -> believes(agents.arch("b2"), "working(find(c),c)"));
        long left = System.nanoTime();
        leave("b2");
        RunningAgents.await("c to award the next bid, b1", () -> helpedBy("c", "b1"));
        long ms = (System.nanoTime() - left) / 1_000_000;
        assertTrue(ms <= 5000, "the next bidder was awarded " + ms + " ms after the contractor left");
    }

    @Test
    void aCallerCallsTheNextBidderWhenItsContractorCannotHelpAndGivesUpAfterTheLast() throws Exception {
        start(fleet("c", 5, 2));
        perceive("test", "call(c)");
        RunningAgents.await("c to get b2", () -> helpedBy("c", "b2"));
        perceive("test", "failedBy(c, b2)");
        RunningAgents.await("c to get b1", () -> helpedBy("c", "b1"));
        perceive("test", "failedBy(c, b1)");
        RunningAgents.await("c to give up", () -> believes(agents.arch("c"), "gaveUp(no_contractor_left)"));
        RunningAgents.await("both bidders to be free", () -> !committed("b1") && !committed("b2"));
    }

    @Test
    void aCallerWithNobodyToCallOrNoBidGivesUpWithAReason() throws Exception {
        start(fleet("c", (Integer) null));
        perceive("test", "call(c)");
        RunningAgents.await("c to give up", () -> believes(agents.arch("c"), "gaveUp(no_contractor_left)"));
        assertFalse(committed("b1"));
        agents.stop();
        start(Map.of("c", caller()));
        perceive("test", "call(c)");
        RunningAgents.await("c to give up", () -> believes(agents.arch("c"), "gaveUp(no_candidates(\"observer\"))"));
    }

    @Test
    void aContractorWhoseCallerLeftIsFreeAfterTheGrace() throws Exception {
        start(fleet("c", 3));
        perceive("test", "call(c)");
        RunningAgents.await("b1 to work for c", () -> believes(agents.arch("b1"), "working(find(c),c)"));
        leave("c");
        RunningAgents.await("b1 to be free again", () -> !committed("b1"));
    }
}
