package rason.infra;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static rason.bridge.RunningAgents.await;
import static rason.bridge.RunningAgents.believes;

import java.nio.file.Path;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;

import rason.RosAgArch;
import rason.bridge.Bridge;
import rason.bridge.Outbound;
import rason.bridge.RunningAgents;

/**
 * .stopMAS(T) gives the agents T ms of their clock (ROS time here, pushed by the
 * test) and tells them +jag_shutting_down(T) before the node is asked to stop;
 * .stopMAS stops at once; the first .stopMAS decides, as in Jason.
 */
class StopMasDeadlineTest {

    private static final long MS = 1_000_000L;
    private static final long START = 100 * RunningAgents.SECOND; // RunningAgents' ROS time

    private final Bridge bridge = new Bridge();
    @RegisterExtension
    final RunningAgents agents = new RunningAgents(bridge);

    @TempDir
    Path dir;

    @AfterEach
    void backToTheWallClock() {
        bridge.agentsOnRosTime(false);
    }

    private RosAgArch start(String program) throws Exception {
        bridge.agentsOnRosTime(true);
        return agents.start(dir, "stopper", program);
    }

    @Test
    void theAgentsRunOnUntilTheDeadline() throws Exception {
        RosAgArch arch = start("""
                !go.
                +!go <- .stopMAS(3000, 4); .wait(2000); +late_plan_ran.
                +jag_shutting_down(T) <- +told(T).
                """);
        await("+jag_shutting_down(3000)", () -> believes(arch, "told(3000)"));
        await("the stop and the wait scheduled", () -> bridge.scheduler().waitingTasks() == 2);
        assertNull(bridge.outbox().poll(), "nothing is queued before the deadline");
        bridge.clockAdvanced(START + 2000 * MS);
        await("the plan after .wait(2000)", () -> believes(arch, "late_plan_ran"));
        bridge.clockAdvanced(START + 2999 * MS);
        assertEquals(1, bridge.scheduler().waitingTasks(), "not due 1 ms early");
        assertNull(bridge.outbox().poll(), "no stop 1 ms before the deadline");
        bridge.clockAdvanced(START + 3000 * MS);
        assertEquals(new Outbound.Stop(4), bridge.outbox().take(RunningAgents.WAIT_MS));
    }

    @Test
    void withoutADeadlineTheStopIsQueuedAtOnce() throws Exception {
        RosAgArch arch = start("!go. +!go <- .stopMAS. +jag_shutting_down(T) <- +told(T).");
        assertEquals(new Outbound.Stop(0), bridge.outbox().take(RunningAgents.WAIT_MS));
        assertFalse(believes(arch, "told(_)"));
    }

    @Test
    void aSecondStopMasIsIgnoredAsInJason() throws Exception {
        RosAgArch arch = start("!go. +!go <- .stopMAS(500, 2); .stopMAS(0, 7); +both_made.");
        await("both .stopMAS made", () -> believes(arch, "both_made"));
        assertNull(bridge.outbox().poll(), "the immediate second one is ignored");
        bridge.clockAdvanced(START + 500 * MS);
        assertEquals(new Outbound.Stop(2), bridge.outbox().take(RunningAgents.WAIT_MS));
        assertTrue(bridge.outbox().poll() == null, "one stop only");
    }
}
