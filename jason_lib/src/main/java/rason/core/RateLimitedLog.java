package rason.core;

import java.util.ArrayList;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.logging.Level;
import java.util.logging.Logger;

/**
 * Logs at most a few lines of one kind (dropped perception, dropped message,
 * ignored event, …) per period, and when the period ends one line saying how
 * many more there were. A period starts with the first line of its kind; it is
 * closed by the next line of that kind after its end or by {@link #tick}. Time
 * is passed in (any clock that only goes forward, in nanoseconds).
 */
public final class RateLimitedLog {

    public static final int DEFAULT_LINES = 10;
    public static final long DEFAULT_PERIOD_NANOS = 10_000_000_000L;
    /** Kinds are names in code, but their number is bounded all the same. */
    static final int MAX_KINDS = 100;

    private static final class Window {
        final long start;
        int logged;
        long suppressed;
        Level level = Level.FINEST; // the highest level among the suppressed lines

        Window(long start) {
            this.start = start;
        }
    }

    private record Line(Level level, String text) {
    }

    private final Logger logger;
    private final int lines;
    private volatile long periodNanos;
    private final Map<String, Window> windows = new LinkedHashMap<>() { // guarded by itself
        @Override
        protected boolean removeEldestEntry(Map.Entry<String, Window> eldest) {
            return size() > MAX_KINDS;
        }
    };

    public RateLimitedLog(Logger logger) {
        this(logger, DEFAULT_LINES, DEFAULT_PERIOD_NANOS);
    }

    /** @param lines lines of one kind logged per period (1 or more) */
    public RateLimitedLog(Logger logger, int lines, long periodNanos) {
        if (lines < 1 || periodNanos <= 0)
            throw new IllegalArgumentException("need at least one line per period of more than 0 ns");
        this.logger = logger;
        this.lines = lines;
        this.periodNanos = periodNanos;
    }

    /**
     * From now on a period lasts periodNanos; the periods already under way end by the new
     * length (a shorter one ends them sooner).
     */
    public void setPeriodNanos(long periodNanos) {
        if (periodNanos <= 0)
            throw new IllegalArgumentException("a period is more than 0 ns");
        this.periodNanos = periodNanos;
    }

    public long periodNanos() {
        return periodNanos;
    }

    /**
     * Logs message unless its kind has had its lines this period (then it is counted).
     *
     * @return true if it was logged
     */
    public boolean log(String kind, Level level, String message, long nowNanos) {
        Line summary = null;
        boolean logged;
        synchronized (windows) {
            Window w = windows.get(kind);
            if (w != null && nowNanos - w.start >= periodNanos) {
                windows.remove(kind);
                summary = summary(kind, w, nowNanos);
                w = null;
            }
            if (w == null) {
                w = new Window(nowNanos);
                windows.put(kind, w);
            }
            logged = w.logged < lines;
            if (logged) {
                w.logged++;
            } else {
                w.suppressed++;
                if (level.intValue() > w.level.intValue())
                    w.level = level;
            }
        }
        if (summary != null)
            logger.log(summary.level, summary.text);
        if (logged)
            logger.log(level, message);
        return logged;
    }

    public boolean warn(String kind, String message, long nowNanos) {
        return log(kind, Level.WARNING, message, nowNanos);
    }

    /** Ends the periods that are over, logging the summary of those that suppressed lines. */
    public void tick(long nowNanos) {
        endPeriods(nowNanos, false);
    }

    /** Ends every period now, over or not, logging the summaries: each kind has all its lines again. */
    public void endAll(long nowNanos) {
        endPeriods(nowNanos, true);
    }

    private void endPeriods(long nowNanos, boolean all) {
        List<Line> out = new ArrayList<>();
        synchronized (windows) {
            for (Iterator<Map.Entry<String, Window>> it = windows.entrySet().iterator(); it.hasNext();) {
                Map.Entry<String, Window> e = it.next();
                if (all || nowNanos - e.getValue().start >= periodNanos) {
                    it.remove();
                    Line s = summary(e.getKey(), e.getValue(), nowNanos);
                    if (s != null)
                        out.add(s);
                }
            }
        }
        for (Line s : out)
            logger.log(s.level, s.text);
    }

    /** How many lines of kind the current period has suppressed so far. */
    public long suppressed(String kind) {
        synchronized (windows) {
            Window w = windows.get(kind);
            return w == null ? 0 : w.suppressed;
        }
    }

    private static Line summary(String kind, Window w, long nowNanos) {
        if (w.suppressed == 0)
            return null;
        long seconds = Math.max(1, Math.round((nowNanos - w.start) / 1e9));
        return new Line(w.level, String.format(Locale.ROOT, "%s: … %,d more like this in the last %d s", kind,
                w.suppressed, seconds));
    }
}
