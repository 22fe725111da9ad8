package rason.casestudy;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static rason.bridge.RunningAgents.believes;

import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;

import rason.RosAgArch;
import rason.bridge.Bridge;
import rason.bridge.Outbound;
import rason.bridge.RunningAgents;

/**
 * Faulty, needing help while no other robot is in reach (still starting, or its first contact
 * slow on a lossy link), waits for one up to helpTimeout before it asks, and only then gives
 * the diagnosis up (faulty.asl, !askForHelp). Real Jason on Faulty's own file; a helper agent
 * created later plays the robot that comes into reach.
 */
class FaultyWaitsForAHelperInReachTest {

    private static final Path FAULTY = Path.of("..", "src", "rason", "agents", "case_study", "faulty.asl")
            .toAbsolutePath().normalize();

    private final Bridge bridge = new Bridge();
    @RegisterExtension
    final RunningAgents agents = new RunningAgents(bridge);

    @TempDir
    Path dir;

    private RosAgArch faulty(String timeoutMs) throws Exception {
        Files.writeString(dir.resolve("helper.asl"), "+!helpme[source(S)] <- +askedForHelp(S).\n");
        String trial = "{ include(\"" + FAULTY + "\") }\n"
                + "+ask <- -+helpTimeout(" + timeoutMs + "); !askForHelp.\n"
                + "+arrive <- .create_agent(helper, \"" + dir.resolve("helper.asl") + "\").\n";
        return agents.start(dir, "faulty", trial);
    }

    @Test
    void aRobotComingIntoReachIsAskedForHelp() throws Exception {
        RosAgArch faulty = faulty("120000");
        bridge.perception().perceive("test", new String[] { "ask" }, 101 * RunningAgents.SECOND);
        RunningAgents.noInputFor(300, "Faulty waits with nobody in reach");
        assertFalse(believes(faulty, "diagnosed(_)"), "not given up while waiting");
        bridge.perception().perceive("test", new String[] { "ask", "arrive" }, 102 * RunningAgents.SECOND);
        RunningAgents.await("the helper in reach was asked for help", () -> {
            RosAgArch helper = agents.arch("helper");
            return helper != null && believes(helper, "askedForHelp(faulty)");
        });
        assertFalse(believes(faulty, "diagnosed(_)"));
    }

    @Test
    void nobodyInReachWithinHelpTimeoutIsUndiagnosedWithTheReason() throws Exception {
        faulty("2000");
        bridge.perception().perceive("test", new String[] { "ask" }, 101 * RunningAgents.SECOND);
        bridge.tick(104 * RunningAgents.SECOND);          // helpTimeout passes in ROS time
        Outbound.Action report = agents.next(Outbound.Action.class);
        while (!report.action().equals("report_diagnosis"))
            report = agents.next(Outbound.Action.class);
        assertArrayEquals(new String[] { "undiagnosed", "no other robot to ask for help" }, report.parameters());
        assertEquals("faulty", report.agent());
    }
}
