package rason.perception;

import java.util.ArrayList;
import java.util.Collection;
import java.util.Collections;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;

import jason.asSyntax.Literal;

/**
 * Selective perception (thesis §5.5, §8.1): only literals whose functor/arity
 * the agent declared reach the wrapped manager, so the rest never becomes a
 * belief nor costs a belief update. Without a selection everything passes.
 * <p>
 * The selection can change while the agent runs ({@code rason.perceive_only},
 * {@code rason.perceive_all}): the last list of each source is kept unfiltered
 * so a newly wanted literal appears at once, and the output is filtered too so
 * a no longer wanted one disappears at once.
 */
public class SelectivePerception implements PerceptionManager {

    private static final class Raw {
        final List<Literal> literals;
        final long heardNanos;

        Raw(List<Literal> literals, long heardNanos) {
            this.literals = literals;
            this.heardNanos = heardNanos;
        }
    }

    private final PerceptionManager inner;
    private volatile Set<String> wanted; // "functor/arity"; null = everything
    private final Map<String, Raw> raw = new HashMap<>();
    private boolean selectionChanged = false;

    public SelectivePerception(PerceptionManager inner, Set<String> wanted) {
        this.inner = inner;
        this.wanted = wanted == null ? null : Set.copyOf(wanted);
    }

    /**
     * Parses a selection such as {@code "robot/4, battery/1"}.
     *
     * @throws IllegalArgumentException naming the entry that is not functor/arity
     */
    public static Set<String> parseSelection(Collection<String> entries) {
        Set<String> out = new TreeSet<>();
        for (String entry : entries) {
            for (String part : entry.split(",")) {
                String s = part.replaceAll("[\\s()\"]", "");
                if (s.isEmpty())
                    continue;
                int slash = s.lastIndexOf('/');
                if (slash <= 0 || slash == s.length() - 1)
                    throw new IllegalArgumentException("'" + part.strip() + "' is not functor/arity (e.g. robot/4)");
                String functor = s.substring(0, slash);
                String arity = s.substring(slash + 1);
                if (!functor.matches("~?[a-z][A-Za-z0-9_]*") || !arity.matches("[0-9]+"))
                    throw new IllegalArgumentException("'" + part.strip() + "' is not functor/arity (e.g. robot/4)");
                out.add(functor.replace("~", "") + "/" + Integer.parseInt(arity));
            }
        }
        return out;
    }

    public static Set<String> parseSelection(String spec) {
        return parseSelection(List.of(spec));
    }

    /** The current selection, null for everything. */
    public Set<String> selection() {
        return wanted;
    }

    /** Changes the selection (null: everything) and re-filters what the sources last sent. */
    public synchronized void select(Set<String> selection) {
        wanted = selection == null ? null : Set.copyOf(selection);
        selectionChanged = true;
        for (Map.Entry<String, Raw> e : raw.entrySet())
            inner.update(e.getKey(), filter(e.getValue().literals), e.getValue().heardNanos);
    }

    @Override
    public boolean wants(Literal l) {
        Set<String> w = wanted;
        return w == null || w.contains(l.getFunctor() + "/" + l.getArity());
    }

    private List<Literal> filter(Collection<Literal> literals) {
        if (wanted == null)
            return literals instanceof List<Literal> list ? list : new ArrayList<>(literals);
        List<Literal> out = new ArrayList<>(literals.size());
        for (Literal l : literals)
            if (wants(l))
                out.add(l);
        return out;
    }

    // Holds this lock while passing on, so a selection change and an update
    // of the same source cannot overtake each other (the wrapped manager never calls back).
    @Override
    public synchronized boolean update(String source, List<Literal> literals, long nowNanos) {
        if (literals.isEmpty())
            raw.remove(source);
        else
            raw.put(source, new Raw(literals, nowNanos));
        return inner.update(source, filter(literals), nowNanos);
    }

    @Override
    public boolean expire(long nowNanos, long ttlNanos) {
        if (ttlNanos > 0)
            synchronized (this) {
                raw.values().removeIf(r -> nowNanos - r.heardNanos > ttlNanos);
            }
        return inner.expire(nowNanos, ttlNanos);
    }

    @Override
    public Collection<Literal> perceive() {
        Collection<Literal> c = inner.perceive();
        boolean forced;
        synchronized (this) {
            forced = selectionChanged;
            selectionChanged = false;
        }
        if (c == null && !forced)
            return null;
        return filter(c != null ? c : inner.current());
    }

    @Override
    public Collection<Literal> current() {
        return filter(inner.current());
    }

    @Override
    public String toString() {
        Set<String> w = wanted;
        return w == null ? inner.toString() : "selective" + Collections.unmodifiableSet(w) + " over " + inner;
    }
}
