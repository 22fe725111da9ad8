package rason.perception;

import java.util.ArrayList;
import java.util.Collection;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import jason.asSyntax.Literal;

/**
 * The unfiltered mode of thesis Table 5.1: every message's literals are added,
 * whatever their source, and nothing is replaced. A literal leaves only when it
 * has not been heard again within the perception TTL. Every non-empty message
 * counts as a change, so Jason runs its belief update once per message; this
 * is the baseline the other strategies are measured against.
 */
public class AccumulatePerception implements PerceptionManager {

    private final Map<Literal, Long> heard = new LinkedHashMap<>();
    private boolean changed = false;

    @Override
    public synchronized boolean update(String source, List<Literal> literals, long nowNanos) {
        if (literals.isEmpty())
            return false; // nothing to add; an empty list clears nothing here
        for (Literal l : literals)
            heard.put(l, nowNanos);
        changed = true;
        return true;
    }

    @Override
    public synchronized boolean expire(long nowNanos, long ttlNanos) {
        if (ttlNanos <= 0)
            return false;
        boolean removed = heard.values().removeIf(t -> nowNanos - t > ttlNanos);
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
