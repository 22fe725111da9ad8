package rason.casestudy;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static rason.bridge.RunningAgents.believes;

import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.function.BooleanSupplier;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;

import jason.asSemantics.Unifier;
import jason.asSyntax.ASSyntax;
import jason.asSyntax.Literal;
import jason.asSyntax.NumberTerm;
import jason.runtime.RuntimeServicesFactory;
import rason.bridge.Bridge;
import rason.bridge.Outbound;
import rason.bridge.RunningAgents;
import rason.casestudy.FleetWorld.Robot;
import rason.infra.RasonLocalMAS;

/**
 * The case study as one fleet program (agents/fleet/fleet_robot.asl) on real Jason: every
 * robot's agent runs the same file, each perceiving its own robot in a small world the test
 * runs ({@link FleetWorld}). A robot whose moves fail asks the robots with a camera to watch it
 * by contract net; the cheapest bidder is awarded and the two run the case study's dialogue to
 * the diagnosis. A timed-out wait shows what the agents printed; with the environment variable
 * FLEET_TRANSCRIPT=file every test appends it there.
 */
class FleetCaseStudyTest {

    private static final Path FLEET_ROBOT = Path.of("..", "src", "rason", "agents", "fleet", "fleet_robot.asl")
            .toAbsolutePath().normalize();
    /** ms for a whole diagnosis (contract net, search, tracking, the move, the report). */
    private static final long DIAGNOSIS_MS = 30_000;

    private final Bridge bridge = new Bridge();
    @RegisterExtension
    final RunningAgents agents = new RunningAgents(bridge);
    @TempDir
    Path dir;
    private FleetWorld world;
    private boolean sideOnHidden = false;

    @AfterEach
    void stopWorld() throws Exception {
        if (world != null) {
            world.close();
            if (System.getenv("FLEET_TRANSCRIPT") != null)
                java.nio.file.Files.writeString(Path.of(System.getenv("FLEET_TRANSCRIPT")), world.transcript(),
                        java.nio.file.StandardOpenOption.CREATE, java.nio.file.StandardOpenOption.APPEND);
        }
    }

    /**
     * Every robot runs the fleet program; the faulty robots' moves are held until every other
     * robot ended its mission (and, with a camera, offers to watch and has seen a camera frame
     * taken since), so that the calls find them free and their bids are from where they stand.
     */
    private void start(Robot... robots) throws Exception {
        start(1, false, "", robots);
    }

    /** The same, ROS time running speed times as fast as the wall, with tuning added to the program. */
    private void start(int speed, boolean sharedFrame, String tuning, Robot... robots) throws Exception {
        Map<String, String> programs = new LinkedHashMap<>();
        for (Robot r : robots)
            programs.put(r.name, "{ include(\"" + FLEET_ROBOT + "\") }\n" + tuning);
        world = new FleetWorld(bridge, agents, List.of(robots), speed, sharedFrame);
        if (sideOnHidden)
            world.hideSideOn();
        world.park(a -> !fault(robots, a.agent()).equals("none"));
        agents.startAll(dir, programs);
        world.start();
        for (Robot r : robots) {
            if (!r.fault.equals("none"))
                continue;
            await(r.name + " to end its mission", 10_000, () -> believes(agents.arch(r.name), "diagnosed(none)"));
            if (r.camera)
                await(r.name + " to offer to watch", 10_000, () -> believes(agents.arch(r.name), "offering(observe)"));
        }
        int framesBefore = world.frame();
        for (Robot r : robots)
            if (r.camera)
                await(r.name + " to see a frame taken after the missions", 10_000,
                        () -> holds(r.name, "cameraFrame(N,_) & N > " + framesBefore));
        world.releaseParked();
    }

    private static String fault(Robot[] robots, String agent) {
        for (Robot r : robots)
            if (r.name.equals(agent))
                return r.fault;
        return "none";
    }

    private void await(String what, long ms, BooleanSupplier condition) throws InterruptedException {
        long deadline = System.currentTimeMillis() + ms;
        while (!condition.getAsBoolean()) {
            world.check();
            if (System.currentTimeMillis() > deadline)
                throw new AssertionError("timed out waiting for " + what + "; the agents printed:\n" + world.transcript());
            Thread.sleep(10);
        }
    }

    private boolean holds(String agent, String formula) {
        try {
            return agents.arch(agent).getTS().getAg().believes(ASSyntax.parseFormula(formula), new Unifier());
        } catch (Exception e) {
            throw new IllegalStateException(e);
        }
    }

    private boolean awarded(String caller, String helper) {
        return believes(agents.arch(caller), "awarded(_,help(" + caller + ",_)," + helper + ")");
    }

    private boolean watches(String helper, String caller) {
        return believes(agents.arch(helper), "committed(_,help(" + caller + ",_)," + caller + ")");
    }

    private void diagnosed(String caller, String expected) throws InterruptedException {
        await(caller + "'s diagnosis", DIAGNOSIS_MS, () -> world.diagnosis(caller) != null);
        assertEquals(expected, world.diagnosis(caller), caller + "'s diagnosis");
    }

    /** The robot whose feedback the caller's diagnosis used. */
    private String helper(String caller) {
        Unifier u = new Unifier();
        assertTrue(agents.arch(caller).getTS().getAg().believes(Literal.parseLiteral("helpedBy(H)"), u),
                caller + " had feedback");
        return u.get("H").toString();
    }

    /** A turn asked by this robot's agent (it searched or centred). */
    private boolean turned(String robot) {
        return world.done().stream().anyMatch(a -> a.agent().equals(robot) && a.action().equals("turn"));
    }

    @Test
    void theCheapestCameraRobotIsAwardedAndRunsTheDialogueToTheDiagnosis() throws Exception {
        start(new Robot("f", 0, 0, 0, false, "right_actuator"),
                new Robot("a", 0, 2, -75, true, "none"),     // sees f 16 degrees off-centre: bids 16
                new Robot("b", -2, 0, 180, true, "none"),    // has f behind it: a search, 360
                new Robot("c", 2, 0, 190, true, "none"),     // sees f 10 degrees off-centre: 10
                new Robot("d", 0, -2, 90, false, "none"));   // no camera: never called
        await("c to take the help f awarded it", 10_000, () -> awarded("f", "c") && watches("c", "f"));
        diagnosed("f", "right_actuator");
        assertTrue(believes(agents.arch("f"), "helpedBy(c)"), "the feedback came from c");
        assertTrue(turned("c"), "c centred f before tracking it");
        assertFalse(turned("a") || turned("b") || turned("d"), "nobody else searched");
        assertFalse(watches("a", "f") || watches("b", "f") || believes(agents.arch("a"), "helping(_)"));
        await("c to be released", 10_000, () -> !watches("c", "f") && !believes(agents.arch("c"), "helping(_)"));
        RunningAgents.noInputFor(1500, "the pair's Faulty stops the MAS 1 s after its diagnosis");
        assertFalse(world.stopAsked(), "no robot stopped the MAS: the others may still need it");
    }

    @Test
    void withFirstAnswerWinsTheFirstRobotToOfferIsAwardedAloneAndTheDiagnosisIsStillRight() throws Exception {
        // the thesis's broadcast, for the fleet campaign's comparison: no ranking by bid
        start(1, false, "firstAnswerWins.\n", new Robot("f", 0, 0, 0, false, "right_actuator"),
                new Robot("a", 0, 2, -75, true, "none"),     // both see f: either may be first
                new Robot("c", 2, 0, 190, true, "none"));
        diagnosed("f", "right_actuator");
        Matcher call = Pattern.compile("contract contract\\(f,1\\) for help\\(f,\\w+\\): bids (\\[[^\\]]*\\]) from 2 called")
                .matcher(world.transcript());
        assertTrue(call.find(), "f called both camera robots:\n" + world.transcript());
        Matcher offers = Pattern.compile("offer\\([^,]+,(\\w+)\\)").matcher(call.group(1));
        assertTrue(offers.find(), "an offer in " + call.group(1));
        String first = offers.group(1);
        assertFalse(offers.find(), "only the first offer is kept: " + call.group(1));
        assertEquals(first, helper("f"), "the diagnosis used the feedback of the robot that offered first");
    }

    @Test
    void twoRobotsFaultyAtOnceEachGetADifferentHelper() throws Exception {
        start(new Robot("f1", 0, 0.25, 0, false, "right_actuator"),
                new Robot("f2", 0, -0.25, 0, false, "both_actuators"),
                new Robot("a", 2.5, 0, 180, true, "none"),   // sees both 6 degrees off-centre
                new Robot("b", -2.5, 0, 15, true, "none"));  // sees them 10 and 21 degrees off
        diagnosed("f1", "right_actuator");
        diagnosed("f2", "both_actuators");
        String first = helper("f1");
        String second = helper("f2");
        assertTrue(Set.of("a", "b").containsAll(List.of(first, second)), first + " and " + second + " watched");
        assertNotEquals(first, second, "each caller had a helper of its own");
    }

    @Test
    void theHelperKilledMidHelpIsReplacedByTheNextBidderAndTheDiagnosisIsStillRight() throws Exception {
        start(new Robot("f", 0, 0, 0, false, "left_actuator"),
                new Robot("a", 0, 2, -75, true, "none"),     // bids 16
                new Robot("b", -2, 0, 180, true, "none"),    // 360
                new Robot("c", 2, 0, 190, true, "none"));    // 10
        // the move f makes for c to watch (its failed move(1) again, backwards) is held: c
        // dies while f moves for it
        world.park(a -> a.agent().equals("f") && a.action().equals("move") && Double.parseDouble(a.parameters()[0]) < 0);
        await("f to move for c", 10_000, () -> awarded("f", "c") && !world.parked().isEmpty());
        Outbound.Action watched = world.parked().get(0);
        long killed = System.nanoTime();
        assertTrue(RuntimeServicesFactory.get().killAgent("c", "test", 0), "c killed");
        world.remove("c");
        await("f to award the next bidder, a", 5_000, () -> awarded("f", "a"));
        long ms = (System.nanoTime() - killed) / 1_000_000;
        world.note("a was awarded " + ms + " ms after c left");
        assertTrue(ms <= 5000, "a was awarded " + ms + " ms after c left");
        await("the move for c to be taken back", 5_000, () -> world.wasCancelled(watched));
        world.releaseParked();
        diagnosed("f", "left_actuator");
        assertTrue(believes(agents.arch("f"), "helpedBy(a)"), "the feedback came from a");
        assertFalse(watches("b", "f"), "b was not needed");
    }

    @Test
    void aWatcherThatCannotFindTheCallerFailsAndTheNextBidderIsAwarded() throws Exception {
        // every robot knows its pose in a shared frame; so that a's full search takes seconds,
        // ROS time runs 10 times as fast as the wall (as the simulator may) and a search turns
        // 30 degrees a step
        start(10, true, "!tune.\n+!tune <- -+turnRate(30).\n", new Robot("f", 0, 0, 0, false, "right_actuator"),
                new Robot("a", 7, 0, 180, true, "none"),     // faces f, too far to see it: bids 0
                new Robot("b", 0, 2, -75, true, "none"),     // sees f: 16
                new Robot("c", -2, 0, 180, true, "none"));   // f behind it: a half turn, 180
        await("f to award a", 10_000, () -> awarded("f", "a"));
        Unifier u = new Unifier();
        assertTrue(agents.arch("f").getTS().getAg().believes(
                ASSyntax.parseLiteral("contract(_,help(f,at(_,_,_)),[offer(B,b),offer(C,c)])"), u),
                "the other bids kept ranked: the caller sent where it is, each bid from its own pose");
        assertEquals(15.6, ((NumberTerm) u.get("B")).solve(), 0.1);
        assertEquals(180, ((NumberTerm) u.get("C")).solve(), 0.1);
        await("a to give up its search and f to award b", 20_000, () -> awarded("f", "b"));
        assertFalse(watches("a", "f") || believes(agents.arch("a"), "helping(_)"), "a forgot f");
        diagnosed("f", "right_actuator");
        assertTrue(believes(agents.arch("f"), "helpedBy(b)"), "the feedback came from b");
    }

    @Test
    void aWatcherThatWouldSeeTheCallerSideOnLooksFromAheadOfIt() throws Exception {
        // b, the only watcher, stands on f's left, where the camera sees one of f's cylinders
        // behind the other and so no robot: it drives to 1.5 m ahead of f first, then faces it
        sideOnHidden = true;
        start(10, true, "", new Robot("f", 0, 0, 0, false, "both_actuators"),
                new Robot("b", 0, 2.5, -90, true, "none"));
        await("f to award b", 10_000, () -> awarded("f", "b"));
        diagnosed("f", "both_actuators");
        assertTrue(believes(agents.arch("f"), "helpedBy(b)"), "the feedback came from b");
        assertTrue(world.done().stream().anyMatch(a -> a.agent().equals("b") && a.action().equals("goto")
                && Math.abs(Double.parseDouble(a.parameters()[0]) - 1.5) < 0.05
                && Math.abs(Double.parseDouble(a.parameters()[1])) < 0.05), "b drove to 1.5 m ahead of f");
    }

    @Test
    void aCameraThatNamesRobotsAsTheWorldDoesStillFindsTheCaller() throws Exception {
        // fleet.launch's vision_synth reports the robot r1, whose agent is r1_robot
        start(new Robot("r1_robot", 0, 0, 0, false, "both_actuators", "r1"),
                new Robot("r2_robot", 0, 2, -75, true, "none", "r2"),
                new Robot("r3_robot", 2, 0, 190, true, "none", "r3"));
        await("r3_robot, which sees r1 closer to the centre, to take the help", 10_000,
                () -> awarded("r1_robot", "r3_robot") && watches("r3_robot", "r1_robot"));
        diagnosed("r1_robot", "both_actuators");
        assertTrue(believes(agents.arch("r1_robot"), "helpedBy(r3_robot)"));
        assertTrue(turned("r3_robot"), "r3_robot centred r1 before tracking it");
    }

    @Test
    void theFleetsMas2jRunsTheProgramUnderEachRobotsPrefix() throws Exception {
        Path mas2j = FLEET_ROBOT.resolveSibling("fleet_robot.mas2j");
        bridge.attach();
        RasonLocalMAS mas = bridge.newMas();
        try {
            mas.setAgentPrefix("r1_");
            mas.load(mas2j.toString());
            mas.create();
            var robot = mas.getAg("r1_robot");
            assertTrue(robot != null, "the agent named by the robot's prefix");
            String plans = robot.getTS().getAg().getPL().getAsTxt(false);
            for (String plan : List.of("+!contract(", "+!carryOut(help(", "+!tryMove", "+!findRobot(", "+!sendSafely("))
                assertTrue(plans.contains(plan), "the included files' plans: " + plan);
        } finally {
            assertTrue(mas.stopAgents(5000));
            bridge.detach();
        }
    }
}
