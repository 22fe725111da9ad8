package rason.casestudy;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static rason.bridge.RunningAgents.believes;

import java.nio.file.Path;
import java.util.Locale;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;

import jason.asSyntax.Literal;
import jason.asSyntax.NumberTerm;
import jason.asSyntax.Term;
import jason.asSemantics.Unifier;
import rason.RosAgArch;
import rason.bridge.Bridge;
import rason.bridge.Outbound;
import rason.core.Protocol;
import rason.bridge.RunningAgents;

/**
 * The helper keeps a robot that moved towards the edge of its view in view (helper.asl,
 * !currentView): it turns to it, and reports where it saw the robot in the view it first
 * looked from. Real Jason on the helper's own file; the camera is played by the test with a
 * model of what the helper sees after it turned.
 */
class HelperKeepsInViewTest {

    private static final Path HELPER = Path.of("..", "src", "rason", "agents", "case_study", "helper.asl")
            .toAbsolutePath().normalize();
    private static final long NOW = 100 * RunningAgents.SECOND;

    private static final String WATCHER = "{ include(\"" + HELPER + "\") }\n" + """
            helping(faulty).
            +go <- -settleTime(_); +settleTime(30); !look.
            +!look <- !currentView(faulty, D, P, Y); +seen(D, P, Y).
            -!look <- +unseen.
            """;

    private final Bridge bridge = new Bridge();
    @RegisterExtension
    final RunningAgents agents = new RunningAgents(bridge);
    private int frame = 0;
    /** ROS time: each frame is taken FRAME_PERIOD after the last, and the bridge hears of it. */
    private long now = NOW;
    private static final long FRAME_PERIOD = 10_000_000L;

    @TempDir
    Path dir;


    /**
     * One camera frame, taken now: the robot (angle, depth, yaw) as the helper sees it, or
     * nothing (null).
     */
    private void camera(double[] robot) {
        frame++;
        now += FRAME_PERIOD;
        bridge.tick(now);
        String counter = "cameraFrame(" + frame + "," + now / 1_000_000 + ")";
        if (robot == null)
            bridge.perception().perceive("vision_synth_robots", new String[] { counter }, now);
        else
            bridge.perception().perceive("vision_synth_robots", new String[] { String.format(Locale.ROOT,
                    "robot(faulty,%.2f,%.3f,%.2f)", robot[0], robot[1], robot[2]), counter }, now);
    }

    private void heading(double radians) {
        bridge.perception().perceive("odom", new String[] { String.format(Locale.ROOT, "pos(1,2,%.4f)", radians) }, now);
    }

    /**
     * What the helper sees of a robot seen at (angle, depth, yaw) once it has turned
     * turnedCw degrees clockwise about its axis (angles clockwise-positive, yaw = heading +
     * angle, depth along the optical axis: vision_synth's conventions).
     */
    static double[] afterTurning(double angle, double depth, double yaw, double turnedCw) {
        double[] robot = CameraFrames.robotSeenAt(new double[] { angle, depth, yaw });
        return CameraFrames.view(new double[] { 0, 0, -Math.toRadians(turnedCw) }, robot);
    }

    /** Frames of the robot at robot until the helper asks for an action; that action. */
    private Outbound.Action framesUntilAction(double[] robot) throws InterruptedException {
        return CameraFrames.expectAction(bridge, () -> camera(robot), RunningAgents.WAIT_MS);
    }

    /** Frames of the robot at robot until the helper has its view (or gave up). */
    private void framesUntilSeen(RosAgArch arch, double[] robot) throws InterruptedException {
        long deadline = System.currentTimeMillis() + RunningAgents.WAIT_MS;
        while (!believes(arch, "seen(_,_,_)") && !believes(arch, "unseen")) {
            assertTrue(System.currentTimeMillis() < deadline, "the helper settles on a view");
            camera(robot);
            Thread.sleep(20);
        }
    }

    private static double[] seen(RosAgArch arch) {
        Unifier u = new Unifier();
        Literal query = Literal.parseLiteral("seen(D,P,Y)");
        assertTrue(arch.getTS().getAg().believes(query, u), "the helper has a view");
        double[] v = new double[3];
        int i = 0;
        for (String name : new String[] { "D", "P", "Y" }) {
            Term t = u.get(name);
            try {
                v[i++] = ((NumberTerm) t).solve();
            } catch (Exception e) {
                throw new AssertionError(name + " is not a number: " + t, e);
            }
        }
        return v;
    }

    private static void assertView(double[] expected, double[] actual) {
        assertEquals(expected[0], actual[0], 0.1, "angle");
        assertEquals(expected[1], actual[1], 0.005, "depth");
        assertEquals(expected[2], actual[2], 0.2, "yaw");
    }

    private void turned(Outbound.Action turn) {
        assertTrue(bridge.actions().event("watcher", Protocol.ACTION_FEEDBACK, new String[] { Protocol.OK, "" + turn.actionId() }));
    }

    @Test
    void aRobotNearTheEdgeIsCentredAndReportedAsSeenBeforeTheTurn() throws Exception {
        RosAgArch arch = agents.start(dir, "watcher", WATCHER);
        double[] robot = { 24, 1.5, -66 };
        heading(0.5);
        camera(robot);
        bridge.perception().perceive("test", new String[] { "go" }, now);
        Outbound.Action turn = framesUntilAction(robot);
        assertEquals("turn", turn.action());
        assertEquals(24.0, Double.parseDouble(turn.parameters()[0]), 0.01);
        // the base overshoots to 27 degrees; its odometry says so
        heading(0.5 - Math.toRadians(27));
        turned(turn);
        framesUntilSeen(arch, afterTurning(24, 1.5, -66, 27));
        assertView(robot, seen(arch));
    }

    @Test
    void aRobotLostAtTheEdgeIsLookedForWhereItWasSeenLast() throws Exception {
        RosAgArch arch = agents.start(dir, "watcher", WATCHER);
        camera(new double[] { 26, 1.4, -70 });
        RunningAgents.await("the sighting noted", () -> believes(arch, "lastSeen(faulty,26)"));
        camera(null); // it went on out of the view
        bridge.perception().perceive("test", new String[] { "go" }, now);
        Outbound.Action turn = framesUntilAction(null);
        assertEquals("turn", turn.action());
        assertEquals(26.0, Double.parseDouble(turn.parameters()[0]), 0.01);
        turned(turn); // no odometry: the turn counts as commanded
        double[] robot = { 31, 1.3, -65 };
        framesUntilSeen(arch, afterTurning(31, 1.3, -65, 26));
        assertView(robot, seen(arch));
    }

    @Test
    void aRobotWellInsideTheViewIsReadWhereItIs() throws Exception {
        RosAgArch arch = agents.start(dir, "watcher", WATCHER);
        double[] robot = { -9.5, 1.7, -100 };
        camera(robot);
        bridge.perception().perceive("test", new String[] { "go" }, now);
        framesUntilSeen(arch, robot);
        assertView(robot, seen(arch));
        assertNull(bridge.outbox().poll(), "no turn");
    }

    @Test
    void theModelOfTheTurnIsItsOwnInverse() {
        double[] there = afterTurning(20, 1.5, -60, 20);
        double[] back = afterTurning(there[0], there[1], there[2], -20);
        assertView(new double[] { 20, 1.5, -60 }, back);
    }
}
