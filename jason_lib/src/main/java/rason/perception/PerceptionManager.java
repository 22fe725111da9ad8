package rason.perception;

import java.util.Collection;
import java.util.List;

import jason.asSyntax.Literal;

/**
 * How an agent turns the perception messages it hears into the percepts Jason
 * sees (thesis §8.1: perception managers as plug-ins). One instance per agent;
 * called from ROS threads (update, expire) and the agent's thread (perceive,
 * current), so implementations are thread-safe.
 * <p>
 * Chosen per agent with the {@code perception_manager} option of the .mas2j
 * (see {@link PerceptionManagers}); a class implementing this interface with a
 * public no-argument constructor can be named there without changing Rason.
 */
public interface PerceptionManager {

    /**
     * A source published its current perceptions (already parsed, read-only).
     *
     * @return true if what the agent perceives changed
     */
    boolean update(String source, List<Literal> literals, long nowNanos);

    /**
     * Called every few tens of milliseconds (ROS time): forgets sources not heard
     * from for more than ttlNanos (0 or less: never), and applies anything held back.
     *
     * @return true if what the agent perceives changed
     */
    boolean expire(long nowNanos, long ttlNanos);

    /** The full percept list if it changed since the last call, else null (Jason then skips belief update). */
    Collection<Literal> perceive();

    /** The full current percept list, changed or not. */
    Collection<Literal> current();

    /** Whether the agent wants this kind of literal at all (selective perception); also applied to the bridge's own percepts. */
    default boolean wants(Literal literal) {
        return true;
    }
}
