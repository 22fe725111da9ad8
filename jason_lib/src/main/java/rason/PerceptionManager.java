package rason;

import java.util.Collection;
import java.util.List;

import jason.asSyntax.Literal;

/**
 * How an agent turns the perception messages it hears into the percepts Jason
 * sees. One instance per agent; called from ROS threads (update, expire) and
 * the agent's thread (perceive, current), so implementations are thread-safe.
 */
public interface PerceptionManager {

    /**
     * A source published its current perceptions (already parsed, read-only).
     *
     * @return true if what the agent perceives changed
     */
    boolean update(String source, List<Literal> literals, long nowNanos);

    /**
     * Forgets sources not heard from for more than ttlNanos (0 or less: never).
     *
     * @return true if what the agent perceives changed
     */
    boolean expire(long nowNanos, long ttlNanos);

    /** The full percept list if it changed since the last call, else null (Jason then skips belief update). */
    Collection<Literal> perceive();

    /** The full current percept list, changed or not. */
    Collection<Literal> current();
}
