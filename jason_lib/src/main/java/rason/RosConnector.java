package rason;

/**
 * What the rospy process does on behalf of the agents. Implemented in Python
 * (JPype {@code @JImplements}); every method is called on an agent's thread, so
 * implementations must return quickly and never block.
 */
public interface RosConnector {

    /** Returned by {@link #publishAction} when no node subscribes to jason/action. */
    long NO_DECOMPOSER = -1L;

    /**
     * Publishes a rason_msgs/Action on jason/action.
     *
     * @return the ROS time of publication in nanoseconds, or {@link #NO_DECOMPOSER}
     */
    long publishAction(String agent, int actionId, String action, String[] parameters);

    /** An agent ran .stopMAS: the node should shut down and exit with exitValue. */
    void stopRequested(int exitValue);

    /**
     * Publishes a rason_msgs/AgentMessage on the shared messages topic, at once
     * or, if the receiving process is not connected yet, as soon as it is.
     *
     * @param receiverMas the receiving process; empty for a broadcast (receiver empty too)
     * @return false if it cannot be sent (the node is stopping)
     */
    boolean publishMessage(String receiverMas, String sender, String receiver, String performative,
            String content, String msgId, String inReplyTo);
}
