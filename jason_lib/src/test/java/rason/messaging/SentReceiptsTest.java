package rason.messaging;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;

class SentReceiptsTest {

    private static final long SECOND = 1_000_000_000L;
    private static final long TTL = 60 * SECOND;
    private final SentReceipts receipts = new SentReceipts();

    private List<SentReceipts.Outcome> settle(long now) {
        return receipts.settle(id -> true, now, TTL, null);
    }

    @Test
    void aSendEndsWhenEveryRemoteReceiverConfirmed() {
        receipts.expect("mid1", "bob", "/r2/rason_mas", SECOND);
        receipts.expect("mid1", "carol", "/r3/rason_mas", SECOND);
        assertTrue(receipts.arrived("mid1", "bob", "/r2/rason_mas", false));
        assertTrue(receipts.hasNews());
        assertTrue(settle(2 * SECOND).isEmpty(), "carol has not confirmed");
        assertFalse(receipts.hasNews());
        assertTrue(receipts.arrived("mid1", "carol", "/r3/rason_mas", false));
        List<SentReceipts.Outcome> ended = settle(3 * SECOND);
        assertEquals(1, ended.size());
        assertTrue(ended.get(0).delivered());
        assertTrue(receipts.isEmpty());
    }

    @Test
    void aReceiptOfAnotherProcessOrAgentOrMessageCountsForNothing() {
        receipts.expect("mid1", "bob", "/r2/rason_mas", SECOND);
        assertFalse(receipts.arrived("mid1", "bob", "/r3/rason_mas", false), "bob is on r2");
        assertFalse(receipts.arrived("mid1", "carol", "/r2/rason_mas", false), "carol was not sent mid1");
        assertFalse(receipts.arrived("mid2", "bob", "/r2/rason_mas", false), "mid2 was never sent");
        assertTrue(settle(2 * SECOND).isEmpty());
        assertTrue(receipts.arrived("mid1", "bob", "/r2/rason_mas", false));
        assertFalse(receipts.arrived("mid1", "bob", "/r2/rason_mas", false), "a second copy");
    }

    @Test
    void withoutAReceiptWithinTheTtlTheSendFailsUndelivered() {
        receipts.expect("mid1", "bob", "/r2/rason_mas", SECOND);
        assertFalse(receipts.due(SECOND + TTL, TTL));
        assertTrue(settle(SECOND + TTL).isEmpty());
        assertTrue(receipts.due(SECOND + TTL + 1, TTL));
        SentReceipts.Outcome o = settle(SECOND + TTL + 1).get(0);
        assertEquals(SentReceipts.UNDELIVERED, o.error());
        assertTrue(o.text().contains("bob"), o.text());
        assertTrue(o.text().contains("60 s"), o.text());
        assertNull(o.departed());
    }

    @Test
    void aReceiverThatLeavesFailsTheSendNamingIt() {
        receipts.expect("mid1", "bob", "/r2/rason_mas", SECOND);
        receipts.expect("mid2", "carol", "/r3/rason_mas", SECOND);
        assertTrue(receipts.receiversLost(List.of("bob")));
        List<SentReceipts.Outcome> ended = settle(2 * SECOND);
        assertEquals(List.of(new SentReceipts.Outcome("mid1", RemoteAsks.RECEIVER_DEPARTED,
                "bob left before confirming it", "bob")), ended);
        assertFalse(receipts.isEmpty(), "the send to carol still waits");
    }

    @Test
    void aRefusalFailsTheSendEvenIfOthersConfirmed() {
        receipts.expect("mid1", "bob", "/r2/rason_mas", SECOND);
        receipts.expect("mid1", "carol", "/r3/rason_mas", SECOND);
        receipts.arrived("mid1", "bob", "/r2/rason_mas", true);
        assertEquals(SentReceipts.REFUSED, settle(2 * SECOND).get(0).error());
    }

    @Test
    void aStoppingNodeFailsEveryWaitingSend() {
        receipts.expect("mid1", "bob", "/r2/rason_mas", SECOND);
        receipts.expect("mid2", "bob", "/r2/rason_mas", SECOND);
        List<SentReceipts.Outcome> ended = receipts.settle(id -> true, 2 * SECOND, TTL, "shutdown");
        assertEquals(List.of("mid1", "mid2"), ended.stream().map(SentReceipts.Outcome::msgId).toList());
        assertTrue(ended.stream().allMatch(o -> "shutdown".equals(o.error())));
    }

    @Test
    void aSendWhoseIntentionWasDroppedIsForgottenSilently() {
        receipts.expect("mid1", "bob", "/r2/rason_mas", SECOND);
        receipts.arrived("mid1", "bob", "/r2/rason_mas", false);
        assertTrue(receipts.settle(id -> false, 2 * SECOND, TTL, null).isEmpty());
        assertTrue(receipts.isEmpty());
        receipts.expect("mid2", "bob", "/r2/rason_mas", SECOND);
        assertTrue(receipts.settle(id -> false, 2 * SECOND, TTL, null).isEmpty());
        assertFalse(receipts.isEmpty(), "kept until its receipt comes or its TTL passes");
        assertTrue(receipts.settle(id -> false, SECOND + TTL + 1, TTL, null).isEmpty(), "its TTL ends it silently");
        assertTrue(receipts.isEmpty());
    }

    @Test
    void theOldestSendDecidesWhetherOneIsDue() {
        receipts.expect("mid1", "bob", "/r2/rason_mas", SECOND);
        receipts.expect("mid2", "bob", "/r2/rason_mas", 2 * SECOND);
        assertFalse(receipts.due(SECOND + TTL, TTL));
        assertTrue(receipts.due(SECOND + TTL + 1, TTL));
        receipts.arrived("mid1", "bob", "/r2/rason_mas", false);
        assertEquals(1, settle(SECOND + TTL + 1).size(), "mid1 delivered");
        assertFalse(receipts.due(SECOND + TTL + 1, TTL), "mid2 is not due yet");
        assertTrue(receipts.due(2 * SECOND + TTL + 1, TTL));
    }

    @Test
    void lossesMatterOnlyWhenSomethingWaits() {
        assertFalse(receipts.receiversLost(List.of("bob")));
        assertFalse(receipts.hasNews());
    }
}
