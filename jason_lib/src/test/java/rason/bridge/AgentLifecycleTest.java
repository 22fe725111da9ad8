package rason.bridge;

import rason.core.Protocol;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static rason.bridge.RunningAgents.await;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import jason.asSemantics.Unifier;
import jason.asSyntax.ASSyntax;
import jason.asSyntax.Literal;
import rason.infra.RasonLocalMAS;

/**
 * Agents created and killed while the robot runs: .create_agent names the agent
 * as the robot names its own (its ~agent_prefix), finds its source from the
 * project, never takes a name another robot uses, and the other robots hear of
 * it at once (an announcement is queued); .kill_agent of a local agent does the
 * same for its departure, of another robot's agent fails with a reason.
 */
class AgentLifecycleTest {

    private static final String KEY = "test-lifecycle-key-0123456789abcdef0123456789abcdef";
    private static final String OTHER_MAS = "/robot8/rason_mas";

    private final Bridge bridge = new Bridge();
    private OtherRobot otherRobot;
    private RasonLocalMAS mas;

    @TempDir
    Path dir;

    @AfterEach
    void stop() throws Exception {
        if (otherRobot != null)
            announceOtherRobot(true);
        bridge.shutdown(Protocol.SHUTDOWN);
        if (mas != null)
            mas.stopAgents(5000);
        bridge.detach();
        while (bridge.outbox().poll() != null) {
            // nothing of this test reaches the next one
        }
    }

    /** robot8 hosts far_worker (and r1_helper, a name this robot's program would make). */
    private void announceOtherRobot(boolean leaving) {
        otherRobot.announce(new String[] { "far_worker", "r1_helper" }, leaving);
        bridge.fleet().presenceTick(new String[] { OTHER_MAS });
    }

    /** Runs boss (program) with helper.asl in lib/ (an aslSourcePath), prefix r1_, robot8 present. */
    private void start(String boss) throws Exception {
        bridge.fleet().setMasId("/robot1/rason_mas");
        otherRobot = new OtherRobot(bridge, OTHER_MAS, KEY);
        Files.createDirectories(dir.resolve("lib"));
        Files.writeString(dir.resolve("lib/helper.asl"), "!start. +!start <- .df_register(\"helping\"); +started.");
        Files.writeString(dir.resolve("boss.asl"), boss);
        Files.writeString(dir.resolve("p.mas2j"), "MAS p { agents: boss; aslSourcePath: \"lib\"; }");
        bridge.attach();
        announceOtherRobot(false);
        mas = bridge.newMas();
        mas.setAgentPrefix("r1_");
        mas.load(dir.resolve("p.mas2j").toString());
        mas.create();
        drainOutbox();
        mas.start();
    }

    private List<Outbound> drainOutbox() {
        List<Outbound> items = new ArrayList<>();
        for (Outbound o = bridge.outbox().poll(); o != null; o = bridge.outbox().poll()) {
            items.add(o);
            if (o instanceof Outbound.Announce)
                bridge.rosChannel().announced(); // as the node does when it announces
        }
        return items;
    }

    private boolean believes(String agent, String literal) {
        try {
            return mas.getAg(agent).getTS().getAg().believes(ASSyntax.parseLiteral(literal), new Unifier());
        } catch (Exception e) {
            throw new IllegalStateException(e);
        }
    }

    private Literal belief(String agent, String pattern) throws Exception {
        Unifier u = new Unifier();
        Literal l = ASSyntax.parseLiteral(pattern);
        assertTrue(mas.getAg(agent).getTS().getAg().believes(l, u), agent + " believes " + pattern);
        return (Literal) l.capply(u);
    }

    @Test
    void aCreatedAgentIsNamedLikeTheRobotsOwnNeverAsAnotherRobotsAndAnnouncedAtOnce() throws Exception {
        start("""
                !start.
                +!start <- .create_agent(helper, "helper.asl"); .create_agent(Helper, "helper.asl"); +made(Helper).
                -!start[error_msg(M)] <- +failed(M).
                """);
        await("both helpers made", () -> believes("r1_boss", "made(_)") || believes("r1_boss", "failed(_)"));
        assertFalse(believes("r1_boss", "failed(_)"), () -> mas.getAg("r1_boss").getTS().getAg().getBB().toString());
        // r1_helper is robot8's: the first one is r1_helper_1, the second (named by Jason after the variable) r1_helper_2
        await("both helpers run", () -> bridge.fleet().names().hosts("r1_helper_1") && bridge.fleet().names().hosts("r1_helper_2"));
        assertTrue(believes("r1_boss", "made(\"r1_helper_2\")"));
        assertFalse(bridge.fleet().names().hosts("r1_helper"));
        await("helper1 started", () -> mas.getAg("r1_helper_1") != null && believes("r1_helper_1", "started"));
        assertTrue(drainOutbox().stream().anyMatch(o -> o instanceof Outbound.Announce),
                "the new agents are announced without waiting for the next period");
        List<String> announced = List.of(bridge.agentNames());
        assertTrue(announced.containsAll(List.of("r1_boss", "r1_helper_1", "r1_helper_2")), announced.toString());
        assertTrue(bridge.fleet().names().allNames().containsAll(List.of("far_worker", "r1_helper", "r1_helper_1")));
        await("registered", () -> bridge.fleet().directory().search("helping").equals(List.of("r1_helper_1", "r1_helper_2")));
    }

    @Test
    void killingALocalAgentAnnouncesItsDepartureAndTakesItsRegistrations() throws Exception {
        start("""
                !start.
                +!start <- .create_agent(aide, "helper.asl"); .wait(".df_search(\\"helping\\", [_])"); +ready.
                +!kill <- .kill_agent(aide); +killed.
                """);
        await("aide registered", () -> believes("r1_boss", "ready") || bridge.fleet().directory().search("helping").size() == 1);
        drainOutbox();
        mas.getAg("r1_boss").getTS().getC().addAchvGoal(ASSyntax.parseLiteral("kill"), null);
        mas.getAg("r1_boss").wakeUpSense();
        // the aide stops on its own thread and +killed is the boss's next step: either can come first
        await("aide gone", () -> !bridge.fleet().names().hosts("r1_aide") && mas.getAg("r1_aide") == null);
        await("the boss noted it", () -> believes("r1_boss", "killed"));
        List<Outbound> seen = new ArrayList<>();
        long deadline = System.currentTimeMillis() + RunningAgents.WAIT_MS;
        while (seen.stream().noneMatch(o -> o instanceof Outbound.Announce) && System.currentTimeMillis() < deadline) {
            seen.addAll(drainOutbox());
            Thread.sleep(5);
        }
        assertTrue(seen.stream().anyMatch(o -> o instanceof Outbound.Announce), "its departure is announced: " + seen);
        assertFalse(bridge.fleet().names().allNames().contains("r1_aide"));
        assertEquals(List.of(), bridge.fleet().directory().search("helping"));
    }

    @Test
    void killingAnotherRobotsAgentOrNobodyFailsWithAReason() throws Exception {
        start("""
                !start.
                +!start <- !kill(far_worker); !kill(nobody_here).
                +!kill(A) <- .kill_agent(A); +killed(A).
                -!kill(A)[error(E), error_msg(M)] <- +failed(A, E, M).
                """);
        await("both kills failed", () -> believes("r1_boss", "failed(nobody_here, _, _)"));
        Literal remote = belief("r1_boss", "failed(far_worker, E, M)");
        assertEquals("remote_agent", remote.getTerm(1).toString());
        assertTrue(remote.getTerm(2).toString().contains("runs on " + OTHER_MAS), remote.toString());
        Literal unknown = belief("r1_boss", "failed(nobody_here, E, M)");
        assertEquals("agent_not_found", unknown.getTerm(1).toString());
        assertFalse(believes("r1_boss", "killed(_)"));
        assertTrue(bridge.fleet().names().allNames().contains("far_worker"), "robot8's agent is untouched");
    }

    @Test
    void aSourceFoundNowhereFailsTheCreationNamingThePathsTried() throws Exception {
        start("""
                !start.
                +!start <- .create_agent(ghost, "ghost.asl").
                -!start[error(E), error_msg(M)] <- +failed(E, M).
                """);
        await("the creation failed", () -> believes("r1_boss", "failed(_, _)"));
        Literal f = belief("r1_boss", "failed(E, M)");
        assertEquals("source_not_found", f.getTerm(0).toString());
        assertTrue(f.getTerm(1).toString().contains(dir.resolve("lib").toRealPath().resolve("ghost.asl").toString()),
                f.toString());
        assertNotNull(mas.getAg("r1_boss"));
        assertFalse(bridge.fleet().names().hosts("r1_ghost"));
    }
}
