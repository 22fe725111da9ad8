package rason.core;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;

class LogQueueTest {

    private static LogQueue attached() {
        LogQueue q = new LogQueue();
        q.setAttached(true);
        return q;
    }

    @Test
    void aBatchHoldsTheLinesInOrderWithTheirLevelsAndAgents() {
        LogQueue q = attached();
        q.add(800, "bob", "hello");
        q.add(1000, "", "jason failed");
        q.add(900, "alice", "");
        LogQueue.Batch b = q.drainBatch(10);
        assertArrayEquals(new int[] {800, 1000, 900}, b.levels());
        assertEquals("[bob] hellojason failed[alice] ", b.text());
        assertArrayEquals(new int[] {11, 23, 31}, b.ends());
        assertEquals(0, q.drainBatch(10).levels().length);
    }

    @Test
    void endsCountCodePointsSoThatPythonSlicesTheSameLines() {
        LogQueue q = attached();
        q.add(800, "", "a\uD83D\uDE00b"); // one character outside the BMP: two Java chars, one code point
        q.add(800, "", "c");
        assertArrayEquals(new int[] {3, 4}, q.drainBatch(10).ends());
    }

    @Test
    void aBatchTakesAtMostMaxLinesAndLeavesTheRest() {
        LogQueue q = attached();
        for (int i = 0; i < 5; i++)
            q.add(800, "", "line" + i);
        assertEquals(3, q.drainBatch(3).levels().length);
        LogQueue.Batch rest = q.drainBatch(3);
        assertEquals("line3line4", rest.text());
    }

    @Test
    void awaitLinesReturnsAtOnceWhenLinesAreQueuedAndFalseAfterItsTimeWithout() {
        LogQueue q = attached();
        long t0 = System.nanoTime();
        assertFalse(q.awaitLines(50));
        assertTrue(System.nanoTime() - t0 >= TimeUnit.MILLISECONDS.toNanos(50));
        q.add(800, "bob", "x");
        assertTrue(q.awaitLines(60_000));
    }

    @Test
    void aLineQueuedByAnotherThreadWakesTheWaitingNode() throws Exception {
        LogQueue q = attached();
        CompletableFuture<Long> wokeAfter = new CompletableFuture<>();
        Thread node = new Thread(() -> {
            long t0 = System.nanoTime();
            q.awaitLines(60_000);
            wokeAfter.complete(System.nanoTime() - t0);
        });
        node.start();
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
        while (node.getState() != Thread.State.TIMED_WAITING && System.nanoTime() < deadline)
            Thread.onSpinWait();
        q.add(800, "bob", "x");
        assertTrue(wokeAfter.get(10, TimeUnit.SECONDS) < TimeUnit.SECONDS.toNanos(10));
    }
}
