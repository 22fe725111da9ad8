package rason.casestudy;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static rason.bridge.RunningAgents.believes;

import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;

import rason.RosAgArch;
import rason.bridge.Bridge;
import rason.bridge.Outbound;
import rason.bridge.RunningAgents;
import rason.core.Protocol;

/**
 * Guided by the helper's view, Faulty drives with goto; while that view stops coming (a lossy
 * or cut link) the robot stands still and goto fails no_progress. Faulty tries again up to
 * guidedTries times, then gives the drive up so that its mission ends, never hangs
 * (faulty_recovery.asl, !reach, !guidedGoto). Real Jason on Faulty's own files; the test plays
 * the motion decomposer.
 */
class FaultyRetriesTheGuidedDriveTest {

    private static final Path FAULTY = Path.of("..", "src", "rason", "agents", "case_study", "faulty.asl")
            .toAbsolutePath().normalize();

    private static final String TRIAL = "{ include(\"" + FAULTY + "\") }\n" + """
            +go(N) <- -+guidedTries(N); -+guidedPause(100); +beingGuided; !drive.
            +!drive <- !reach(1, 0); +arrived.
            -!drive <- +gaveUp.
            """;

    private final Bridge bridge = new Bridge();
    @RegisterExtension
    final RunningAgents agents = new RunningAgents(bridge);

    @TempDir
    Path dir;

    private long now = 101 * RunningAgents.SECOND;

    private RosAgArch faultyGuided(int tries) throws Exception {
        RosAgArch faulty = agents.start(dir, "faulty", TRIAL);
        bridge.perception().perceive("test", new String[] { "go(" + tries + ")" }, now);
        return faulty;
    }

    /** The next goto the agent asks for, ROS time running on (its pause between tries). */
    private Outbound.Action nextGoto() throws InterruptedException {
        long deadline = System.currentTimeMillis() + RunningAgents.WAIT_MS;
        while (System.currentTimeMillis() < deadline) {
            now += RunningAgents.SECOND / 20;
            bridge.tick(now);
            Outbound item = bridge.outbox().take(20);
            if (item instanceof Outbound.Action action && action.action().equals("goto"))
                return action;
        }
        return null;
    }

    private void answer(Outbound.Action action, String result) {
        bridge.actions().event("faulty", Protocol.ACTION_FEEDBACK, new String[] { result, "" + action.actionId() });
    }

    @Test
    void theDriveGoesOnOnceTheViewComesBack() throws Exception {
        RosAgArch faulty = faultyGuided(10);
        for (int i = 0; i < 2; i++) {
            Outbound.Action stalled = nextGoto();
            assertNotNull(stalled, "a goto (try " + (i + 1) + ")");
            answer(stalled, "no_progress");
        }
        Outbound.Action third = nextGoto();
        assertNotNull(third, "a third try");
        assertEquals("[1, 0]", java.util.Arrays.toString(third.parameters()));
        answer(third, Protocol.OK);
        RunningAgents.await("the drive ended", () -> believes(faulty, "arrived"));
        assertFalse(believes(faulty, "gaveUp"));
    }

    @Test
    void afterTheLastTryTheDriveFailsAndTheMissionCanEnd() throws Exception {
        RosAgArch faulty = faultyGuided(3);
        for (int i = 0; i < 3; i++) {
            Outbound.Action stalled = nextGoto();
            assertNotNull(stalled, "a goto (try " + (i + 1) + ")");
            answer(stalled, "no_progress");
        }
        RunningAgents.await("the drive given up", () -> believes(faulty, "gaveUp"));
        assertFalse(believes(faulty, "arrived"));
    }

    @Test
    void aFailureOtherThanNoProgressIsNotRetried() throws Exception {
        RosAgArch faulty = faultyGuided(10);
        answer(nextGoto(), "timeout");
        RunningAgents.await("the drive given up", () -> believes(faulty, "gaveUp"));
    }
}
