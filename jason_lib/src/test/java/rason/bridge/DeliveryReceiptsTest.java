package rason.bridge;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static rason.bridge.RunningAgents.SECOND;
import static rason.bridge.RunningAgents.await;
import static rason.bridge.RunningAgents.believes;

import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;

import rason.RosAgArch;
import rason.core.ManualClock;
import rason.messaging.TrustPolicy;

/**
 * A .send to an agent of another process holds the sending intention until that
 * process's receipt says the message is in the receiver's mailbox; without a receipt
 * within the message TTL, when the receiver leaves, or when its trust policy refuses
 * the message, the send fails with a reason: a message is delivered or its send fails.
 */
class DeliveryReceiptsTest {

    private static final String OTHER_MAS = "/robot2/rason_mas";
    private static final String KEY = "test-receipt-key-0123456789abcdef0123456789abcdef";
    private static final String SENDER = "!go. +!go <- .send(bob, tell, hello); +sent. "
            + "-!go[error(E), error_msg(M)] <- +failed(E).";

    private final ManualClock wall = new ManualClock(System.currentTimeMillis() * 1_000_000L);
    private final Bridge bridge = new Bridge(wall);
    @RegisterExtension
    final RunningAgents agents = new RunningAgents(bridge);

    @TempDir
    Path dir;

    private OtherRobot robot2;

    private RosAgArch start(String agent, String program) throws Exception {
        bridge.fleet().setMasId("/robot1/rason_mas");
        robot2 = new OtherRobot(bridge, OTHER_MAS, KEY);
        robot2.announce(new String[] { "bob", "carol" }, false);
        return agents.start(dir, agent, program);
    }

    /** The tell alice sent to bob, once her intention waits for its receipt. */
    private Outbound.AgentMessage sentAndWaiting(RosAgArch alice) throws InterruptedException {
        Outbound.AgentMessage tell = agents.next(Outbound.AgentMessage.class);
        assertEquals("bob", tell.receiver());
        assertEquals(OTHER_MAS, tell.receiverMas());
        await("the intention waits for the receipt",
                () -> alice.getTS().getC().getPendingIntentions().containsKey("rason_receipt_" + tell.msgId()));
        assertFalse(believes(alice, "sent"), "the plan went on before the receipt");
        return tell;
    }

    @Test
    void theSendingIntentionGoesOnWhenTheReceiptComes() throws Exception {
        RosAgArch alice = start("alice", SENDER);
        Outbound.AgentMessage tell = sentAndWaiting(alice);
        robot2.send("carol", "alice", "rason_receipt", "delivered", tell.msgId());
        assertFalse(believes(alice, "sent"), "a receipt from another agent than the receiver counts for nothing");
        robot2.send("bob", "alice", "rason_receipt", "delivered", "mid_never_sent");
        robot2.send("bob", "alice", "rason_receipt", "delivered", tell.msgId());
        await("the plan goes on", () -> believes(alice, "sent"));
        assertFalse(believes(alice, "failed(_)"));
    }

    @Test
    void aSendInsideAnIfWaitsToo() throws Exception {
        RosAgArch alice = start("alice", "!go. +!go <- .list_rules; if (true) { .send(bob, tell, hello) }; +sent.");
        Outbound.AgentMessage tell = sentAndWaiting(alice);
        robot2.send("bob", "alice", "rason_receipt", "delivered", tell.msgId());
        await("the plan goes on", () -> believes(alice, "sent"));
    }

    @Test
    void withoutAReceiptWithinTheMessageTtlTheSendFails() throws Exception {
        bridge.fleet().setMessageTtlNanos(5 * SECOND);
        RosAgArch alice = start("alice", SENDER);
        sentAndWaiting(alice);
        wall.advance(4 * SECOND);
        bridge.tick(104 * SECOND);
        assertFalse(believes(alice, "failed(_)"), "failed before its TTL");
        wall.advance(2 * SECOND);
        bridge.tick(106 * SECOND);
        await("the send fails", () -> believes(alice, "failed(undelivered)"));
        assertFalse(believes(alice, "sent"));
    }

    @Test
    void whenTheReceiverLeavesBeforeItsReceiptTheSendFails() throws Exception {
        RosAgArch alice = start("alice", SENDER);
        sentAndWaiting(alice);
        robot2.announce(new String[] { "bob", "carol" }, true);
        await("the send fails", () -> believes(alice, "failed(receiver_departed)"));
    }

    @Test
    void aMessageTheReceiversTrustPolicyRefusesFailsItsSend() throws Exception {
        RosAgArch alice = start("alice", SENDER);
        Outbound.AgentMessage tell = sentAndWaiting(alice);
        robot2.send("bob", "alice", "rason_receipt", "refused", tell.msgId());
        await("the send fails", () -> believes(alice, "failed(refused)"));
    }

    @Test
    void theReceivingSideSendsAReceiptForWhatReachedTheMailboxAndForWhatItRefused() throws Exception {
        bridge.fleet().trust().setParameterRule("dave", TrustPolicy.Group.ACHIEVE, TrustPolicy.Rule.parse("none"));
        RosAgArch dave = start("dave", "+hello[source(S)] <- +heard(S).");
        assertEquals(1, robot2.send("carol", "dave", "tell", "hello", ""));
        Outbound.AgentMessage receipt = agents.next(Outbound.AgentMessage.class);
        assertEquals("rason_receipt", receipt.performative());
        assertEquals("carol", receipt.receiver());
        assertEquals(OTHER_MAS, receipt.receiverMas());
        assertEquals("delivered", receipt.content());
        await("the tell", () -> believes(dave, "heard(carol)"));
        assertEquals(0, robot2.send("carol", "dave", "achieve", "hello", ""));
        assertEquals("refused", agents.next(Outbound.AgentMessage.class).content());
    }
}
