package rason.mind;

import java.util.List;

/**
 * What one agent believes, wants and does, as a reasoning cycle left it: the
 * content of {@code rason_msgs/AgentMind}. Immutable, so the agent's thread can
 * hand it to the node's publishing thread.
 *
 * @param cycle reasoning cycles the agent has run
 * @param stampNanos ROS time the snapshot was taken
 * @param beliefs beliefs in Jason syntax, annotations included (rules apart)
 * @param rules the rules of its belief base ({@code head :- body})
 * @param goals the achievement goals its intentions pursue, each as {@code !goal}
 * @param omitted items left out of the lists to keep the snapshot bounded
 */
public record AgentMind(String name, long cycle, long stampNanos, List<String> beliefs, List<String> rules,
        List<String> goals,
        List<IntentionView> intentions, List<ActionView> actions, List<String> events, List<String> messages,
        int omitted) {

    /**
     * One intention: its id, Jason's state of it ({@code running}, {@code waiting} for an
     * action, ask or {@code .wait}, {@code suspended}) and its stack, innermost plan first,
     * each as {@code label: trigger <- next step}.
     */
    public record IntentionView(int id, String state, List<String> plans) {
    }

    /** An action sent to the robot and not answered yet, since ROS time startedNanos. */
    public record ActionView(int id, String action, long startedNanos, boolean held) {
    }

    /** Whether the two differ in anything but the cycle count and the time they were taken. */
    public boolean sameStateAs(AgentMind other) {
        return other != null && name.equals(other.name) && beliefs.equals(other.beliefs)
                && rules.equals(other.rules) && goals.equals(other.goals)
                && intentions.equals(other.intentions) && actions.equals(other.actions) && events.equals(other.events)
                && messages.equals(other.messages) && omitted == other.omitted;
    }
}
