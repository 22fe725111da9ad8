package rason.messaging;

import jason.asSemantics.Message;

/**
 * The receipt a process sends back for an agent message that named one of its agents:
 * an agent message of the fleet (signed, sequenced and deduplicated like any other)
 * from that agent to the sender, in reply to the message's id, saying whether the agent
 * has it in its mailbox or its trust policy refused it. It never reaches Jason.
 */
public final class Receipts {

    static final String PERFORMATIVE = "rason_receipt";
    private static final String DELIVERED = "delivered";
    private static final String REFUSED = "refused";

    private Receipts() {
    }

    static boolean isReceipt(WireMessage m) {
        return PERFORMATIVE.equals(m.performative());
    }

    /** Whether the sender waits for a receipt: a message to one agent that is not a receipt or a synchronous ask. */
    public static boolean wanted(WireMessage m) {
        return !m.receiver().isEmpty() && !isReceipt(m) && !m.msgId().isEmpty()
                && !m.msgId().startsWith(Message.msgIdSyncAskPrefix);
    }

    /** The receipt of m from receiver, an agent of process ourMas. */
    public static WireMessage of(WireMessage m, String receiver, String ourMas, boolean refused) {
        return new WireMessage(ourMas, receiver, m.senderMas(), m.sender(), PERFORMATIVE, refused ? REFUSED : DELIVERED,
                "", m.msgId());
    }

    static boolean refused(WireMessage receipt) {
        return REFUSED.equals(receipt.content());
    }
}
