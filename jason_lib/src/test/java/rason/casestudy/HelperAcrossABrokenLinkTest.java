package rason.casestudy;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static rason.bridge.RunningAgents.believes;

import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;

import jason.asSyntax.Literal;
import jason.asSemantics.Unifier;
import rason.RosAgArch;
import rason.bridge.Bridge;
import rason.bridge.Outbound;
import rason.bridge.RunningAgents;

/**
 * The helper (helper.asl with helper_recovery.asl) when the link to the robot it works for
 * breaks and heals, as on a lossy link between hosts where presence drops for seconds: a
 * robot it guides is guided on within partnerGrace, and a robot it stopped helping is told
 * why. Real Jason on the helper's own files; the test plays presence and the faulty agent.
 */
class HelperAcrossABrokenLinkTest {

    private static final Path HELPER = Path.of("..", "src", "rason", "agents", "case_study", "helper.asl")
            .toAbsolutePath().normalize();
    private static final String FLEET = "fleet";

    /** Faulty, in the same process: asks what the test says and notes the helper's answer. */
    private static final String FAULTY = """
            +ask(G) <- .send(helper, achieve, G).
            +!noFeedback(Why)[source(helper)] <- +answer(noFeedback(Why)).
            +!feedback(I, C)[source(helper)] <- +answer(feedback(I, C)).
            """;

    private final Bridge bridge = new Bridge();
    @RegisterExtension
    final RunningAgents agents = new RunningAgents(bridge);

    @TempDir
    Path dir;
    private long now = 100 * RunningAgents.SECOND;

    private static String helper(int graceMs) {
        return "{ include(\"" + HELPER + "\") }\n"
                + "+go <- -+partnerGrace(" + graceMs + "); !guideMe[source(faulty)].\n";
    }

    /** The helper alone: faulty is a robot of another process, present while the test says so. */
    private RosAgArch guiding(int graceMs) throws Exception {
        RosAgArch helper = agents.start(dir, "helper", helper(graceMs));
        present(true);
        return helper;
    }

    /** The helper and the faulty agent in one process (which stays present to the helper). */
    private RosAgArch withFaulty() throws Exception {
        Files.writeString(dir.resolve("faulty.asl"), FAULTY);
        agents.start(dir, "helper", helper(300), "; faulty"); // the .mas2j's second agent
        return agents.arch("faulty");
    }

    /** Perceptions stamped with the bridge's clock, a tick after the last ones. */
    private void perceive(String source, String... literals) {
        now += 100_000_000L;
        bridge.tick(now);
        bridge.perception().perceive(source, literals, now);
    }

    private void present(boolean present) {
        perceive(FLEET, present ? new String[] { "present(faulty)" } : new String[0]);
    }

    private void say(String source, String literal) {
        perceive(source, literal);
    }

    /** The next item the agents queue: the guide action. */
    private Outbound.Action guideAction() throws InterruptedException {
        Outbound.Action action = agents.next(Outbound.Action.class);
        assertEquals("guide", action.action(), "the helper guides: " + action);
        return action;
    }

    private String answer(RosAgArch faulty) throws InterruptedException {
        Literal query = Literal.parseLiteral("answer(A)");
        Unifier u = new Unifier();
        RunningAgents.await("the helper's answer", () -> faulty.getTS().getAg().believes(query, u));
        return u.get("A").toString();
    }

    @Test
    void aGuidedRobotBackWithinTheGraceIsGuidedOn() throws Exception {
        RosAgArch helper = guiding(1500);
        say("test", "go");
        Outbound.Action guide = guideAction();
        present(false);
        present(true);
        RunningAgents.noInputFor(2000, "past the grace: nothing may end the guiding");
        assertTrue(believes(helper, "guiding(faulty)"), "still guiding");
        Outbound item = bridge.outbox().poll();
        assertFalse(item instanceof Outbound.Cancel, "the guide action is not taken back: " + item);
    }

    @Test
    void aGuidedRobotNotBackWithinTheGraceIsNoLongerGuided() throws Exception {
        RosAgArch helper = guiding(300);
        say("test", "go");
        Outbound.Action guide = guideAction();
        present(false);
        RunningAgents.await("the guiding to end", () -> !believes(helper, "guiding(faulty)"));
        Outbound.Cancel cancel = agents.next(Outbound.Cancel.class);
        assertEquals(guide.actionId(), cancel.actionId());
    }

    @Test
    void aRobotNoLongerHelpedThatAsksToBeTrackedIsToldWhy() throws Exception {
        RosAgArch faulty = withFaulty();
        say("test", "ask(trackMe)");
        assertEquals("noFeedback(\"the helper had stopped helping: the robot was out of reach for longer than its grace\")",
                answer(faulty));
    }

    @Test
    void aRobotNoLongerHelpedThatAsksForFeedbackIsToldWhy() throws Exception {
        RosAgArch faulty = withFaulty();
        say("test", "ask(giveFeedback)");
        assertTrue(answer(faulty).startsWith("noFeedback(\"the helper had stopped helping"));
    }
}
