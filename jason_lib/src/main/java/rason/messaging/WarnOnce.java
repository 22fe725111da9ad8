package rason.messaging;

import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Set;
import java.util.logging.Level;
import java.util.logging.Logger;

/**
 * Logs a line the first time its key is seen. The keys come from the
 * network, so only the most recent ones are remembered: a flood of distinct
 * names cannot grow memory without bound.
 */
public final class WarnOnce {

    static final int MAX_KEYS = 1000;

    private final Logger logger;
    private final Set<String> seen = Collections.newSetFromMap(new LinkedHashMap<String, Boolean>() {
        @Override
        protected boolean removeEldestEntry(Map.Entry<String, Boolean> eldest) {
            return size() > MAX_KEYS;
        }
    });

    public WarnOnce(Logger logger) {
        this.logger = logger;
    }

    /** @return true the first time key is seen (nothing is logged: the caller logs) */
    public boolean firstTime(String key) {
        synchronized (seen) {
            return seen.add(key);
        }
    }

    /** Logs a warning the first time key is seen; @return true if it was logged */
    public boolean warn(String key, String message) {
        return log(key, Level.WARNING, message);
    }

    /** Logs at level the first time key is seen; @return true if it was logged */
    public boolean log(String key, Level level, String message) {
        synchronized (seen) {
            if (!seen.add(key))
                return false;
        }
        logger.log(level, message);
        return true;
    }
}
