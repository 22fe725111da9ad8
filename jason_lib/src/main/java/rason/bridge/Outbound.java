package rason.bridge;

/**
 * What the agents hand to the rospy node: queued on the agent's thread by
 * {@link Outbox#offer}, published by a thread of the node.
 */
public sealed interface Outbound permits Outbound.Action, Outbound.Cancel, Outbound.AgentMessage, Outbound.Stop,
        Outbound.Announce {

    /** A rason_msgs/Action for jason/action. */
    record Action(String agent, int actionId, String action, String[] parameters) implements Outbound {
    }

    /** A cancel for action actionId of agent (rason_msgs/Action CANCEL on jason/action, after the action). */
    record Cancel(String agent, int actionId, String reason) implements Outbound {
    }

    /** A rason_msgs/AgentMessage for another process (receiverMas empty: every other process). */
    record AgentMessage(String receiverMas, String sender, String receiver, String performative, String content,
            String msgId, String inReplyTo) implements Outbound {
    }

    /** An agent ran .stopMAS: the node shuts down and exits with this status. */
    record Stop(int exitValue) implements Outbound {
    }

    /** Our agents (.create_agent, .kill_agent) or their directory registrations changed: announce now, not at the next period. */
    record Announce() implements Outbound {
    }
}
