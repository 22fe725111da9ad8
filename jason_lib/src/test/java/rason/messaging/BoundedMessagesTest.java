package rason.messaging;

import rason.core.RateLimitedLog;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.logging.Logger;

import org.junit.jupiter.api.Test;

import rason.core.InputLimits;

class BoundedMessagesTest {

    @Test
    void contentLongerThanTheLimitIsRefusedBeforeParsingAndNotEchoedWhole() {
        String content = "\"" + "a".repeat(1 << 20) + "\"";
        long t0 = System.nanoTime();
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> Messages.parseContent(content));
        assertTrue(System.nanoTime() - t0 < 1_000_000_000L);
        assertTrue(e.getMessage().endsWith("refused: longer than 65536 characters"), e.getMessage());
        assertTrue(e.getMessage().length() < 400, "the log line shows the start of the content only");
    }

    @Test
    void deepContentIsRefused() {
        String deep = "f(".repeat(100_000) + "a" + ")".repeat(100_000);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> Messages.parseContent(deep, new InputLimits().setMaxContentLength(Integer.MAX_VALUE)));
        assertTrue(e.getMessage().endsWith("refused: nesting deeper than 32"), e.getMessage());
    }

    @Test
    void aLongListThatJasonWouldParseButNotCopyIsRefused() {
        // 5,000 elements parse, but Jason's clone and hashCode recurse once per element
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> Messages.parseContent("[" + "a,".repeat(5000) + "a]"));
        assertTrue(e.getMessage().contains("refused: term deeper than 512 levels"), e.getMessage());
        assertEquals(301, Messages.parseContent("[" + "a,".repeat(300) + "a]").toString().split(",").length);
    }

    @Test
    void droppedMessagesAreLoggedAFewTimesPerPeriodAndCounted() {
        Logger logger = Logger.getLogger("test.bounded.fleet");
        rason.core.RateLimitedLogTest.Lines lines = rason.core.RateLimitedLogTest.Lines.of(logger);
        RateLimitedLog limited = new RateLimitedLog(logger, 5, 3_600_000_000_000L);
        Fleet fleet = SigningPeer.fleet(logger, limited, "/me/rason_mas", 1);
        SigningPeer other = new SigningPeer("/other/rason_mas", 1);
        for (int i = 0; i < 100; i++)
            assertNull(other.send(fleet, "mallory", "alice", "tell", "hello("));
        assertEquals(5, lines.records.size());
        assertTrue(lines.texts().get(0).startsWith(
                "dropped message tell from mallory (/other/rason_mas) to alice: content 'hello(' is not a Jason term"),
                lines.texts().get(0));
        assertEquals(95, limited.suppressed(Fleet.DROPPED_MESSAGE));
        assertNotNull(other.send(fleet, "mallory", "alice", "tell", "hello"));
    }
}
