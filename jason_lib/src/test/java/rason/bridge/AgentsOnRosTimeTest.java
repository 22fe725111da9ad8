package rason.bridge;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static rason.bridge.RunningAgents.await;
import static rason.bridge.RunningAgents.believes;

import java.nio.file.Path;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;

import rason.RosAgArch;

/**
 * Real agents whose Jason timing follows ROS time (/use_sim_time): a .wait lasts
 * its milliseconds of ROS time, whatever the wall clock does meanwhile.
 */
class AgentsOnRosTimeTest {

    private static final long MS = 1_000_000L;
    private static final long START = 100 * RunningAgents.SECOND; // RunningAgents' ROS time

    /** Waits up to 300 ms for the percept ready. */
    private static final String WAITS_FOR_READY = """
            !go.
            +!go <- .wait(ready, 300); +ready_seen.
            -!go[error(E)] <- +failed(E).
            """;

    private final Bridge bridge = new Bridge();
    @RegisterExtension
    final RunningAgents agents = new RunningAgents(bridge);

    @TempDir
    Path dir;

    @AfterEach
    void backToTheWallClock() throws Exception {
        bridge.agentsOnRosTime(false);
    }

    private RosAgArch start(String program) throws Exception {
        bridge.agentsOnRosTime(true);
        return agents.start(dir, "timed", program);
    }

    @Test
    void aWaitLastsItsMillisecondsOfRosTime() throws Exception {
        RosAgArch arch = start("!go. +!go <- .wait(400); +woke.");
        await("the wait scheduled", () -> bridge.scheduler().waitingTasks() == 1);
        bridge.clockAdvanced(START + 399 * MS);
        assertEquals(1, bridge.scheduler().waitingTasks(), "not due 1 ms of ROS time early");
        assertFalse(believes(arch, "woke"));
        bridge.clockAdvanced(START + 400 * MS);
        await("woke", () -> believes(arch, "woke"));
    }

    @Test
    void aWaitForAnEventTimesOutOnRosTime() throws Exception {
        RosAgArch arch = start(WAITS_FOR_READY);
        await("the wait scheduled", () -> bridge.scheduler().waitingTasks() == 1);
        bridge.clockAdvanced(START + 300 * MS);
        await("the timeout", () -> believes(arch, "failed(_)"));
        assertTrue(believes(arch, "failed(wait_timeout)"));
        assertFalse(believes(arch, "ready_seen"));
    }

    @Test
    void aWaitForAnEventEndsWithTheEventBeforeItsRosTimeout() throws Exception {
        RosAgArch arch = start(WAITS_FOR_READY);
        await("the wait scheduled", () -> bridge.scheduler().waitingTasks() == 1);
        bridge.perception().perceive("test", new String[] { "ready" }, START);
        await("ready seen", () -> believes(arch, "ready_seen"));
        bridge.clockAdvanced(START + 300 * MS); // the timer fires for a wait already over
        await("the timer gone", () -> bridge.scheduler().waitingTasks() == 0);
        assertFalse(believes(arch, "failed(_)"));
    }
}
