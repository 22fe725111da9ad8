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

import rason.core.Protocol;

class ActionTableTest {

    private static final long SECOND = 1_000_000_000L;

    private final AtomicInteger ids = new AtomicInteger();
    private final ActionTable<String> table = new ActionTable<>(ids::incrementAndGet);

    private static void assertSettled(ActionTable.FeedbackOutcome o) {
        assertEquals(ActionTable.FeedbackOutcome.SETTLED, o);
    }

    private static void assertNotSettled(ActionTable.FeedbackOutcome o) {
        assertNotEquals(ActionTable.FeedbackOutcome.SETTLED, o);
    }

    private static ActionTable.Settled<String> only(List<ActionTable.Settled<String>> settled) {
        assertEquals(1, settled.size(), settled.toString());
        return settled.get(0);
    }

    @Test
    void okFeedbackSettlesTheActionOnce() {
        int id = table.start("move(1)", 10 * SECOND);
        assertFalse(table.hasSettled());
        assertSettled(table.feedback(id, Protocol.OK));
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
        assertSettled(table.feedback(id, reason));
        assertEquals(reason, only(table.takeSettled()).result());
    }

    @Test
    void idsComeFromTheSourceAndDiffer() {
        int a = table.start("a", SECOND);
        int b = table.start("b", SECOND);
        assertNotEquals(a, b);
        assertEquals(2, table.pendingCount());
        assertSettled(table.feedback(b, Protocol.OK));
        assertEquals("b", only(table.takeSettled()).action());
        assertEquals(1, table.pendingCount());
    }

    @Test
    void unknownIdIsRefusedAndChangesNothing() {
        int id = table.start("move(1)", SECOND);
        assertNotSettled(table.feedback(id + 1000, Protocol.OK));
        assertFalse(table.hasSettled());
        assertEquals(1, table.pendingCount());
    }

    @Test
    void lateFeedbackAfterTheActionEndedIsRefused() {
        int id = table.start("move(1)", SECOND);
        table.feedback(id, "no_progress");
        table.takeSettled();
        assertNotSettled(table.feedback(id, Protocol.OK));
        assertFalse(table.hasSettled());
    }

    @Test
    void timeoutSettlesOnlyActionsOlderThanItAndOnlyOnce() {
        int old = table.start("old", 1 * SECOND);
        table.start("young", 5 * SECOND);
        assertTrue(table.expire(3 * SECOND, 2 * SECOND, Protocol.TIMEOUT).isEmpty()); // 2 s old: not more than the timeout
        assertFalse(table.expire(3 * SECOND + 1, 2 * SECOND, Protocol.TIMEOUT).isEmpty());
        assertEquals(new ActionTable.Settled<>("old", old, Protocol.TIMEOUT), only(table.takeSettled()));
        assertTrue(table.expire(3 * SECOND + 2, 2 * SECOND, Protocol.TIMEOUT).isEmpty());
        assertEquals(ActionTable.FeedbackOutcome.AFTER_CANCEL, table.feedback(old, Protocol.OK), "feedback after the timeout is late");
        assertEquals(1, table.pendingCount());
    }

    @Test
    void noTimeoutWhenDisabled() {
        table.start("a", SECOND);
        assertTrue(table.expire(1000 * SECOND, 0, Protocol.TIMEOUT).isEmpty());
        assertTrue(table.expire(1000 * SECOND, -1, Protocol.TIMEOUT).isEmpty());
        assertEquals(1, table.pendingCount());
    }

    @Test
    void anActionStartedBeforeTheClockWasKnownCountsFromTheFirstKnownTime() {
        table.start("early", 0); // e.g. /use_sim_time before the first /clock
        assertTrue(table.expire(100 * SECOND, 2 * SECOND, Protocol.TIMEOUT).isEmpty(), "the clock jumping from 0 is no timeout");
        assertTrue(table.expire(101 * SECOND, 2 * SECOND, Protocol.TIMEOUT).isEmpty());
        assertFalse(table.expire(102 * SECOND + 1, 2 * SECOND, Protocol.TIMEOUT).isEmpty());
    }

    @Test
    void shutdownFailsEveryPendingActionWithItsReason() {
        int a = table.start("a", SECOND);
        int b = table.start("b", SECOND);
        assertEquals(List.of(new ActionTable.Taken<>("a", a), new ActionTable.Taken<>("b", b)), table.failAll(Protocol.SHUTDOWN));
        List<ActionTable.Settled<String>> settled = table.takeSettled();
        assertEquals(List.of(new ActionTable.Settled<>("a", a, Protocol.SHUTDOWN),
                new ActionTable.Settled<>("b", b, Protocol.SHUTDOWN)), settled);
        assertEquals(0, table.pendingCount());
        assertNotSettled(table.feedback(a, Protocol.OK));
        assertTrue(table.failAll(Protocol.SHUTDOWN).isEmpty());
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
                    if (table.feedback(idOf[i], Protocol.OK) == ActionTable.FeedbackOutcome.SETTLED)
                        accepted.incrementAndGet();
            });
            threads[t].start();
        }
        for (Thread t : threads)
            t.join();
        assertEquals(n, accepted.get());
        assertEquals(n, table.takeSettled().size());
    }

    @Test
    void aTakenBackActionLeavesUnsettledAndItsLateFeedbackIsRecognised() {
        int a = table.start("a", SECOND);
        int b = table.start("b", SECOND);
        assertEquals(List.of(new ActionTable.Taken<>("a", a)), table.cancel("a"::equals));
        assertFalse(table.hasSettled(), "Jason no longer waits for it: nothing to settle");
        assertEquals(1, table.pendingCount());
        assertEquals(ActionTable.FeedbackOutcome.AFTER_CANCEL, table.feedback(a, Protocol.CANCELLED));
        assertEquals(ActionTable.FeedbackOutcome.UNKNOWN, table.feedback(b + 1000, Protocol.OK));
        assertTrue(table.cancel("a"::equals).isEmpty(), "taken back once");
        assertSettled(table.feedback(b, Protocol.OK));
    }

    @Test
    void aHeldActionIgnoresItsFeedbackAndTimeoutUntilReleased() {
        int a = table.start("a", SECOND);
        assertEquals(List.of(new ActionTable.Taken<>("a", a)), table.hold("a"::equals));
        assertTrue(table.hold("a"::equals).isEmpty(), "held once");
        assertEquals(ActionTable.FeedbackOutcome.AFTER_CANCEL, table.feedback(a, Protocol.CANCELLED));
        assertTrue(table.expire(1000 * SECOND, 2 * SECOND, Protocol.TIMEOUT).isEmpty());
        assertFalse(table.hasSettled());
        assertFalse(table.release("b"::equals, Protocol.SUSPENDED));
        assertTrue(table.release("a"::equals, Protocol.SUSPENDED));
        assertEquals(new ActionTable.Settled<>("a", a, Protocol.SUSPENDED), only(table.takeSettled()));
        assertEquals(0, table.pendingCount());
    }

    @Test
    void aHeldActionThatIsDroppedNeedsNoSecondCancel() {
        table.start("a", SECOND);
        table.hold("a"::equals);
        assertTrue(table.cancel("a"::equals).isEmpty());
        assertEquals(0, table.pendingCount());
        assertFalse(table.hasSettled());
    }

    @Test
    void shutdownSettlesHeldActionsWithoutASecondCancel() {
        int a = table.start("a", SECOND);
        table.hold("a"::equals);
        assertTrue(table.failAll(Protocol.SHUTDOWN).isEmpty());
        assertEquals(new ActionTable.Settled<>("a", a, Protocol.SHUTDOWN), only(table.takeSettled()));
    }

    @Test
    void anActionFailsWhenItsDecomposerIsGoneLongerThanTheGrace() {
        int a = table.start("a", SECOND);
        int b = table.start("b", SECOND);
        assertTrue(table.startedBy(a, "/robot/motion"));
        assertFalse(table.startedBy(b + 1000, "/robot/motion"));
        java.util.Set<String> none = java.util.Set.of();
        assertTrue(table.decomposersLost(java.util.Set.of("/robot/motion"), 0, 100, Protocol.DECOMPOSER_LOST).isEmpty());
        assertTrue(table.decomposersLost(none, 1_000, 100, Protocol.DECOMPOSER_LOST).isEmpty(), "first seen missing");
        assertTrue(table.decomposersLost(none, 1_100, 100, Protocol.DECOMPOSER_LOST).isEmpty(), "within the grace");
        assertTrue(table.decomposersLost(java.util.Set.of("/robot/motion"), 1_150, 100, Protocol.DECOMPOSER_LOST).isEmpty(),
                "back in time: the clock restarts");
        assertTrue(table.decomposersLost(none, 1_200, 100, Protocol.DECOMPOSER_LOST).isEmpty());
        assertEquals(List.of(new ActionTable.Taken<>("a", a)),
                table.decomposersLost(none, 1_301, 100, Protocol.DECOMPOSER_LOST));
        assertEquals(new ActionTable.Settled<>("a", a, Protocol.DECOMPOSER_LOST), only(table.takeSettled()));
        assertEquals(1, table.pendingCount(), "b was never claimed: left to its timeout");
        assertEquals(ActionTable.FeedbackOutcome.AFTER_CANCEL, table.feedback(a, Protocol.OK));
    }

    @Test
    void recentCancelsAreBounded() {
        for (int i = 0; i < ActionTable.RECENT_CANCELS + 10; i++) {
            String name = "a" + i;
            table.start(name, SECOND);
            table.cancel(name::equals);
        }
        assertEquals(ActionTable.FeedbackOutcome.UNKNOWN, table.feedback(1, Protocol.OK), "the oldest is forgotten");
        assertEquals(ActionTable.FeedbackOutcome.AFTER_CANCEL, table.feedback(ActionTable.RECENT_CANCELS + 10, Protocol.OK));
    }
}
