package rason.casestudy;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static rason.bridge.RunningAgents.believes;

import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;

import rason.RosAgArch;
import rason.bridge.Bridge;
import rason.bridge.Outbound;
import rason.bridge.Protocol;
import rason.bridge.RunningAgents;

/**
 * Faulty repeats, for the helper to watch, the move that failed (faulty.asl,
 * !noteFailedMove and !repeatFailedMove): a weak actuator fault shows only over the failed
 * move's length. Real Jason on Faulty's own file, with the failure annotations the bridge
 * really gives; the test plays the motion decomposer.
 */
class FaultyRepeatsTheFailedMoveTest {

    private static final Path FAULTY = Path.of("..", "src", "rason", "agents", "case_study", "faulty.asl")
            .toAbsolutePath().normalize();

    // Fails like goToDestination does, then the helper's tryMove motion is made.
    private static final String TRIAL = "{ include(\"" + FAULTY + "\") }\n" + """
            +go(D) <- !attempt(D).
            +!attempt(D) <- move(D).
            -!attempt(_)[R1 | Rest] <- !noteFailedMove([R1 | Rest]); !repeatFailedMove.
            +watch <- !repeatFailedMove.
            """;

    private final Bridge bridge = Bridge.get();
    @RegisterExtension
    final RunningAgents agents = new RunningAgents();

    @TempDir
    Path dir;

    /** The next action asked for that is not the start's (its first move waits for a peer). */
    private Outbound.Action nextMove() throws InterruptedException {
        Outbound.Action action = agents.next(Outbound.Action.class);
        assertEquals("move", action.action());
        return action;
    }

    private void fail(Outbound.Action action, String reason) {
        assertTrue(bridge.event("faulty", Protocol.ACTION_FEEDBACK, new String[] { reason, "" + action.actionId() }));
    }

    private void failedMoveIsRepeated(String length) throws Exception {
        RosAgArch arch = agents.start(dir, "faulty", TRIAL);
        bridge.perceive("test", new String[] { "go(" + length + ")" }, 100 * RunningAgents.SECOND);
        Outbound.Action first = nextMove();
        assertArrayEquals(new String[] { length }, first.parameters());
        fail(first, "bad_move");
        Outbound.Action repeated = nextMove();
        assertArrayEquals(new String[] { length }, repeated.parameters(), "the same length again");
        assertTrue(believes(arch, "failedMove(" + length + ")"));
    }

    @Test
    void theMissionsMetreIsRepeated() throws Exception {
        failedMoveIsRepeated("1");
    }

    @Test
    void aBackwardMoveIsRepeatedBackward() throws Exception {
        failedMoveIsRepeated("-0.5");
    }

    @Test
    void withoutAFailedMoveTheThesissShortMoveIsMade() throws Exception {
        agents.start(dir, "faulty", TRIAL);
        bridge.perceive("test", new String[] { "watch" }, 100 * RunningAgents.SECOND);
        assertArrayEquals(new String[] { "0.3" }, nextMove().parameters());
    }
}
