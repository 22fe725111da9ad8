package rason.perception;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.function.BiConsumer;

import jason.asSyntax.Literal;

import rason.core.InputLimits;

/**
 * The perception sources the bridge remembers: at most {@link InputLimits#maxSources()}
 * at once, each with the literals of its last message by their text, so that a literal
 * a synthesizer repeats from one message to the next is not parsed again (a
 * synthesizer publishes its whole current list every time). A source is forgotten,
 * with its literals, when a message of it has no literal left or when it has not been
 * heard for the perception TTL; a message from a new source while the table is full is
 * refused, so a flood of distinct source names cannot grow any per-source table
 * (here, in the perception managers) without bound. Thread-safe; parsing happens
 * outside the lock.
 */
public final class PerceptionSources {

    private static final class Source {
        long heardNanos;
        Map<String, Literal> lastByText;

        Source(long heardNanos, Map<String, Literal> lastByText) {
            this.heardNanos = heardNanos;
            this.lastByText = lastByText;
        }
    }

    private final Map<String, Source> sources = new HashMap<>();

    /**
     * Parses the texts of one message of source within limits. A text its previous
     * message also had gives that message's literal again; the others are parsed.
     *
     * @param refused told (text, why) of each text that is not a perception
     * @return the literals, in the message's order; null if source is new, the message
     *         is not empty and the table already holds limits.maxSources() sources
     *         (nothing changes then)
     */
    public List<Literal> parse(String source, String[] texts, long nowNanos, InputLimits limits,
            BiConsumer<String, String> refused) {
        Map<String, Literal> previous;
        synchronized (this) {
            Source s = sources.get(source);
            if (s == null && texts.length > 0 && sources.size() >= limits.maxSources())
                return null;
            previous = s == null ? Map.of() : s.lastByText;
        }
        List<Literal> literals = new ArrayList<>(texts.length);
        Map<String, Literal> byText = new HashMap<>();
        for (String text : texts) {
            Literal l = text == null ? null : previous.get(text);
            if (l == null) {
                try {
                    l = Perceptions.parse(text, limits);
                } catch (IllegalArgumentException e) {
                    refused.accept(text, e.getMessage());
                    continue;
                }
            }
            literals.add(l);
            byText.put(text, l);
        }
        synchronized (this) {
            if (literals.isEmpty())
                sources.remove(source); // the managers clear it too
            else if (sources.containsKey(source) || sources.size() < limits.maxSources())
                sources.put(source, new Source(nowNanos, byText));
        }
        return literals;
    }

    /** Forgets the sources not heard for more than ttlNanos (0 or less: none). */
    public synchronized void expire(long nowNanos, long ttlNanos) {
        if (ttlNanos > 0)
            sources.values().removeIf(s -> nowNanos - s.heardNanos > ttlNanos);
    }

    /** Forgets every source. */
    public synchronized void clear() {
        sources.clear();
    }

    /** How many sources are remembered. */
    public synchronized int size() {
        return sources.size();
    }

    /** Whether source is remembered. */
    public synchronized boolean remembers(String source) {
        return sources.containsKey(source);
    }
}
