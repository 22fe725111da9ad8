package rason.casestudy;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static rason.bridge.RunningAgents.await;
import static rason.bridge.RunningAgents.believes;

import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;

import rason.RosAgArch;
import rason.bridge.Bridge;
import rason.bridge.RunningAgents;

/**
 * The helper's steady view of a robot (helper.asl, !steadyView, !settle), run by real Jason
 * on the file the helper robot runs, with a camera that counts and stamps its frames
 * (cameraFrame(N, T)): a frame read twice, or two frames taken moments apart, are not a
 * steady view; the view settles on two agreeing frames taken settleTime apart; after a
 * motion, a frame taken before it ended is not read.
 */
class HelperSteadyViewTest {

    private static final Path HELPER = Path.of("..", "src", "rason", "agents", "case_study", "helper.asl")
            .toAbsolutePath().normalize();
    private static final long NOW = 100 * RunningAgents.SECOND;

    /** The helper's plans, faster settling, and a probe that reports the view it got. */
    private static final String WATCHER = "{ include(\"" + HELPER + "\") }\n" + """
            +go(W) <- -settleTime(_); +settleTime(50); -frameTimeout(_); +frameTimeout(W);
                   !look.
            +!look <- !steadyView(faulty, D, P, Y); +seen(D, P, Y).
            -!look <- +unsteady.
            +moved <- -settleTime(_); +settleTime(50); !settle; ?robot(faulty, D, P, Y); +seen(D, P, Y).
            """;
    /** The frames' stamps (ms of ROS time): the bridge's clock is at NOW. */
    private static final long NOW_MS = NOW / 1_000_000;

    private final Bridge bridge = new Bridge();
    @RegisterExtension
    final RunningAgents agents = new RunningAgents(bridge);

    @TempDir
    Path dir;


    private void camera(String... literals) {
        bridge.perception().perceive("vision_synth_robots", literals, NOW);
    }

    /**
     * Starts the helper's plans, shows it the camera's first perception, then makes it look,
     * waiting up to frameTimeout ms for each newer frame.
     */
    private RosAgArch startLooking(int frameTimeout, String... firstFrame) throws Exception {
        RosAgArch arch = agents.start(dir, "watcher", WATCHER);
        camera(firstFrame);
        bridge.perception().perceive("test", new String[] { "go(" + frameTimeout + ")" }, NOW);
        return arch;
    }

    @Test
    void aFrameReadTwiceIsNotASteadyViewTheNextFramesAre() throws Exception {
        // a busy CPU holds the frame of a robot still turning; the helper reads it, then waits
        RosAgArch arch = startLooking(5000, "robot(faulty,1,2,3)", frame(1, NOW_MS));
        RunningAgents.noInputFor(400, "several settleTimes: reading frame 1 again would have settled on it");
        // the robot has stopped elsewhere; new frames show it there
        framesUntilSeen(arch, 2, NOW_MS + 100, "robot(faulty,10,2.5,30)");
        assertTrue(believes(arch, "seen(10,2.5,30)"), "the view is the robot at rest, not the old frame");
    }

    @Test
    void twoFramesTakenMomentsApartAreNotASteadyView() throws Exception {
        // a robot still turning, in two frames taken 10 ms apart: they agree within tolerance
        RosAgArch arch = startLooking(5000, "robot(faulty,1,2,3)", frame(1, NOW_MS));
        await("looking", () -> !arch.getTS().getC().getPendingIntentions().isEmpty());
        camera("robot(faulty,1.2,2,4)", frame(2, NOW_MS + 10));
        await("frame 2 perceived", () -> believes(arch, "cameraFrame(2,_)"));
        framesUntilSeen(arch, 3, NOW_MS + 100, "robot(faulty,10,2.5,30)");
        assertTrue(believes(arch, "seen(10,2.5,30)"), "the view is the robot at rest, not mid-turn");
    }

    @Test
    void afterAMotionAFrameTakenBeforeItEndedIsNotRead() throws Exception {
        RosAgArch arch = agents.start(dir, "watcher", WATCHER);
        camera("robot(faulty,-12,1.5,20)", frame(1, NOW_MS - 2000));
        bridge.perception().perceive("test", new String[] { "moved" }, NOW);
        await("settling", () -> !arch.getTS().getC().getPendingIntentions().isEmpty());
        // the pipeline delivers a newer frame, but one taken before the motion ended
        camera("robot(faulty,-8,1.5,24)", frame(2, NOW_MS - 1000));
        await("frame 2 perceived", () -> believes(arch, "cameraFrame(2,_)"));
        camera("robot(faulty,0.5,1.5,32)", frame(3, NOW_MS + 60));
        await("the view after the motion", () -> believes(arch, "seen(_,_,_)"));
        assertTrue(believes(arch, "seen(0.5,1.5,32)"));
    }

    private static String frame(int number, long stampMs) {
        return "cameraFrame(" + number + "," + stampMs + ")";
    }

    /** Frames from number first on, 100 ms apart from firstStamp, until the view settles or is given up. */
    private void framesUntilSeen(RosAgArch arch, int first, long firstStamp, String robot)
            throws InterruptedException {
        long deadline = System.currentTimeMillis() + RunningAgents.WAIT_MS;
        for (int n = 0; !believes(arch, "seen(_,_,_)") && !believes(arch, "unsteady"); n++) {
            assertTrue(System.currentTimeMillis() < deadline, "the view settles");
            camera(robot, frame(first + n, firstStamp + 100L * n));
            Thread.sleep(20);
        }
    }

    @Test
    void aCameraWithoutAFrameCounterIsReadTwiceSettleTimeApart() throws Exception {
        RosAgArch arch = startLooking(5000, "robot(faulty,1,2,3)");
        await("a steady view", () -> believes(arch, "seen(_,_,_)") || believes(arch, "unsteady"));
        assertTrue(believes(arch, "seen(1,2,3)"), () -> arch.getTS().getAg().getBB().toString());
    }

    @Test
    void aCameraThatStopsGivesNoSteadyView() throws Exception {
        RosAgArch arch = startLooking(300, "robot(faulty,1,2,3)", frame(7, NOW_MS));
        await("the view given up", () -> believes(arch, "seen(_,_,_)") || believes(arch, "unsteady"));
        assertTrue(believes(arch, "unsteady"));
        assertFalse(believes(arch, "seen(_,_,_)"));
    }
}
