package rason.core;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.locks.LockSupport;

/**
 * Log lines of the agents and of Jason on their way to rosout. An agent's thread only
 * queues a line; the node takes them with {@link #drain} on a thread of its own, so an
 * agent that prints in every cycle never waits for Python. While no node is attached,
 * lines go to stderr instead.
 */
public final class LogQueue {

    /** One queued line: a java.util.logging level value, the agent ("" if none) and the text. */
    public record Line(int level, String agent, String message) {
    }

    /**
     * Lines taken at once, in one object so that the node crosses from Python to Java once
     * per batch, not three times per line. Line i is the text from ends[i-1] to ends[i] (from 0
     * for the first), counted in code points as Python indexes strings; it reads "[agent]
     * message" (the message alone if no agent), at java.util.logging level {@code levels[i]}.
     */
    public record Batch(int[] levels, int[] ends, String text) {
    }

    /** Lines kept while nobody drains; beyond this, the oldest are dropped (and counted). */
    public static final int MAX_QUEUED = 100_000;

    private final ConcurrentLinkedQueue<Line> queue = new ConcurrentLinkedQueue<>();
    private final AtomicInteger queued = new AtomicInteger();
    private final AtomicInteger dropped = new AtomicInteger();
    private volatile boolean attached = false;
    /** The node's thread while it waits in {@link #awaitLines}, else null. */
    private volatile Thread waiter;

    /** Queues a line for the node, or writes it to stderr when no node takes lines. */
    public void add(int level, String agent, String message) {
        if (!attached) {
            System.err.println((agent.isEmpty() ? "" : "[" + agent + "] ") + message);
            return;
        }
        queue.add(new Line(level, agent, message));
        if (queued.incrementAndGet() > MAX_QUEUED && queue.poll() != null) {
            queued.decrementAndGet();
            dropped.incrementAndGet();
        }
        Thread w = waiter;
        if (w != null)
            LockSupport.unpark(w); // never blocks the agent's thread
    }

    /**
     * Waits until a line is queued or {@code millis} have passed, so that the node's thread
     * sleeps while nobody prints instead of looking every few milliseconds. One thread at a
     * time (the node's).
     *
     * @return whether lines are queued
     */
    public boolean awaitLines(long millis) {
        long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(millis);
        waiter = Thread.currentThread();
        try {
            long left;
            while (queue.isEmpty() && (left = deadline - System.nanoTime()) > 0 && !Thread.interrupted())
                LockSupport.parkNanos(this, left);
        } finally {
            waiter = null;
        }
        return !queue.isEmpty();
    }

    /** A node takes the lines from now on (true), or none does (false). */
    public void setAttached(boolean on) {
        attached = on;
    }

    public boolean isAttached() {
        return attached;
    }

    /** Takes up to max queued lines, oldest first (empty if none). */
    public Line[] drain(int max) {
        List<Line> out = new ArrayList<>();
        Line l;
        while (out.size() < max && (l = queue.poll()) != null) {
            queued.decrementAndGet();
            out.add(l);
        }
        return out.toArray(new Line[0]);
    }

    /** Takes up to max queued lines, oldest first, as one {@link Batch} (no lines: empty arrays). */
    public Batch drainBatch(int max) {
        Line[] lines = drain(max);
        int[] levels = new int[lines.length];
        int[] ends = new int[lines.length];
        StringBuilder text = new StringBuilder();
        for (int i = 0; i < lines.length; i++) {
            Line l = lines[i];
            int from = text.length();
            if (!l.agent().isEmpty())
                text.append('[').append(l.agent()).append("] ");
            text.append(l.message());
            levels[i] = l.level();
            ends[i] = (i == 0 ? 0 : ends[i - 1]) + text.codePointCount(from, text.length());
        }
        return new Batch(levels, ends, text.toString());
    }

    /** Lines dropped because nobody drained them in time, since the last call. */
    public int takeDropped() {
        return dropped.getAndSet(0);
    }
}
