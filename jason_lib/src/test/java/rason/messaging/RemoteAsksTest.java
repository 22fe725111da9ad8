package rason.messaging;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Set;

import org.junit.jupiter.api.Test;

class RemoteAsksTest {

    private static final long SECOND = 1_000_000_000L;
    private final RemoteAsks asks = new RemoteAsks();

    @Test
    void anAnsweredAskIsForgotten() {
        asks.track("sa1", "bob", SECOND, 60 * SECOND);
        assertTrue(asks.settle(id -> false, 2 * SECOND, null).isEmpty());
        assertTrue(asks.isEmpty());
    }

    @Test
    void anAskWhoseReceiverLeftFailsNamingIt() {
        asks.track("sa1", "bob", SECOND, 60 * SECOND);
        asks.track("sa2", "carol", SECOND, 60 * SECOND);
        assertTrue(asks.receiversLost(List.of("bob")));
        assertTrue(asks.hasLost());
        List<RemoteAsks.Failure> failed = asks.settle(id -> true, 2 * SECOND, null);
        assertEquals(List.of(new RemoteAsks.Failure("sa1", RemoteAsks.RECEIVER_DEPARTED, "bob left before answering", "bob")),
                failed);
        assertFalse(asks.hasLost());
        assertFalse(asks.isEmpty(), "the ask to carol still waits");
    }

    @Test
    void lossesMatterOnlyWhenSomethingWaits() {
        assertFalse(asks.receiversLost(List.of("bob")));
        assertFalse(asks.hasLost());
    }

    @Test
    void anAskTimesOutAfterItsTimeoutOnly() {
        asks.track("sa1", "bob", 10 * SECOND, 5 * SECOND);
        assertFalse(asks.due(15 * SECOND));
        assertTrue(asks.settle(id -> true, 15 * SECOND, null).isEmpty());
        assertTrue(asks.due(15 * SECOND + 1));
        List<RemoteAsks.Failure> failed = asks.settle(id -> true, 15 * SECOND + 1, null);
        assertEquals(1, failed.size());
        assertEquals(RemoteAsks.ASK_TIMEOUT, failed.get(0).error());
        assertTrue(asks.isEmpty());
    }

    @Test
    void anAskWithJasonsOwnTimeoutIsLeftToJason() {
        asks.track("sa1", "bob", SECOND, 0);
        assertFalse(asks.due(1000 * SECOND));
        assertTrue(asks.settle(id -> true, 1000 * SECOND, null).isEmpty());
    }

    @Test
    void anAskSentBeforeTheClockWasKnownCountsFromTheFirstKnownTime() {
        asks.track("sa1", "bob", 0, 5 * SECOND);
        assertFalse(asks.due(100 * SECOND));
        assertFalse(asks.due(105 * SECOND));
        assertTrue(asks.due(105 * SECOND + 1));
    }

    @Test
    void stoppingFailsEveryWaitingAsk() {
        asks.track("sa1", "bob", SECOND, 0);
        asks.track("sa2", "carol", SECOND, 60 * SECOND);
        List<RemoteAsks.Failure> failed = asks.settle(Set.of("sa1", "sa2")::contains, 2 * SECOND, "shutdown");
        assertEquals(2, failed.size());
        assertTrue(failed.stream().allMatch(f -> f.error().equals("shutdown")));
        assertTrue(asks.isEmpty());
    }

    @Test
    void aForgottenAskNeverFails() {
        asks.track("sa1", "bob", SECOND, SECOND);
        asks.forget("sa1");
        asks.receiversLost(List.of("bob"));
        assertTrue(asks.settle(id -> true, 100 * SECOND, null).isEmpty());
    }
}
