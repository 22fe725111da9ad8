package rason.perception;

import java.util.ArrayList;
import java.util.Collection;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import jason.asSyntax.Literal;

/**
 * The unfiltered mode of thesis Table 5.1: every message's literals are added,
 * whatever their source, and nothing is replaced. A literal leaves only when it
 * has not been heard again within the perception TTL, or when more than
 * {@link #DEFAULT_MAX_LITERALS} distinct literals are held (then the least recently
 * heard leave first, so a flood of new literals cannot grow the agent's beliefs
 * without bound, TTL or not). Every non-empty message counts as a change, so Jason
 * runs its belief update once per message; this is the baseline the other
 * strategies are measured against.
 */
public class AccumulatePerception implements PerceptionManager {

    /** Distinct literals held at most. */
    public static final int DEFAULT_MAX_LITERALS = 10_000;

    // in the order they were last heard: the least recently heard first
    private final LinkedHashMap<Literal, Long> heard = new LinkedHashMap<>();
    private final int maxLiterals;
    private boolean changed = false;

    public AccumulatePerception() {
        this(DEFAULT_MAX_LITERALS);
    }

    /** @param maxLiterals distinct literals held at most (1 or more) */
    public AccumulatePerception(int maxLiterals) {
        if (maxLiterals < 1)
            throw new IllegalArgumentException("an accumulating manager must hold at least one literal");
        this.maxLiterals = maxLiterals;
    }

    @Override
    public synchronized boolean update(String source, List<Literal> literals, long nowNanos) {
        if (literals.isEmpty())
            return false; // nothing to add; an empty list clears nothing here
        for (Literal l : literals) {
            heard.remove(l); // heard again: to the end of the order
            heard.put(l, nowNanos);
        }
        for (Iterator<Literal> oldest = heard.keySet().iterator(); heard.size() > maxLiterals;) {
            oldest.next();
            oldest.remove();
        }
        changed = true;
        return true;
    }

    @Override
    public synchronized boolean expire(long nowNanos, long ttlNanos) {
        if (ttlNanos <= 0)
            return false;
        boolean removed = false;
        // the least recently heard first: stop at the first one still alive
        for (Iterator<Map.Entry<Literal, Long>> it = heard.entrySet().iterator(); it.hasNext();) {
            if (nowNanos - it.next().getValue() <= ttlNanos)
                break;
            it.remove();
            removed = true;
        }
        changed |= removed;
        return removed;
    }

    @Override
    public synchronized Collection<Literal> perceive() {
        if (!changed)
            return null;
        changed = false;
        return current();
    }

    @Override
    public synchronized Collection<Literal> current() {
        return new ArrayList<>(heard.keySet());
    }

    @Override
    public String toString() {
        return "accumulate";
    }
}
