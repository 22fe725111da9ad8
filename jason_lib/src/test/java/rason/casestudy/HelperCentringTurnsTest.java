package rason.casestudy;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static rason.bridge.RunningAgents.believes;

import java.nio.file.Path;
import java.util.Locale;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;

import rason.RosAgArch;
import rason.bridge.Bridge;
import rason.bridge.Outbound;
import rason.core.Protocol;
import rason.bridge.RunningAgents;

/**
 * The helper's search (helper.asl, !findRobot) turns to centre a robot seen off-centre at
 * most maxCentringTurns times: a robot half hidden, lost at each turn to it and seen off
 * centre again, made it turn back and forth until the robot gave up waiting. Real Jason on
 * the helper's own file; the test plays the camera and the base.
 */
class HelperCentringTurnsTest {

    private static final Path HELPER = Path.of("..", "src", "rason", "agents", "case_study", "helper.asl")
            .toAbsolutePath().normalize();
    private static final String SEARCHER = "{ include(\"" + HELPER + "\") }\n"
            + "+go <- !helpme[source(faulty)].\n";
    private static final long FRAME_PERIOD = 10_000_000L;

    private final Bridge bridge = new Bridge();
    @RegisterExtension
    final RunningAgents agents = new RunningAgents(bridge);
    private int frame = 0;
    private long now = 100 * RunningAgents.SECOND;

    @TempDir
    Path dir;

    /** One camera frame, now: the robot at angle (degrees, clockwise) or, with NaN, nothing. */
    private void camera(double angle) {
        frame++;
        now += FRAME_PERIOD;
        bridge.tick(now);
        String counter = "cameraFrame(" + frame + "," + now / 1_000_000 + ")";
        String[] seen = Double.isNaN(angle) ? new String[] { counter }
                : new String[] { String.format(Locale.ROOT, "robot(faulty,%.2f,1.5,-70)", angle), counter };
        bridge.perception().perceive("vision_synth_robots", seen, now);
    }

    /** Frames showing the robot at angle until the helper asks for an action (null: none in time). */
    private Outbound.Action framesUntilAction(double angle, long waitMs) throws InterruptedException {
        return CameraFrames.untilAction(bridge, () -> camera(angle), waitMs);
    }

    private void done(Outbound.Action action) {
        assertTrue(bridge.actions().event("helper", Protocol.ACTION_FEEDBACK, new String[] { Protocol.OK, "" + action.actionId() }));
    }

    @Test
    void aRobotThatStaysOffCentreEndsTheSearchAfterFourTurnsToIt() throws Exception {
        RosAgArch arch = agents.start(dir, "helper", SEARCHER);
        camera(20);
        bridge.perception().perceive("test", new String[] { "go" }, now);
        for (int i = 1; i <= 4; i++) {
            Outbound.Action turn = framesUntilAction(20, RunningAgents.WAIT_MS);
            assertTrue(turn != null, "turn " + i + " to the robot");
            assertEquals("turn", turn.action());
            assertEquals(20.0, Double.parseDouble(turn.parameters()[0]), 0.01);
            done(turn); // and the robot is seen 20 degrees off again
        }
        // still seen 20 degrees off: no fifth turn, the search ends
        long deadline = System.currentTimeMillis() + RunningAgents.WAIT_MS;
        while (believes(arch, "helping(faulty)")) {
            assertTrue(System.currentTimeMillis() < deadline, "the helper gives up");
            camera(20);
            Outbound item = bridge.outbox().take(20);
            assertFalse(item instanceof Outbound.Action, "no fifth turn: " + item);
        }
        assertTrue(believes(arch, "centringTurns(4)"));
        assertFalse(believes(arch, "foundRobot(faulty,_,_,_)"));
    }

    @Test
    void aRobotCentredByATurnIsFound() throws Exception {
        RosAgArch arch = agents.start(dir, "helper", SEARCHER);
        camera(20);
        bridge.perception().perceive("test", new String[] { "go" }, now);
        Outbound.Action turn = framesUntilAction(20, RunningAgents.WAIT_MS);
        assertEquals("turn", turn.action());
        done(turn);
        long deadline = System.currentTimeMillis() + RunningAgents.WAIT_MS;
        while (!believes(arch, "foundRobot(faulty,_,_,_)")) {
            assertTrue(System.currentTimeMillis() < deadline, "the robot is found");
            camera(1.5);
            Thread.sleep(20);
        }
        assertTrue(believes(arch, "centringTurns(1)"));
    }
}
