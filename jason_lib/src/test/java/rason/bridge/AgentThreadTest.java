package rason.bridge;

import rason.core.Protocol;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static rason.bridge.RunningAgents.await;
import static rason.bridge.RunningAgents.believes;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;

import rason.RosAgArch;

/**
 * Real Jason agents with RosAgArch and nobody draining the outbox — as if the
 * rospy side were blocked: act() must return at once (the agent's other
 * intentions go on), and feedback, timeouts, shutdown and .stopMAS all work
 * through the Java side alone.
 */
class AgentThreadTest {

    private static final long SECOND = RunningAgents.SECOND;
    private static final long WAIT_MS = RunningAgents.WAIT_MS;

    private final Bridge bridge = new Bridge();
    @RegisterExtension
    final RunningAgents agents = new RunningAgents(bridge);

    @TempDir
    Path dir;

    private RosAgArch start(String agent, String program) throws Exception {
        return agents.start(dir, agent, program);
    }


    private Outbound.Action nextAction() throws InterruptedException {
        return agents.next(Outbound.Action.class);
    }

    private static final String WORKER = """
            !work.
            !count(0).
            +!work <- move(1, "fast"); +moved.
            -!work[R|Rest] : .member(Why, [timeout, shutdown, no_progress]) & .member(Why, [R|Rest]) <- +failed(Why).
            +!count(N) : N < 200 <- -+counted(N + 1); !count(N + 1).
            +!count(_) <- +counted_all.
            """;

    @Test
    void actReturnsAtOnceAndTheAgentGoesOnWhileNobodyPublishes() throws Exception {
        RosAgArch arch = start("worker", WORKER);
        Outbound.Action a = nextAction();
        assertEquals("worker", a.agent());
        assertEquals("move", a.action());
        assertEquals(java.util.List.of("1", "fast"), java.util.List.of(a.parameters()));
        // nobody took the action to ROS, yet the agent's other intention runs to its end
        await("the other intention ends", () -> believes(arch, "counted_all"));
        assertFalse(believes(arch, "moved"));
        assertTrue(bridge.actions().event("worker", Protocol.ACTION_FEEDBACK, new String[] { Protocol.OK, "" + a.actionId() }));
        await("the action's intention resumes", () -> believes(arch, "moved"));
    }

    @Test
    void aFailureReasonFailsTheIntentionWithIt() throws Exception {
        RosAgArch arch = start("worker", WORKER);
        Outbound.Action a = nextAction();
        bridge.actions().event("worker", Protocol.ACTION_FEEDBACK, new String[] { "no_progress", "" + a.actionId() });
        await("-!work with no_progress", () -> believes(arch, "failed(no_progress)"));
    }

    @Test
    void badAndForeignEventsChangeNothing() throws Exception {
        RosAgArch arch = start("worker", WORKER);
        Outbound.Action a = nextAction();
        assertFalse(bridge.actions().event("someone_else", Protocol.ACTION_FEEDBACK, new String[] { Protocol.OK, "" + a.actionId() }));
        assertFalse(bridge.actions().event("worker", "status", new String[] { Protocol.OK, "" + a.actionId() }));
        assertFalse(bridge.actions().event("worker", Protocol.ACTION_FEEDBACK, new String[] { Protocol.OK, "2147483648" }));
        assertFalse(bridge.actions().event("worker", Protocol.ACTION_FEEDBACK, new String[] { Protocol.OK, "" + (a.actionId() + 1000) }));
        assertEquals(1, pending(arch));
        assertTrue(bridge.actions().event("worker", Protocol.ACTION_FEEDBACK, new String[] { Protocol.OK, "" + a.actionId() }));
        await("the action's intention resumes", () -> believes(arch, "moved"));
        assertFalse(bridge.actions().event("worker", Protocol.ACTION_FEEDBACK, new String[] { Protocol.OK, "" + a.actionId() }),
                "late feedback is ignored");
    }

    @Test
    void timeoutFollowsThePushedRosClock() throws Exception {
        RosAgArch arch = start("worker", WORKER);
        bridge.actions().setTimeoutNanos(2 * SECOND);
        nextAction();
        bridge.tick(101 * SECOND);
        await("the other intention ends", () -> believes(arch, "counted_all"));
        assertFalse(believes(arch, "failed(timeout)"), "1 s of ROS time is within the timeout");
        bridge.tick(103 * SECOND);
        await("-!work with timeout", () -> believes(arch, "failed(timeout)"));
    }

    @Test
    void shutdownFailsPendingActionsAndLaterOnesAtOnce() throws Exception {
        RosAgArch arch = start("worker", WORKER + "+failed(_) <- move(2); +moved_after.\n"
                + "-!g[error(E)] <- true.\n");
        Outbound.Action a = nextAction();
        bridge.shutdown(Protocol.SHUTDOWN);
        assertEquals(new Outbound.Cancel("worker", a.actionId(), Protocol.SHUTDOWN), bridge.outbox().take(WAIT_MS),
                "the robot is told to stop it");
        await("-!work with shutdown", () -> believes(arch, "failed(shutdown)"));
        // the plan's next action failed at once (no intention waits), and nothing more was queued
        await("the -! plan's action ended", () -> pending(arch) == 0 && !arch.getTS().getC().hasRunningIntention());
        assertNull(bridge.outbox().poll());
        assertFalse(believes(arch, "moved_after"));
    }

    @Test
    void stopMasIsQueuedForTheNodeWithItsExitValue() throws Exception {
        start("stopper", "!go.\n+!go <- .stopMAS(0, 3).\n");
        Outbound item = bridge.outbox().take(WAIT_MS);
        assertEquals(new Outbound.Stop(3), item);
    }

    private static int pending(RosAgArch arch) {
        return arch.actions().pendingCount();
    }

    private static void assertNull(Object o) {
        org.junit.jupiter.api.Assertions.assertNull(o);
    }
}
