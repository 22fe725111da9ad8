package rason.perception;

import java.util.ArrayList;
import java.util.Collection;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

import jason.asSyntax.Literal;

/**
 * Thesis §5.2 strategy: each source's latest list replaces its previous one, so
 * a fast synthesizer cannot flood the agent; an empty list clears the source.
 */
public class PerSourcePerception implements PerceptionManager {

    private static final class Source {
        final List<Literal> literals;
        long heardNanos;

        Source(List<Literal> literals, long heardNanos) {
            this.literals = literals;
            this.heardNanos = heardNanos;
        }
    }

    private final Map<String, Source> sources = new HashMap<>();
    private boolean changed = false;

    @Override
    public synchronized boolean update(String source, List<Literal> literals, long nowNanos) {
        Source old = sources.get(source);
        if (literals.isEmpty()) {
            if (old == null)
                return false;
            sources.remove(source);
            changed = true;
            return true;
        }
        if (old != null && old.literals.equals(literals)) {
            old.heardNanos = nowNanos; // same content: only keeps the source alive
            return false;
        }
        sources.put(source, new Source(literals, nowNanos));
        changed = true;
        return true;
    }

    @Override
    public synchronized boolean expire(long nowNanos, long ttlNanos) {
        if (ttlNanos <= 0)
            return false;
        boolean removed = sources.values().removeIf(s -> nowNanos - s.heardNanos > ttlNanos);
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
        List<Literal> all = new ArrayList<>();
        for (Source s : sources.values())
            all.addAll(s.literals);
        return all;
    }

    @Override
    public String toString() {
        return PerceptionManagers.PER_SOURCE;
    }

    /** Names of the sources currently held (for tests and introspection). */
    public synchronized List<String> sourceNames() {
        return new ArrayList<>(sources.keySet());
    }
}
