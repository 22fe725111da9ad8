package rason.mind;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static rason.bridge.RunningAgents.SECOND;
import static rason.bridge.RunningAgents.await;
import static rason.bridge.RunningAgents.believes;

import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;

import rason.RosAgArch;
import rason.bridge.Bridge;
import rason.bridge.Outbound;
import rason.core.Protocol;
import rason.bridge.RunningAgents;

/** jason/mind's snapshots of real Jason agents, read on their own threads. */
class AgentMindTest {

    private final Bridge bridge = new Bridge();
    @RegisterExtension
    final RunningAgents agents = new RunningAgents(bridge);

    @TempDir
    Path dir;

    @AfterEach
    void mindOff() {
        bridge.mind().setPeriodNanos(0);
        bridge.mind().setLimits(200, 500);
    }

    private static final String MOVER = """
            battery(80).
            !deliver(parcel).
            +!deliver(P) <- !goTo(dock); +delivered(P).
            +!goTo(Where) <- move(Where).
            """;

    /** The newest snapshot of agent once cond holds for it. */
    private AgentMind awaitMind(RosAgArch arch, String what, java.util.function.Predicate<AgentMind> cond)
            throws InterruptedException {
        await(what, () -> rason.MindAgArch.of(arch.getTS()).recorder().latest() != null && cond.test(rason.MindAgArch.of(arch.getTS()).recorder().latest()));
        return rason.MindAgArch.of(arch.getTS()).recorder().latest();
    }

    @Test
    void showsBeliefsGoalsTheWaitingIntentionAndItsPendingAction() throws Exception {
        bridge.mind().setPeriodNanos(SECOND / 100);
        RosAgArch arch = agents.start(dir, "mover", MOVER);
        Outbound.Action move = agents.next(Outbound.Action.class);
        AgentMind m = awaitMind(arch, "the pending move", s -> !s.actions().isEmpty());
        assertEquals("mover", m.name());
        assertTrue(m.beliefs().contains("battery(80)[source(self)]"), m.beliefs().toString());
        assertTrue(m.beliefs().stream().noneMatch(b -> b.contains("hide_in_mind_inspector")), "Jason's kqml rules");
        assertEquals(List.of("!deliver(parcel)[source(self)]", "!goTo(dock)[source(self)]"), m.goals());
        assertEquals(1, m.intentions().size(), m.intentions().toString());
        AgentMind.IntentionView i = m.intentions().get(0);
        assertEquals("waiting", i.state());
        assertTrue(i.plans().get(0).contains("+!goTo(dock)") && i.plans().get(0).endsWith("<- move(dock)"),
                i.plans().toString());
        assertTrue(i.plans().get(1).contains("+!deliver(parcel)"), i.plans().toString());
        assertEquals(move.actionId(), m.actions().get(0).id());
        assertEquals("move(dock)", m.actions().get(0).action());
        assertEquals(100 * SECOND, m.actions().get(0).startedNanos());
        assertTrue(m.events().stream().anyMatch(e -> e.startsWith("+!deliver(parcel)")), m.events().toString());
        assertTrue(m.cycle() > 0);

        bridge.actions().event("mover", Protocol.ACTION_FEEDBACK, new String[] { Protocol.OK, "" + move.actionId() });
        // the state it goes to sleep in: delivered, nothing left to do
        awaitMind(arch, "the delivery, nothing pending", s -> s.beliefs().contains("delivered(parcel)[source(self)]")
                && s.actions().isEmpty() && s.intentions().isEmpty() && s.goals().isEmpty());
    }

    @Test
    void rulesAreKeptApartFromBeliefs() throws Exception {
        bridge.mind().setPeriodNanos(SECOND / 100);
        RosAgArch arch = agents.start(dir, "ruler", """
                battery(80).
                charged :- battery(B) & B > 50.
                """);
        AgentMind m = awaitMind(arch, "its state", s -> !s.beliefs().isEmpty());
        assertTrue(m.beliefs().contains("battery(80)[source(self)]"), m.beliefs().toString());
        assertTrue(m.beliefs().stream().noneMatch(b -> b.contains(":-")), m.beliefs().toString());
        assertEquals(List.of("charged[source(self)] :- (battery(B) & (B > 50))"), m.rules());
    }

    @Test
    void theStateItPausesInIsReadWhateverThePeriod() throws Exception {
        bridge.mind().setPeriodNanos(3600 * SECOND); // only the first cycle and the pauses
        RosAgArch arch = agents.start(dir, "counter", """
                !count(0).
                +!count(N) : N < 50 <- -+counted(N + 1); !count(N + 1).
                +!count(_) <- +done.
                """);
        AgentMind m = awaitMind(arch, "the last state", s -> s.beliefs().contains("done[source(self)]"));
        assertTrue(m.beliefs().contains("counted(50)[source(self)]"), m.beliefs().toString());
    }

    @Test
    void messagesInAndOutAreNoted() throws Exception {
        bridge.mind().setPeriodNanos(SECOND / 100);
        RosAgArch arch = agents.start(dir, "talker", """
                !greet.
                +!greet <- .my_name(Me); .send(Me, tell, hello(1)).
                """);
        await("the message", () -> believes(arch, "hello(1)"));
        AgentMind m = awaitMind(arch, "both ends", s -> s.messages().size() == 2);
        assertEquals(List.of("talker -> talker: tell hello(1)", "talker -> talker: tell hello(1)"), m.messages());
    }

    @Test
    void listsAndEntriesAreBoundedAndWhatIsLeftOutCounted() throws Exception {
        bridge.mind().setLimits(10, 40);
        bridge.mind().setPeriodNanos(SECOND / 100);
        RosAgArch arch = agents.start(dir, "hoarder", """
                !fill(0).
                +!fill(N) : N < 30 <- +item(N); !fill(N + 1).
                +!fill(_) <- +long("%s"); +full.
                """.formatted("x".repeat(200)));
        await("full", () -> believes(arch, "full"));
        AgentMind m = awaitMind(arch, "the bounded state", s -> s.omitted() >= 22);
        assertEquals(10, m.beliefs().size());
        assertTrue(m.beliefs().stream().allMatch(b -> b.length() <= 40), m.beliefs().toString());
        assertTrue(m.omitted() >= 32 - 10, "omitted " + m.omitted());
    }

    @Test
    void offMeansNoSnapshotAndTurningOnReadsASleepingAgent() throws Exception {
        RosAgArch arch = agents.start(dir, "idle", "ready.\n");
        await("started", () -> believes(arch, "ready"));
        // cycles run while off (a perception, then a belief from it): none of them reads the mind
        bridge.perception().perceive("test", new String[] { "tick(1)" }, 100 * SECOND);
        await("a cycle with the mind off", () -> believes(arch, "tick(1)"));
        assertNull(rason.MindAgArch.of(arch.getTS()).recorder().latest());
        assertNull(bridge.mind().changes());

        bridge.mind().setPeriodNanos(SECOND);
        awaitMind(arch, "read after turning on", s -> s.beliefs().contains("ready[source(self)]"));
        AgentMind[] all = bridge.mind().changes();
        assertNotNull(all);
        assertEquals("idle", all[0].name());
        assertNull(bridge.mind().changes(), "nothing changed since");
    }
}
