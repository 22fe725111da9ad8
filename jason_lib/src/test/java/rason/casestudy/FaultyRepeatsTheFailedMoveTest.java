package rason.casestudy;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static rason.bridge.RunningAgents.believes;

import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;

import rason.RosAgArch;
import rason.bridge.Bridge;
import rason.bridge.Outbound;
import rason.core.Protocol;
import rason.bridge.RunningAgents;

/**
 * Faulty repeats, for the helper to watch, the move that failed, as long and backwards
 * (faulty.asl, !noteFailedMove, !repeatFailedMove): a weak actuator fault shows only over
 * the failed move's length, and ahead may be a wall. Only a failure the diagnosis knows is
 * evidence (-!tryMove). Real Jason on Faulty's own file, with the failure annotations the
 * bridge really gives; the test plays the motion decomposer.
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
            +watched <- !tryMove[source(helper)].
            """;

    private final Bridge bridge = new Bridge();
    @RegisterExtension
    final RunningAgents agents = new RunningAgents(bridge);

    @TempDir
    Path dir;

    /** The next action asked for that is not the start's (its first move waits for a peer). */
    private Outbound.Action nextMove() throws InterruptedException {
        Outbound.Action action = agents.next(Outbound.Action.class);
        assertEquals("move", action.action());
        return action;
    }

    private void fail(Outbound.Action action, String reason) {
        assertTrue(bridge.actions().event("faulty", Protocol.ACTION_FEEDBACK, new String[] { reason, "" + action.actionId() }));
    }

    private void failedMoveIsRepeated(String length, String reversed) throws Exception {
        RosAgArch arch = agents.start(dir, "faulty", TRIAL);
        bridge.perception().perceive("test", new String[] { "go(" + length + ")" }, 100 * RunningAgents.SECOND);
        Outbound.Action first = nextMove();
        assertArrayEquals(new String[] { length }, first.parameters());
        fail(first, "bad_move");
        Outbound.Action repeated = nextMove();
        assertEquals(Double.parseDouble(reversed), Double.parseDouble(repeated.parameters()[0]), 1e-9,
                "as long, backwards");
        assertTrue(believes(arch, "failedMove(" + length + ")"));
    }

    @Test
    void theMissionsMetreIsRepeatedBackwards() throws Exception {
        failedMoveIsRepeated("1", "-1");
    }

    @Test
    void aFailedBackwardMoveIsRepeatedForwards() throws Exception {
        failedMoveIsRepeated("-0.5", "0.5");
    }

    /** A helper in the same process that notes what Faulty asks of it. */
    private static final String NOTING_HELPER = """
            +!giveFeedback[source(S)] <- +askedForFeedback(S).
            +!thanks[source(S)] <- +thanked(S).
            """;

    /** The watched move (tryMove for the helper) fails with reason; the helper's agent. */
    private RosAgArch watchedMoveFails(String reason) throws Exception {
        Files.writeString(dir.resolve("helper.asl"), NOTING_HELPER);
        agents.start(dir, "faulty", TRIAL, "; helper");
        RosAgArch helper = agents.arch("helper");
        bridge.perception().perceive("test", new String[] { "watched" }, 100 * RunningAgents.SECOND);
        Outbound.Action watched = nextMove();
        while (!watched.parameters()[0].equals("0.3")) // the mission's, begun as a peer is present
            watched = nextMove();
        fail(watched, reason);
        return helper;
    }

    @Test
    void withoutAFailedMoveTheThesissShortMoveIsMade() throws Exception {
        agents.start(dir, "faulty", TRIAL);
        bridge.perception().perceive("test", new String[] { "watch" }, 100 * RunningAgents.SECOND);
        assertArrayEquals(new String[] { "0.3" }, nextMove().parameters());
    }

    @Test
    void aWatchedMoveFailingLikeTheFaultAsksTheHelperForFeedback() throws Exception {
        RosAgArch helper = watchedMoveFails("bad_move");
        RunningAgents.await("the helper asked for feedback", () -> believes(helper, "askedForFeedback(faulty)"));
        assertFalse(believes(helper, "thanked(faulty)"));
    }

    @Test
    void aWatchedMoveStoppedOtherwiseIsNoEvidence() throws Exception {
        // e.g. driven against a wall until the decomposer's max_duration
        RosAgArch helper = watchedMoveFails("timeout");
        Outbound.Action report = agents.next(Outbound.Action.class);
        while (report.action().equals("move")) // the mission's, begun now that a peer is present
            report = agents.next(Outbound.Action.class);
        assertEquals("report_diagnosis", report.action());
        assertEquals("undiagnosed", report.parameters()[0]);
        RunningAgents.await("the helper released", () -> believes(helper, "thanked(faulty)"));
        assertFalse(believes(helper, "askedForFeedback(faulty)"));
    }
}
