package rason.action;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

import rason.bridge.Protocol;

class ActionTableTest {

    private static final long SECOND = 1_000_000_000L;

    private final AtomicInteger ids = new AtomicInteger();
    private final ActionTable<String> table = new ActionTable<>(ids::incrementAndGet);

    private static ActionTable.Settled<String> only(List<ActionTable.Settled<String>> settled) {
        assertEquals(1, settled.size(), settled.toString());
        return settled.get(0);
    }

    @Test
    void okFeedbackSettlesTheActionOnce() {
        int id = table.start("move(1)", 10 * SECOND);
        assertFalse(table.hasSettled());
        assertTrue(table.feedback(id, Protocol.OK));
        assertTrue(table.hasSettled());
        assertEquals(new ActionTable.Settled<>("move(1)", id, Protocol.OK), only(table.takeSettled()));
        assertFalse(table.hasSettled());
        assertEquals(0, table.pendingCount());
        assertTrue(table.takeSettled().isEmpty());
    }

    @ParameterizedTest
    @ValueSource(strings = { "no_progress", "bad_move", "bad_parameters", "no_decomposer", "Motor stalled!" })
    void aFailureReasonIsPassedOnAsItCame(String reason) {
        int id = table.start("move(1)", SECOND);
        assertTrue(table.feedback(id, reason));
        assertEquals(reason, only(table.takeSettled()).result());
    }

    @Test
    void idsComeFromTheSourceAndDiffer() {
        int a = table.start("a", SECOND);
        int b = table.start("b", SECOND);
        assertNotEquals(a, b);
        assertEquals(2, table.pendingCount());
        assertTrue(table.feedback(b, Protocol.OK));
        assertEquals("b", only(table.takeSettled()).action());
        assertEquals(1, table.pendingCount());
    }

    @Test
    void unknownIdIsRefusedAndChangesNothing() {
        int id = table.start("move(1)", SECOND);
        assertFalse(table.feedback(id + 1000, Protocol.OK));
        assertFalse(table.hasSettled());
        assertEquals(1, table.pendingCount());
    }

    @Test
    void lateFeedbackAfterTheActionEndedIsRefused() {
        int id = table.start("move(1)", SECOND);
        table.feedback(id, "no_progress");
        table.takeSettled();
        assertFalse(table.feedback(id, Protocol.OK));
        assertFalse(table.hasSettled());
    }

    @Test
    void timeoutSettlesOnlyActionsOlderThanItAndOnlyOnce() {
        int old = table.start("old", 1 * SECOND);
        table.start("young", 5 * SECOND);
        assertFalse(table.expire(3 * SECOND, 2 * SECOND, Protocol.TIMEOUT)); // 2 s old: not more than the timeout
        assertTrue(table.expire(3 * SECOND + 1, 2 * SECOND, Protocol.TIMEOUT));
        assertEquals(new ActionTable.Settled<>("old", old, Protocol.TIMEOUT), only(table.takeSettled()));
        assertFalse(table.expire(3 * SECOND + 2, 2 * SECOND, Protocol.TIMEOUT));
        assertFalse(table.feedback(old, Protocol.OK), "feedback after the timeout is late");
        assertEquals(1, table.pendingCount());
    }

    @Test
    void noTimeoutWhenDisabled() {
        table.start("a", SECOND);
        assertFalse(table.expire(1000 * SECOND, 0, Protocol.TIMEOUT));
        assertFalse(table.expire(1000 * SECOND, -1, Protocol.TIMEOUT));
        assertEquals(1, table.pendingCount());
    }

    @Test
    void anActionStartedBeforeTheClockWasKnownCountsFromTheFirstKnownTime() {
        table.start("early", 0); // e.g. /use_sim_time before the first /clock
        assertFalse(table.expire(100 * SECOND, 2 * SECOND, Protocol.TIMEOUT), "the clock jumping from 0 is no timeout");
        assertFalse(table.expire(101 * SECOND, 2 * SECOND, Protocol.TIMEOUT));
        assertTrue(table.expire(102 * SECOND + 1, 2 * SECOND, Protocol.TIMEOUT));
    }

    @Test
    void shutdownFailsEveryPendingActionWithItsReason() {
        int a = table.start("a", SECOND);
        int b = table.start("b", SECOND);
        assertEquals(2, table.failAll(Protocol.SHUTDOWN));
        List<ActionTable.Settled<String>> settled = table.takeSettled();
        assertEquals(List.of(new ActionTable.Settled<>("a", a, Protocol.SHUTDOWN),
                new ActionTable.Settled<>("b", b, Protocol.SHUTDOWN)), settled);
        assertEquals(0, table.pendingCount());
        assertFalse(table.feedback(a, Protocol.OK));
        assertEquals(0, table.failAll(Protocol.SHUTDOWN));
    }

    @Test
    void settledActionsComeOutInTheOrderTheyEnded() {
        int a = table.start("a", SECOND);
        int b = table.start("b", SECOND);
        table.feedback(b, Protocol.OK);
        table.feedback(a, "bad_move");
        List<ActionTable.Settled<String>> settled = table.takeSettled();
        assertEquals("b", settled.get(0).action());
        assertEquals("a", settled.get(1).action());
    }

    @Test
    void feedbackFromManyThreadsSettlesEachActionExactlyOnce() throws InterruptedException {
        int n = 2000;
        int[] idOf = new int[n];
        for (int i = 0; i < n; i++)
            idOf[i] = table.start("a" + i, SECOND);
        AtomicInteger accepted = new AtomicInteger();
        Thread[] threads = new Thread[4];
        for (int t = 0; t < threads.length; t++) {
            threads[t] = new Thread(() -> {
                for (int i = 0; i < n; i++)
                    if (table.feedback(idOf[i], Protocol.OK))
                        accepted.incrementAndGet();
            });
            threads[t].start();
        }
        for (Thread t : threads)
            t.join();
        assertEquals(n, accepted.get());
        assertEquals(n, table.takeSettled().size());
    }
}
