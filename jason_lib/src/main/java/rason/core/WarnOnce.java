package rason.core;

import java.nio.charset.StandardCharsets;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.Collections;
import java.util.HexFormat;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Set;
import java.util.logging.Level;
import java.util.logging.Logger;

/**
 * Logs a line the first time its key is seen. The keys come from the
 * network, so only the most recent ones are remembered, and a long key is
 * remembered by a short digest of it: a flood of distinct names, however long,
 * cannot grow memory without bound.
 */
public final class WarnOnce {

    static final int MAX_KEYS = 1000;
    /** Characters of a key kept as they are; a longer key is remembered by its digest. */
    static final int MAX_KEY_LENGTH = 256;

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
        String k = remembered(key);
        synchronized (seen) {
            return seen.add(k);
        }
    }

    /** Logs a warning the first time key is seen; @return true if it was logged */
    public boolean warn(String key, String message) {
        return log(key, Level.WARNING, message);
    }

    /** Logs at level the first time key is seen; @return true if it was logged */
    public boolean log(String key, Level level, String message) {
        if (!firstTime(key))
            return false;
        logger.log(level, message);
        return true;
    }

    /** What is stored for key: itself if short, else its start, length and SHA-256 (a 1 MB name costs 130 bytes). */
    static String remembered(String key) {
        if (key == null || key.length() <= MAX_KEY_LENGTH)
            return key;
        try {
            byte[] digest = MessageDigest.getInstance("SHA-256").digest(key.getBytes(StandardCharsets.UTF_8));
            return key.substring(0, 32) + "#" + key.length() + "#" + HexFormat.of().formatHex(digest);
        } catch (NoSuchAlgorithmException e) { // every Java has SHA-256
            throw new IllegalStateException(e);
        }
    }
}
