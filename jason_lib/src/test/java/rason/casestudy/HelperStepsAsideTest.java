package rason.casestudy;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;

import jason.asSemantics.Unifier;
import jason.asSyntax.Literal;
import jason.asSyntax.NumberTerm;
import rason.RosAgArch;
import rason.bridge.Bridge;
import rason.bridge.Outbound;
import rason.core.Protocol;
import rason.bridge.RunningAgents;

/**
 * The helper steps aside when it cannot see the robot after the robot moved (helper.asl,
 * -!reportFeedback, thesis §7.5 and §8.1: the observer repositions), and reports where it
 * saw the robot from there in the view it first looked from. Real Jason on the helper's own
 * file; the test plays the camera (a model of what the helper sees from a pose), the base
 * and its odometry.
 */
class HelperStepsAsideTest {

    private static final Path HELPER = Path.of("..", "src", "rason", "agents", "case_study", "helper.asl")
            .toAbsolutePath().normalize();
    private static final long FRAME_PERIOD = 10_000_000L;
    /** Where the helper first saw the robot steadily (odometry: x, y, heading CCW). */
    private static final double[] VIEWPOINT = { 1.0, 2.0, 0.5 };

    private final Bridge bridge = new Bridge();
    @RegisterExtension
    final RunningAgents agents = new RunningAgents(bridge);
    private int frame = 0;
    private long now = 100 * RunningAgents.SECOND;
    /** The helper's pose as its odometry has it. */
    private final double[] pose = VIEWPOINT.clone();

    @TempDir
    Path dir;

    /** The robot in the odometry frame (x, y, heading CCW), 1.6 m ahead and a little left. */
    private static double[] robotAt() {
        double th = VIEWPOINT[2];
        double ahead = CameraFrames.CAMERA_AHEAD + 1.6, left = 0.1;
        return new double[] { VIEWPOINT[0] + ahead * Math.cos(th) - left * Math.sin(th),
                VIEWPOINT[1] + ahead * Math.sin(th) + left * Math.cos(th), th + 0.4 };
    }

    /** Faulty, in the same process: notes the helper's answer. */
    private static final String FAULTY = """
            +!feedback(I, C)[source(helper)] <- +answer(feedback(I, C)).
            +!noFeedback(Why)[source(helper)] <- +answer(noFeedback(Why)).
            """;

    /** The helper (first seen the robot at then) and the faulty agent, in one process. */
    private RosAgArch start(String then) throws Exception {
        Files.writeString(dir.resolve("faulty.asl"), FAULTY);
        agents.start(dir, "helper", agent(then), "; faulty"); // the .mas2j's second agent
        return agents.arch("faulty");
    }

    private static String agent(String then) {
        return "{ include(\"" + HELPER + "\") }\n" + "helping(faulty).\n"
                + "+go <- -settleTime(_); +settleTime(30); -maxSteadyReads(_); +maxSteadyReads(4);\n"
                + "  -+foundRobot(faulty," + then + ");\n"
                + String.format(Locale.ROOT, "  -+viewpoint(%.4f,%.4f,%.4f); !reportFeedback(faulty).%n",
                        VIEWPOINT[0], VIEWPOINT[1], VIEWPOINT[2]);
    }

    private void odometry() {
        bridge.perception().perceive("odom", new String[] { String.format(Locale.ROOT, "pos(%.5f,%.5f,%.5f)", pose[0], pose[1], pose[2]) },
                now);
    }

    /** One camera frame, now, with the odometry: the robot as seen from the helper's pose, or nothing. */
    private void camera(boolean visible) {
        frame++;
        now += FRAME_PERIOD;
        bridge.tick(now);
        odometry();
        String counter = "cameraFrame(" + frame + "," + now / 1_000_000 + ")";
        if (!visible) {
            bridge.perception().perceive("vision_synth_robots", new String[] { counter }, now);
            return;
        }
        double[] v = CameraFrames.view(pose, robotAt());
        bridge.perception().perceive("vision_synth_robots", new String[] {
                String.format(Locale.ROOT, "robot(faulty,%.2f,%.3f,%.2f)", v[0], v[1], v[2]), counter }, now);
    }

    /** Frames until the helper asks for an action; that action. */
    private Outbound.Action next(boolean visible) throws InterruptedException {
        return CameraFrames.expectAction(bridge, () -> camera(visible), RunningAgents.WAIT_MS);
    }

    /** Frames until the faulty agent believes answer; its text. */
    private String answer(RosAgArch faulty, boolean visible) throws InterruptedException {
        Literal query = Literal.parseLiteral("answer(A)");
        long deadline = System.currentTimeMillis() + RunningAgents.WAIT_MS;
        while (System.currentTimeMillis() < deadline) {
            camera(visible);
            Unifier u = new Unifier();
            if (faulty.getTS().getAg().believes(query, u))
                return u.get("A").toString();
            Outbound item = bridge.outbox().take(20);
            assertTrue(!(item instanceof Outbound.Action), "no more actions: " + item);
        }
        throw new AssertionError("the helper did not answer");
    }

    /** The base does the action (its odometry follows exactly) and reports it done. */
    private void perform(Outbound.Action action) {
        double arg = Double.parseDouble(action.parameters()[0]);
        if (action.action().equals("turn"))
            pose[2] -= Math.toRadians(arg); // clockwise-positive degrees
        else if (action.action().equals("move")) {
            pose[0] += arg * Math.cos(pose[2]);
            pose[1] += arg * Math.sin(pose[2]);
        } else
            throw new AssertionError("unexpected action " + action);
        odometry();
        assertTrue(bridge.actions().event("helper", Protocol.ACTION_FEEDBACK, new String[] { Protocol.OK, "" + action.actionId() }));
    }

    /**
     * A side step: turn left, move, turn back to the robot; the actions' texts. The robot is
     * hidden until the step starts, then visible or not.
     */
    private List<String> stepAside(boolean visible) throws InterruptedException {
        List<String> done = new ArrayList<>();
        for (int i = 0; i < 3; i++) {
            Outbound.Action action = next(i > 0 && visible);
            done.add(action.action() + "(" + action.parameters()[0] + ")");
            perform(action);
        }
        return done;
    }

    private static double[] numbers(String text, String functor) {
        Matcher m = Pattern.compile(functor + "\\(([-0-9.e]+),([-0-9.e]+),([-0-9.e]+)\\)").matcher(text);
        assertTrue(m.find(), functor + " in " + text);
        return new double[] { Double.parseDouble(m.group(1)), Double.parseDouble(m.group(2)),
                Double.parseDouble(m.group(3)) };
    }

    private static void assertView(double[] expected, double[] actual) {
        assertEquals(expected[0], actual[0], 0.1, "angle");
        assertEquals(expected[1], actual[1], 0.005, "depth");
        assertEquals(expected[2], actual[2], 0.2, "yaw");
    }

    private static String text(double[] v) {
        return String.format(Locale.ROOT, "%.2f,%.3f,%.2f", v[0], v[1], v[2]);
    }

    @Test
    void hiddenFromTheLeftSeenFromTheRightIsReportedAsSeenFromWhereItFirstLooked() throws Exception {
        double[] first = { -3.0, 1.5, 2.0 };
        RosAgArch faulty = start(text(first));
        odometry();
        bridge.perception().perceive("test", new String[] { "go" }, now);

        List<String> left = stepAside(false);
        assertEquals("turn(-90)", left.get(0));
        assertEquals("move(0.3)", left.get(1));
        assertEquals("turn", left.get(2).substring(0, 4));
        assertTrue(Double.parseDouble(left.get(2).substring(5, left.get(2).length() - 1)) > 90, "back and towards the robot");
        List<String> right = stepAside(true); // still hidden from the left: to the right
        assertEquals("turn(-90)", right.get(0));
        assertEquals("move(-0.6)", right.get(1));

        String feedback = answer(faulty, true);
        assertTrue(feedback.startsWith("feedback("), feedback);
        assertView(first, numbers(feedback, "initPos"));
        assertView(CameraFrames.view(VIEWPOINT, robotAt()), numbers(feedback, "currPos"));
        assertTrue(Math.abs(pose[0] - VIEWPOINT[0]) + Math.abs(pose[1] - VIEWPOINT[1]) > 0.2, "the helper stands elsewhere");
    }

    @Test
    void hiddenFromBothSidesIsSaidSo() throws Exception {
        RosAgArch faulty = start("0,1.5,0");
        odometry();
        bridge.perception().perceive("test", new String[] { "go" }, now);
        stepAside(false);
        stepAside(false);
        assertEquals("noFeedback(\"the helper lost sight of the robot after it moved\")", answer(faulty, false));
    }

    @Test
    void theRuleUndoesATurnAndAStepAnywhere() throws Exception {
        RosAgArch arch = agents.start(dir, "helper", "{ include(\"" + HELPER + "\") }\n");
        double[] robot = robotAt();
        double[][] poses = { { 1.3, 1.7, 0.2 }, { 0.7, 2.4, 1.1 }, { 1.0, 2.0, 0.5 + Math.toRadians(170) + Math.PI } };
        for (double[] there : poses) {
            double[] seen = CameraFrames.view(there, robot);
            if (seen[1] <= 0)
                continue; // behind the camera
            Literal query = Literal.parseLiteral(String.format(Locale.ROOT,
                    "beforeMoving(pos(%.5f,%.5f,%.5f),pos(%.5f,%.5f,%.5f),%.2f,%.3f,%.2f,D,P,Y)",
                    VIEWPOINT[0], VIEWPOINT[1], VIEWPOINT[2], there[0], there[1], there[2], seen[0], seen[1], seen[2]));
            Unifier u = new Unifier();
            assertTrue(arch.getTS().getAg().believes(query, u), "the rule holds for " + query);
            double[] back = new double[3];
            String[] names = { "D", "P", "Y" };
            for (int i = 0; i < 3; i++)
                back[i] = ((NumberTerm) u.get(names[i])).solve();
            assertView(CameraFrames.view(VIEWPOINT, robot), back);
        }
    }
}
