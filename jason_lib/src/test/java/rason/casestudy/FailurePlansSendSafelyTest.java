package rason.casestudy;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;

import rason.bridge.Bridge;
import rason.bridge.Outbound;
import rason.bridge.RunningAgents;
import rason.core.Protocol;

/**
 * A failure plan of the case study whose message cannot be sent (the robot it answers is
 * gone) ends: Jason runs a failure plan that fails again while its goal is the first of the
 * intention, as a goal a message asked for is, so a bare .send there looped for ever. Real
 * Jason on the agents' own files.
 */
class FailurePlansSendSafelyTest {

    private static final Path AGENTS = Path.of("..", "src", "rason", "agents", "case_study")
            .toAbsolutePath().normalize();

    private final Bridge bridge = new Bridge();
    @RegisterExtension
    final RunningAgents agents = new RunningAgents(bridge);
    private final StringBuilder printed = new StringBuilder();

    @TempDir
    Path dir;

    private String printed() {
        printed.append(bridge.log().drainBatch(1000).text());
        return printed.toString();
    }

    private static int count(String text, String part) {
        return text.split(java.util.regex.Pattern.quote(part), -1).length - 1;
    }

    /** Starts agent with file and posts goal as a new intention, as a message would. */
    private void start(String agent, String file, String goal) throws Exception {
        agents.start(dir, agent, "{ include(\"" + AGENTS.resolve(file) + "\") }\n+go <- !!" + goal + ".\n");
        bridge.perception().perceive("test", new String[] { "go" }, 100 * RunningAgents.SECOND);
    }

    /** What the agent printed once its failure plan said it could not send, and a while after. */
    private String printedAfterTheFailedSend() throws Exception {
        RunningAgents.await("the failure plan's message to fail", () -> printed().contains("could not send"));
        RunningAgents.noInputFor(500, "a looping failure plan would print again");
        return printed();
    }

    @Test
    void theHelpersAnswerToATrackRequestItCannotServeEndsOnce() throws Exception {
        start("helper", "helper.asl", "trackMe[source(faulty)]");
        String text = printedAfterTheFailedSend();
        assertEquals(1, count(text, "could not send"), text);
    }

    @Test
    void faultysThanksForAMoveThatFailedOtherwiseEndsWithTheDiagnosis() throws Exception {
        start("faulty", "faulty.asl", "tryMove[source(helper)]");
        Outbound.Action move = agents.next(Outbound.Action.class);
        assertEquals("move", move.action());
        assertTrue(bridge.actions().event("faulty", Protocol.ACTION_FEEDBACK,
                new String[] { Protocol.TIMEOUT, "" + move.actionId() }));
        String text = printedAfterTheFailedSend();
        assertEquals(1, count(text, "could not send"), text);
        // the plan went on after the message it could not send: the diagnosis
        assertEquals("report_diagnosis", agents.next(Outbound.Action.class).action());
    }
}
