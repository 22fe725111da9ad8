package rason.perception;

import java.util.Collection;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

import jason.asSyntax.Literal;

/**
 * At most a given number of updates per second per source reach the wrapped
 * manager. An update inside a source's window is held back, a newer one
 * replaces it, and the newest is applied as soon as the window allows, so a
 * burst ends with the source's latest list and nothing stale sticks.
 */
public class RateLimitedPerception implements PerceptionManager {

    private static final class Window {
        long appliedNanos;
        List<Literal> held; // newest update waiting for the window, or null
        long heldNanos;

        Window(long appliedNanos) {
            this.appliedNanos = appliedNanos;
        }
    }

    private final PerceptionManager inner;
    private final long gapNanos;
    private final double perSecond;
    private final Map<String, Window> windows = new HashMap<>();

    /**
     * @param perSecond updates per second and source, more than 0
     */
    public RateLimitedPerception(PerceptionManager inner, double perSecond) {
        if (!(perSecond > 0) || Double.isInfinite(perSecond))
            throw new IllegalArgumentException("a perception rate must be a positive number of updates per second, not " + perSecond);
        this.inner = inner;
        this.perSecond = perSecond;
        this.gapNanos = (long) (1e9 / perSecond);
    }

    @Override
    public boolean update(String source, List<Literal> literals, long nowNanos) {
        synchronized (this) {
            Window w = windows.get(source);
            if (w != null && nowNanos - w.appliedNanos < gapNanos) {
                w.held = literals;
                w.heldNanos = nowNanos;
                return false;
            }
            if (w == null)
                windows.put(source, new Window(nowNanos));
            else {
                w.appliedNanos = nowNanos;
                w.held = null;
            }
        }
        return inner.update(source, literals, nowNanos);
    }

    @Override
    public boolean expire(long nowNanos, long ttlNanos) {
        boolean changed = false;
        synchronized (this) {
            for (Map.Entry<String, Window> e : windows.entrySet()) {
                Window w = e.getValue();
                if (w.held != null && nowNanos - w.appliedNanos >= gapNanos) {
                    List<Literal> due = w.held;
                    w.held = null;
                    w.appliedNanos = nowNanos;
                    changed |= inner.update(e.getKey(), due, w.heldNanos);
                }
            }
            // a source quiet for a whole window needs no bookkeeping any more
            windows.values().removeIf(w -> w.held == null && nowNanos - w.appliedNanos >= gapNanos);
        }
        return inner.expire(nowNanos, ttlNanos) | changed;
    }

    @Override
    public Collection<Literal> perceive() {
        return inner.perceive();
    }

    @Override
    public Collection<Literal> current() {
        return inner.current();
    }

    @Override
    public boolean wants(Literal literal) {
        return inner.wants(literal);
    }

    @Override
    public String toString() {
        return "rate_limit(" + perSecond + "/s) over " + inner;
    }
}
