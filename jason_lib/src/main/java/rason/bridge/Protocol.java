package rason.bridge;

/**
 * The words of the agents ↔ robot protocol, as rason_msgs/Event.msg defines
 * them (a unit test checks both agree).
 */
public final class Protocol {

    private Protocol() {
    }

    /** Event type of a decomposer's answer: parameters are [result, action_id]. */
    public static final String ACTION_FEEDBACK = "action_feedback";
    /** The result that resumes the intention; anything else is a failure reason. */
    public static final String OK = "OK";
    /** No feedback within the action timeout. */
    public static final String TIMEOUT = "timeout";
    /** Nobody subscribes to jason/action. */
    public static final String NO_DECOMPOSER = "no_decomposer";
    /** The node is stopping. */
    public static final String SHUTDOWN = "shutdown";
    /** The bridge could not hand the action or message on. */
    public static final String BRIDGE_ERROR = "bridge_error";
}
