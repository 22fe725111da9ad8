package rason.perception;

import java.util.ArrayList;
import java.util.List;

import jason.asSyntax.Literal;

/**
 * A test's perception for one hosted agent only. In a fleet each robot's rason_mas perceives
 * its own robot (its camera, its odometry); a test that runs several robots' agents in one MAS
 * gives each agent its own, where the bridge would give every hosted agent the same.
 */
public final class OneAgentPerception {

    private OneAgentPerception() {
    }

    /** The source's current literals for this agent only, heard at nowNanos (ROS time). */
    public static void perceive(AgentPerception agent, String source, long nowNanos, String... texts) {
        List<Literal> literals = new ArrayList<>(texts.length);
        for (String t : texts)
            literals.add(Perceptions.parse(t));
        agent.update(source, literals, nowNanos);
    }
}
