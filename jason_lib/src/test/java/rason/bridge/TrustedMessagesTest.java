package rason.bridge;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static rason.bridge.RunningAgents.await;
import static rason.bridge.RunningAgents.believes;

import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;

import jason.asSyntax.ASSyntax;
import jason.asSyntax.Trigger;
import rason.RosAgArch;
import rason.messaging.TrustPolicy;

/**
 * Messages from agents of another process pass the receiver's trust policy:
 * a plan told by a robot the agent does not trust never reaches Jason, one
 * told by a trusted robot does, and the answer to the agent's own askHow gets
 * in from the robot it asked and from nobody else.
 */
class TrustedMessagesTest {

    private static final String OTHER_MAS = "/robot2/rason_mas";
    private static final String PLAN = "\"+!trick <- +tricked.\"";

    private final Bridge bridge = new Bridge();
    @RegisterExtension
    final RunningAgents agents = new RunningAgents(bridge);

    @TempDir
    Path dir;


    /** A test key (never used outside tests): both processes of the test share it. */
    private static final String KEY = "test-trust-key-0123456789abcdef0123456789abcdef";

    /** robot2's rason_mas: signs what it sends with the fleet key. */
    private OtherRobot otherRobot;

    private RosAgArch start(String agent, String program) throws Exception {
        bridge.fleet().setMasId("/robot1/rason_mas");
        otherRobot = new OtherRobot(bridge, OTHER_MAS, KEY);
        otherRobot.announce(new String[] { "carol", "mallory" }, false);
        return agents.start(dir, agent, program);
    }

    private int fromOtherRobot(String sender, String receiver, String performative, String content, String inReplyTo) {
        return otherRobot.send(sender, receiver, performative, content, inReplyTo);
    }

    private static boolean hasPlanFor(RosAgArch arch, String goal) {
        Trigger t = new Trigger(Trigger.TEOperator.add, Trigger.TEType.achieve, ASSyntax.createLiteral(goal));
        return arch.getTS().getAg().getPL().hasCandidatePlan(t);
    }

    @Test
    void byDefaultAPlanToldByAnotherRobotIsRefusedAndItsAskHowToo() throws Exception {
        RosAgArch arch = start("guarded", "+hello[source(S)] <- +heard(S).");
        assertEquals(0, fromOtherRobot("carol", "guarded", "tellHow", PLAN, ""));
        assertEquals(0, fromOtherRobot("carol", "guarded", "untellHow", "trick", ""));
        assertEquals(0, fromOtherRobot("carol", "guarded", "askHow", "\"+hello\"", ""));
        assertEquals(1, fromOtherRobot("carol", "guarded", "tell", "hello", ""));
        await("the tell that is allowed", () -> believes(arch, "heard(carol)"));
        assertFalse(hasPlanFor(arch, "trick"));
        assertNoAnswer();
    }

    /** Only receipts were queued for robot2 (three refusals and one delivery), no answer. */
    private void assertNoAnswer() {
        for (Outbound o; (o = bridge.outbox().poll()) != null;)
            assertEquals("rason_receipt", ((Outbound.AgentMessage) o).performative(), "nothing answered the askHow");
    }

    @Test
    void aRobotTheAgentTrustsMayTellItPlans() throws Exception {
        bridge.fleet().trust().setParameterRule("open", TrustPolicy.Group.TELL_HOW, TrustPolicy.Rule.parse("carol"));
        RosAgArch arch = start("open", "");
        assertEquals(0, fromOtherRobot("mallory", "open", "tellHow", PLAN, ""));
        assertEquals(1, fromOtherRobot("carol", "open", "tellHow", PLAN, ""));
        await("carol's plan", () -> hasPlanFor(arch, "trick"));
        assertEquals(1, fromOtherRobot("carol", "open", "achieve", "trick", ""));
        await("the plan runs", () -> believes(arch, "tricked"));
    }

    @Test
    void theAnswerToTheAgentsOwnAskHowGetsInFromTheAskedRobotOnly() throws Exception {
        RosAgArch arch = start("curious", "!learn. +!learn <- .send(carol, askHow, \"+!trick\").");
        Outbound.AgentMessage ask = agents.next(Outbound.AgentMessage.class);
        assertEquals("askHow", ask.performative());
        assertEquals("carol", ask.receiver());
        assertEquals(0, fromOtherRobot("mallory", "curious", "tellHow", "[" + PLAN + "]", ask.msgId()),
                "mallory did not get the question");
        assertEquals(0, fromOtherRobot("carol", "curious", "tellHow", "[" + PLAN + "]", "mid_never_sent"));
        assertEquals(1, fromOtherRobot("carol", "curious", "tellHow", "[" + PLAN + "]", ask.msgId()));
        await("the answer's plan", () -> hasPlanFor(arch, "trick"));
        assertEquals(0, fromOtherRobot("carol", "curious", "tellHow", "[" + PLAN + "]", ask.msgId()),
                "a question is answered once");
    }
}
