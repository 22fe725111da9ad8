package rason.casestudy;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
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
 * The helper (helper.asl) searching for a robot that goes out of reach (present/1 gone, as
 * when a link breaks between robots on hosts of their own): it goes on helping for
 * partnerGrace, and stops, taking its turn back, only when the robot is not back by then.
 * Real Jason on the helper's own file; the test plays the camera, the base and presence.
 */
class HelperWaitsForARobotOutOfReachTest {

    private static final Path HELPER = Path.of("..", "src", "rason", "agents", "case_study", "helper.asl")
            .toAbsolutePath().normalize();
    private static final String FLEET = "fleet";

    private final Bridge bridge = new Bridge();
    @RegisterExtension
    final RunningAgents agents = new RunningAgents(bridge);
    private long now = 100 * RunningAgents.SECOND;

    @TempDir
    Path dir;

    private static String searcher(int graceMs) {
        return "{ include(\"" + HELPER + "\") }\n"
                + "+go <- -+partnerGrace(" + graceMs + "); !helpme[source(faulty)].\n";
    }

    /** A camera frame that sees nothing: the helper searches, turning. */
    private void emptyFrame() {
        now += 100_000_000L;
        bridge.tick(now);
        bridge.perception().perceive("vision_synth_robots", new String[0], now);
    }

    private void present(boolean present) {
        bridge.perception().perceive(FLEET, present ? new String[] { "present(faulty)" } : new String[0], now);
    }

    private RosAgArch searching(int graceMs, Outbound.Action[] turn) throws Exception {
        RosAgArch arch = agents.start(dir, "helper", searcher(graceMs));
        present(true);
        bridge.perception().perceive("test", new String[] { "go" }, now);
        turn[0] = CameraFrames.untilAction(bridge, this::emptyFrame, RunningAgents.WAIT_MS);
        assertTrue(turn[0] != null && "turn".equals(turn[0].action()), "the search turns: " + turn[0]);
        return arch;
    }

    @Test
    void aRobotBackWithinTheGraceIsStillHelpedAndTheSearchGoesOn() throws Exception {
        Outbound.Action[] turn = new Outbound.Action[1];
        RosAgArch arch = searching(1000, turn);
        present(false);
        present(true);
        RunningAgents.noInputFor(1500, "past the grace: nothing may end the help");
        assertTrue(believes(arch, "helping(faulty)"), "still helping");
        Outbound item = bridge.outbox().poll();
        assertFalse(item instanceof Outbound.Cancel, "the turn is not taken back: " + item);
        assertTrue(bridge.actions().event("helper", Protocol.ACTION_FEEDBACK,
                new String[] { Protocol.OK, "" + turn[0].actionId() }));
        Outbound.Action next = CameraFrames.untilAction(bridge, this::emptyFrame, RunningAgents.WAIT_MS);
        assertTrue(next != null, "the search goes on with another turn");
        assertEquals("turn", next.action());
    }

    @Test
    void aRobotNotBackWithinTheGraceIsNoLongerHelpedAndTheTurnIsTakenBack() throws Exception {
        Outbound.Action[] turn = new Outbound.Action[1];
        RosAgArch arch = searching(300, turn);
        present(false);
        RunningAgents.await("the help to end", () -> !believes(arch, "helping(faulty)"));
        Outbound.Cancel cancel = agents.next(Outbound.Cancel.class);
        assertEquals(turn[0].actionId(), cancel.actionId());
    }
}
