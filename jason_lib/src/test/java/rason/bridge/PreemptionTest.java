package rason.bridge;

import rason.core.ManualClock;
import rason.core.Protocol;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static rason.bridge.RunningAgents.await;
import static rason.bridge.RunningAgents.believes;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

import rason.RosAgArch;

/**
 * An agent that changes its mind stops what it set in motion: every Jason
 * construct that makes an intention stop waiting for its action queues a
 * cancel for that action, right after the action, and the agent's next action
 * goes out at once. Real agents; nobody drains the outbox but the test.
 */
class PreemptionTest {

    private static final long SECOND = RunningAgents.SECOND;
    private static final long WAIT_MS = RunningAgents.WAIT_MS;

    private final ManualClock wall = new ManualClock(1_000 * SECOND);
    private final Bridge bridge = new Bridge(wall);
    @RegisterExtension
    final RunningAgents agents = new RunningAgents(bridge);

    @TempDir
    Path dir;

    private static final String MOVER = """
            !go.
            +!go <- move(3); +arrived.
            -!go[R|Rest] : .member(suspended, [R|Rest]) <- +saw_suspended.
            -!go <- +go_failed.
            +next <- turn(90); +turned.
            +resume_now <- .resume(go).
            """;

    private RosAgArch start(String takeBack) throws Exception {
        return agents.start(dir, "mover", MOVER + "+stop <- " + takeBack + ".\n");
    }


    private <T extends Outbound> T next(Class<T> kind) throws InterruptedException {
        return agents.next(kind);
    }

    private void perceive(String... literals) {
        bridge.perception().perceive("test", literals, 100 * SECOND);
    }

    private boolean feedback(int id, String result) {
        return bridge.actions().event("mover", Protocol.ACTION_FEEDBACK, new String[] { result, "" + id });
    }

    @ParameterizedTest
    @ValueSource(strings = { ".drop_intention(go)", ".drop_desire(go)", ".drop_all_intentions", ".drop_all_desires",
            ".fail_goal(go)", ".succeed_goal(go)" })
    void aTakenBackActionIsCancelledAndTheNextOneGoesOutAtOnce(String takeBack) throws Exception {
        RosAgArch arch = start(takeBack);
        Outbound.Action move = next(Outbound.Action.class);
        assertEquals("move", move.action());
        perceive("stop");
        assertEquals(new Outbound.Cancel("mover", move.actionId(), Protocol.DROPPED), next(Outbound.Cancel.class));
        assertEquals(0, arch.actions().pendingCount());
        if (takeBack.startsWith(".fail_goal"))
            await("-!go runs", () -> believes(arch, "go_failed"));
        // the decomposer's answer to the cancel, and any late one, change nothing
        assertFalse(feedback(move.actionId(), Protocol.CANCELLED));
        assertFalse(feedback(move.actionId(), Protocol.OK));
        perceive("stop", "next");
        Outbound.Action turn = next(Outbound.Action.class);
        assertEquals("turn", turn.action());
        assertTrue(feedback(turn.actionId(), Protocol.OK));
        await("the next action's intention goes on", () -> believes(arch, "turned"));
        assertFalse(believes(arch, "arrived"));
    }

    @Test
    void suspendStopsTheActionAndResumeSeesItFailSuspended() throws Exception {
        RosAgArch arch = start(".suspend(go)");
        Outbound.Action move = next(Outbound.Action.class);
        perceive("stop");
        assertEquals(new Outbound.Cancel("mover", move.actionId(), Protocol.SUSPENDED), next(Outbound.Cancel.class));
        assertFalse(feedback(move.actionId(), Protocol.CANCELLED), "the answer to the cancel does not end the suspended intention");
        bridge.tick(1000 * SECOND); // no timeout while suspended: the agent, not the robot, must act
        perceive("stop", "next");
        Outbound.Action turn = next(Outbound.Action.class);
        assertTrue(feedback(turn.actionId(), Protocol.OK));
        await("other intentions run meanwhile", () -> believes(arch, "turned"));
        assertFalse(believes(arch, "saw_suspended"));
        assertFalse(believes(arch, "go_failed"));
        perceive("stop", "next", "resume_now");
        await(".resume(go): the action failed 'suspended'", () -> believes(arch, "saw_suspended"));
        assertEquals(0, arch.actions().pendingCount());
        assertNull(bridge.outbox().poll(), "no second cancel");
    }

    @Test
    void theTimeoutCancelsTheAction() throws Exception {
        RosAgArch arch = start("true");
        bridge.actions().setTimeoutNanos(2 * SECOND);
        Outbound.Action move = next(Outbound.Action.class);
        bridge.tick(103 * SECOND);
        assertEquals(new Outbound.Cancel("mover", move.actionId(), Protocol.TIMEOUT), next(Outbound.Cancel.class));
        await("-!go with timeout", () -> believes(arch, "go_failed"));
        assertFalse(feedback(move.actionId(), Protocol.OK), "late feedback after the timeout");
    }

    @Test
    void shutdownCancelsWhatIsPending() throws Exception {
        start("true");
        Outbound.Action move = next(Outbound.Action.class);
        bridge.shutdown(Protocol.SHUTDOWN);
        assertEquals(new Outbound.Cancel("mover", move.actionId(), Protocol.SHUTDOWN), next(Outbound.Cancel.class));
    }

    @Test
    void anActionWhoseDecomposerWentAwayFailsAndIsCancelled() throws Exception {
        RosAgArch arch = start("true");
        bridge.actions().setDecomposerGraceNanos(0);
        Outbound.Action move = next(Outbound.Action.class);
        assertTrue(bridge.actions().event("mover", Protocol.ACTION_STARTED, new String[] { "" + move.actionId() }, "/motion_decomp"));
        bridge.actions().decomposersTick(new String[] { "/motion_decomp", "/other" });
        bridge.actions().decomposersTick(new String[] { "/motion_decomp" });
        assertEquals(1, arch.actions().pendingCount(), "its decomposer is still there");
        bridge.actions().decomposersTick(new String[] { "/other" }); // first seen missing
        wall.advance(1_000_000);
        bridge.actions().decomposersTick(new String[] { "/other" });
        assertEquals(new Outbound.Cancel("mover", move.actionId(), Protocol.DECOMPOSER_LOST), next(Outbound.Cancel.class));
        await("-!go with decomposer_lost", () -> believes(arch, "go_failed"));
    }

    @Test
    void anActionNobodyClaimedIsLeftToItsTimeout() throws Exception {
        RosAgArch arch = start("true");
        bridge.actions().setDecomposerGraceNanos(0);
        next(Outbound.Action.class);
        bridge.actions().decomposersTick(new String[0]);
        wall.advance(1_000_000);
        bridge.actions().decomposersTick(new String[0]);
        assertEquals(1, arch.actions().pendingCount());
    }
}
