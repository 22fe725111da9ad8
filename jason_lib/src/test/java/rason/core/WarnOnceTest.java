package rason.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.logging.Handler;
import java.util.logging.LogRecord;
import java.util.logging.Logger;

import org.junit.jupiter.api.Test;

class WarnOnceTest {

    private final Logger logger = Logger.getLogger("rason.test.warnonce");
    private final List<String> lines = new ArrayList<>();

    WarnOnceTest() {
        logger.setUseParentHandlers(false);
        logger.addHandler(new Handler() {
            @Override
            public void publish(LogRecord r) {
                lines.add(r.getMessage());
            }

            @Override
            public void flush() {
            }

            @Override
            public void close() {
            }
        });
    }

    @Test
    void logsOncePerKey() {
        WarnOnce w = new WarnOnce(logger);
        assertTrue(w.warn("a", "first a"));
        assertFalse(w.warn("a", "second a"));
        assertTrue(w.warn("b", "first b"));
        assertEquals(List.of("first a", "first b"), lines);
    }

    @Test
    void longKeysAreRememberedByADigest() {
        WarnOnce w = new WarnOnce(logger);
        String big = "x".repeat(1 << 20);
        String other = "x".repeat((1 << 20) - 1) + "y"; // same start and length
        assertTrue(w.firstTime(big));
        assertFalse(w.firstTime(new String(big)));
        assertTrue(w.firstTime(other));
        assertTrue(WarnOnce.remembered(big).length() < 140, "a 1 MB key is kept in " + WarnOnce.remembered(big).length() + " characters");
        assertEquals("short", WarnOnce.remembered("short"));
    }

    @Test
    void onlyTheMostRecentKeysAreRemembered() {
        WarnOnce w = new WarnOnce(logger);
        for (int i = 0; i <= WarnOnce.MAX_KEYS; i++)
            assertTrue(w.firstTime("k" + i));
        assertTrue(w.firstTime("k0"), "the oldest key was forgotten");
        assertFalse(w.firstTime("k" + WarnOnce.MAX_KEYS));
    }
}
