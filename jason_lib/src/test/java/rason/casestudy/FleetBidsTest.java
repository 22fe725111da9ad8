package rason.casestudy;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;

import jason.asSemantics.Unifier;
import jason.asSyntax.Literal;
import jason.asSyntax.NumberTerm;
import rason.RosAgArch;
import rason.bridge.Bridge;
import rason.bridge.RunningAgents;

/**
 * What a robot of the fleet program bids to watch a caller (agents/fleet/fleet_robot.asl, the
 * rule bid/3): degrees to turn before its camera faces the caller, from the camera when it sees
 * the caller, else from both poses in a shared frame (after a drive to a viewpoint, when it would
 * see the caller side-on), else a full search; nothing while its own mission has not ended
 * without a fault. Real Jason on the program's file.
 */
class FleetBidsTest {

    private static final Path FLEET_ROBOT = Path.of("..", "src", "rason", "agents", "fleet", "fleet_robot.asl")
            .toAbsolutePath().normalize();

    private final Bridge bridge = new Bridge();
    @RegisterExtension
    final RunningAgents agents = new RunningAgents(bridge);
    @TempDir
    Path dir;
    private long now = 100 * RunningAgents.SECOND;

    private RosAgArch watcher(String... perceptions) throws Exception {
        return watcherWith("", perceptions);
    }

    /** The same, with plans added to the program. */
    private RosAgArch watcherWith(String plans, String... perceptions) throws Exception {
        RosAgArch arch = agents.start(dir, "w", "{ include(\"" + FLEET_ROBOT + "\") }\n" + plans);
        perceive(perceptions);
        return arch;
    }

    private void perceive(String... literals) throws InterruptedException {
        now += RunningAgents.SECOND / 10;
        bridge.tick(now);
        bridge.perception().perceive("test", literals, now);
        RosAgArch arch = agents.arch("w");
        RunningAgents.await("the perceptions to be beliefs",
                () -> java.util.Arrays.stream(literals).allMatch(l -> RunningAgents.believes(arch, l)));
    }

    /** The bid for task, null if none. */
    private static Double bid(RosAgArch arch, String task) throws Exception {
        Unifier u = new Unifier();
        if (!arch.getTS().getAg().believes(Literal.parseLiteral("bid(" + task + ",f,B)"), u))
            return null;
        return ((NumberTerm) u.get("B")).solve();
    }

    @Test
    void theTurnToFaceTheCallerInTheSharedFrameClockwise() throws Exception {
        RosAgArch w = watcher("diagnosed(none)", "mapPose(1,1,0)"); // at (1, 1), facing +x
        assertEquals(0, bid(w, "help(f,at(3,1,0))"), 0.01, "ahead");
        assertEquals(90, bid(w, "help(f,at(1,0,1.5708))"), 0.01, "on my right: a quarter turn clockwise");
        assertEquals(270, bid(w, "help(f,at(1,2,1.5708))"), 0.01, "on my left: the search turns clockwise");
        assertEquals(180, bid(w, "help(f,at(0,1,0))"), 0.01, "behind");
        assertEquals(45, bid(w, "help(f,at(2,0,2.3562))"), 0.01);
    }

    @Test
    void aCallerISeeSideOnCostsTheDriveToAViewpointAfterEveryDirectView() throws Exception {
        // f at (1, 3) facing +x: I, at (1, 1), am on its right, where one of its cylinders hides
        // the other; its viewpoint on my side is 1.5 m ahead of it, (2.5, 3), 2.5 m from me
        RosAgArch w = watcher("diagnosed(none)", "mapPose(1,1,0)", "pos(0,0,0)");
        assertEquals(362.5, bid(w, "help(f,at(1,3,0))"), 0.01);
        assertEquals(362.5, bid(w, "help(f,at(1,3,3.1416))"), 0.01, "facing -x: side-on too, as far");
        assertEquals(90, bid(w, "help(f,at(1,0,1.5708))"), 0.01, "seen from ahead of it: no drive");
        assertEquals(90, bid(w, "help(f,at(1,0,1.1))"), 0.01, "27 degrees off its front is no side-on view");
    }

    @Test
    void aWatchThatEndedLeavesTheBidsAsTheyWere() throws Exception {
        // what a watcher does when its caller releases it (the pair's helper forgets its own
        // viewpoint/3 then): a robot free again bids as before
        RosAgArch w = watcherWith("+!release <- !stopWatching(g); +released.\n",
                "diagnosed(none)", "mapPose(1,1,0)", "pos(0,0,0)");
        w.getTS().getC().addAchvGoal(Literal.parseLiteral("release"), null);
        w.wakeUpSense();
        RunningAgents.await("the watch to end", () -> RunningAgents.believes(w, "released"));
        assertEquals(362.5, bid(w, "help(f,at(1,3,0))"), 0.01, "side-on: the drive to the vantage point");
        assertEquals(0, bid(w, "help(f,at(3,1,0))"), 0.01, "ahead");
    }

    @Test
    void aRobotThatCannotDriveToAViewpointDoesNotBidForACallerItWouldSeeSideOn() throws Exception {
        RosAgArch w = watcher("diagnosed(none)", "mapPose(1,1,0)"); // no odometry: no goto
        assertEquals(null, bid(w, "help(f,at(1,3,0))"));
    }

    @Test
    void aCallerInViewCostsItsAngleInTheCamera() throws Exception {
        RosAgArch w = watcher("diagnosed(none)", "mapPose(1,1,0)", "robot(f,-12.5,2.0,30)");
        assertEquals(12.5, bid(w, "help(f,at(1,2,0))"), 0.01, "the camera, not the shared frame");
        assertEquals(12.5, bid(w, "help(f,unknown)"), 0.01);
    }

    @Test
    void withoutEitherAFullSearch() throws Exception {
        RosAgArch w = watcher("diagnosed(none)");
        assertEquals(360, bid(w, "help(f,unknown)"), 0.01);
        assertEquals(360, bid(w, "help(f,at(3,1,0))"), 0.01, "the caller's pose, but not mine");
    }

    @Test
    void aRobotOnItsMissionOrFaultyDoesNotBid() throws Exception {
        RosAgArch w = watcher("robot(f,3.0,2.0,30)");
        assertTrue(RunningAgents.believes(w, "robot(f,3.0,2.0,30)"));
        assertEquals(null, bid(w, "help(f,unknown)"), "its own mission not ended");
        perceive("diagnosed(left_actuator)", "robot(f,3.0,2.0,30)");
        assertEquals(null, bid(w, "help(f,unknown)"), "faulty itself");
        perceive("diagnosed(none)", "robot(f,3.0,2.0,30)");
        assertFalse(bid(w, "help(f,unknown)") == null, "free");
    }
}
