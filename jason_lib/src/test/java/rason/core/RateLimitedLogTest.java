package rason.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.logging.Handler;
import java.util.logging.Level;
import java.util.logging.LogRecord;
import java.util.logging.Logger;

import org.junit.jupiter.api.Test;

public class RateLimitedLogTest {

    static final long S = 1_000_000_000L;

    /** Collects what a logger logs, without passing it to the console. */
    public static final class Lines extends Handler {
        public final List<LogRecord> records = new ArrayList<>();

        public static Lines of(Logger logger) {
            Lines l = new Lines();
            logger.setUseParentHandlers(false);
            logger.addHandler(l);
            return l;
        }

        public List<String> texts() {
            return records.stream().map(LogRecord::getMessage).toList();
        }

        @Override
        public synchronized void publish(LogRecord r) {
            records.add(r);
        }

        @Override
        public void flush() {
        }

        @Override
        public void close() {
        }
    }

    private final Logger logger = Logger.getLogger("test.ratelimited." + System.identityHashCode(this));
    private final Lines lines = Lines.of(logger);
    private final RateLimitedLog log = new RateLimitedLog(logger, 5, 10 * S);

    @Test
    void theFirstLinesOfAPeriodAreLoggedAndTheRestCounted() {
        for (int i = 0; i < 10_000; i++)
            assertEquals(i < 5, log.warn("dropped perception", "line " + i, 100 * S + i));
        assertEquals(List.of("line 0", "line 1", "line 2", "line 3", "line 4"), lines.texts());
        assertEquals(9_995, log.suppressed("dropped perception"));
    }

    @Test
    void endingAllPeriodsSummarisesThemAndGivesEachKindItsLinesAgain() {
        for (int i = 0; i < 8; i++)
            log.warn("dropped perception", "line " + i, 100 * S);
        log.warn("ignored event", "event", 100 * S);
        log.endAll(102 * S);
        assertEquals("dropped perception: … 3 more like this in the last 2 s", lines.texts().get(6));
        assertEquals(7, lines.records.size(), "no summary where nothing was suppressed");
        assertTrue(log.warn("dropped perception", "again", 102 * S));
    }

    @Test
    void theTickAtTheEndOfThePeriodLogsTheSummary() {
        for (int i = 0; i < 10_000; i++)
            log.warn("dropped perception", "line " + i, 100 * S);
        log.tick(109 * S);
        assertEquals(5, lines.records.size(), "no summary before the period ends");
        log.tick(110 * S);
        assertEquals(6, lines.records.size());
        assertEquals("dropped perception: … 9,995 more like this in the last 10 s", lines.texts().get(5));
        assertEquals(Level.WARNING, lines.records.get(5).getLevel());
        log.tick(200 * S);
        assertEquals(6, lines.records.size(), "one summary per period");
        assertEquals(0, log.suppressed("dropped perception"));
    }

    @Test
    void withoutTicksTheNextLineAfterThePeriodBringsTheSummaryAndOpensANewPeriod() {
        for (int i = 0; i < 8; i++)
            log.warn("k", "line " + i, 100 * S);
        assertTrue(log.warn("k", "late", 130 * S));
        assertEquals(List.of("line 0", "line 1", "line 2", "line 3", "line 4",
                "k: … 3 more like this in the last 30 s", "late"), lines.texts());
        for (int i = 0; i < 4; i++)
            assertTrue(log.warn("k", "again " + i, 131 * S));
        assertFalse(log.warn("k", "one too many", 131 * S));
    }

    @Test
    void aPeriodWithoutSuppressedLinesEndsSilently() {
        log.warn("k", "only", 100 * S);
        log.tick(111 * S);
        assertEquals(List.of("only"), lines.texts());
    }

    @Test
    void kindsAreCountedApart() {
        for (int i = 0; i < 7; i++) {
            log.warn("a", "a" + i, 100 * S);
            log.log("b", Level.INFO, "b" + i, 100 * S);
        }
        assertEquals(2, log.suppressed("a"));
        assertEquals(2, log.suppressed("b"));
        assertEquals(10, lines.records.size());
        log.tick(110 * S);
        assertTrue(lines.texts().containsAll(List.of("a: … 2 more like this in the last 10 s",
                "b: … 2 more like this in the last 10 s")), lines.texts().toString());
        LogRecord b = lines.records.stream().filter(r -> r.getMessage().startsWith("b: …")).findFirst().orElseThrow();
        assertEquals(Level.INFO, b.getLevel(), "the summary has the level of the lines it stands for");
    }

    @Test
    void aShorterPeriodEndsThePeriodUnderWaySooner() {
        for (int i = 0; i < 8; i++)
            log.warn("k", "line " + i, 100 * S);
        log.setPeriodNanos(2 * S);
        log.tick(101 * S);
        assertEquals(5, lines.records.size(), "no summary before the new period's end");
        log.tick(102 * S);
        assertEquals("k: … 3 more like this in the last 2 s", lines.texts().get(5));
        assertEquals(2 * S, log.periodNanos());
    }

    @Test
    void aPeriodIsMoreThanZero() {
        org.junit.jupiter.api.Assertions.assertThrows(IllegalArgumentException.class, () -> log.setPeriodNanos(0));
        assertEquals(10 * S, log.periodNanos());
    }
}
