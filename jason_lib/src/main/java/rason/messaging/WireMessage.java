package rason.messaging;

/**
 * A rason_msgs/AgentMessage as it crosses between processes, without its
 * authentication fields (those are {@link FleetAuth.Signed}). Null fields read as "".
 */
public record WireMessage(String senderMas, String sender, String receiverMas, String receiver, String performative,
        String content, String msgId, String inReplyTo) {

    public WireMessage {
        senderMas = orEmpty(senderMas);
        sender = orEmpty(sender);
        receiverMas = orEmpty(receiverMas);
        receiver = orEmpty(receiver);
        performative = orEmpty(performative);
        content = orEmpty(content);
        msgId = orEmpty(msgId);
        inReplyTo = orEmpty(inReplyTo);
    }

    private static String orEmpty(String s) {
        return s == null ? "" : s;
    }
}
