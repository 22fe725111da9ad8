package rason.core;

/**
 * The words of the agents ↔ robot protocol, as rason_msgs/Event.msg defines
 * them (a unit test checks both agree).
 */
public final class Protocol {

    private Protocol() {
    }

    /** Event type of a decomposer's answer: parameters are [result, action_id]. */
    public static final String ACTION_FEEDBACK = "action_feedback";
    /** Event type of a decomposer saying it took an action: parameters are [action_id]. */
    public static final String ACTION_STARTED = "action_started";
    /** The action name of a cancel on jason/action (rason_msgs/Action CANCEL). */
    public static final String CANCEL = ".cancel";
    /** A decomposer's answer to a cancel. */
    public static final String CANCELLED = "cancelled";
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
    /** The decomposer that took the action went away. */
    public static final String DECOMPOSER_LOST = "decomposer_lost";
    /** The action's intention was suspended while it ran: the robot stopped it; .resume sees this failure. */
    public static final String SUSPENDED = "suspended";
    /** Cancel reason: the agent stopped waiting for the action (drop, succeed/fail goal). */
    public static final String DROPPED = "dropped";
    /** Cancel reason: a restarted bridge takes back what an earlier run of it left. */
    public static final String RESTART = "restart";
}
