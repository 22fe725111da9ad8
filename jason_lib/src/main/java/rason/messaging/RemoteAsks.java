package rason.messaging;

import java.util.ArrayList;
import java.util.Collection;
import java.util.HashSet;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.function.Predicate;

/**
 * One agent's synchronous asks (.send with askOne/askAll and an answer
 * variable) to agents of other processes, so that each one ends: Jason ends
 * the answered ones and those with its own timeout; this table ends those
 * whose receiver left, that waited longer than the ask timeout, or that the
 * stopping node leaves unanswered. Thread-safe: presence changes arrive on ROS
 * threads, the agent's thread tracks and settles.
 */
public final class RemoteAsks {

    /** Why an ask ends without answer: Jason error atom, a text, and the departed agent (or null). */
    public record Failure(String msgId, String error, String text, String departed) {
    }

    public static final String RECEIVER_DEPARTED = "receiver_departed";
    public static final String ASK_TIMEOUT = "ask_timeout";

    private static final class Ask {
        final Set<String> receivers = new HashSet<>();
        long startedNanos; // ROS time, 0 while unknown
        final long timeoutNanos; // 0: Jason's own timeout, or none

        Ask(long startedNanos, long timeoutNanos) {
            this.startedNanos = startedNanos;
            this.timeoutNanos = timeoutNanos;
        }
    }

    private final Map<String, Ask> asks = new LinkedHashMap<>(); // by message id
    private final Set<String> lost = new HashSet<>();

    /**
     * Tracks an ask sent to receiver.
     *
     * @param timeoutNanos how long it may wait for an answer; 0 or less: as long as the receiver is there
     */
    public synchronized void track(String msgId, String receiver, long nowNanos, long timeoutNanos) {
        asks.computeIfAbsent(msgId, id -> new Ask(nowNanos, Math.max(0, timeoutNanos))).receivers.add(receiver);
    }

    /** The send failed after all: the ask is not waiting. */
    public synchronized void forget(String msgId) {
        asks.remove(msgId);
    }

    /**
     * Some agents of other processes left or restarted: asks to them will never be answered.
     *
     * @return true if an ask waits for one of them (the agent should run a cycle)
     */
    public synchronized boolean receiversLost(Collection<String> names) {
        if (asks.isEmpty())
            return false;
        lost.addAll(names);
        return true;
    }

    /** Whether an ask's time is up at nowNanos (the agent should run a cycle). */
    public synchronized boolean due(long nowNanos) {
        for (Ask a : asks.values())
            if (expired(a, nowNanos))
                return true;
        return false;
    }

    public synchronized boolean hasLost() {
        return !lost.isEmpty();
    }

    /**
     * On the agent's thread: forgets asks that no longer wait (answered, or
     * ended by Jason's own timeout) and returns those to fail.
     *
     * @param waiting whether Jason still has the intention of a message id suspended
     * @param stopping non-null when the node stops: every waiting ask fails with it
     */
    public synchronized List<Failure> settle(Predicate<String> waiting, long nowNanos, String stopping) {
        List<Failure> out = new ArrayList<>();
        Set<String> gone = new HashSet<>(lost);
        lost.clear();
        for (Iterator<Map.Entry<String, Ask>> it = asks.entrySet().iterator(); it.hasNext();) {
            Map.Entry<String, Ask> e = it.next();
            String id = e.getKey();
            Ask ask = e.getValue();
            if (!waiting.test(id)) {
                it.remove();
                continue;
            }
            String departed = null;
            for (String r : ask.receivers)
                if (gone.contains(r))
                    departed = r;
            if (stopping != null) {
                it.remove();
                out.add(new Failure(id, stopping, "the bridge is stopping", null));
            } else if (departed != null) {
                it.remove();
                out.add(new Failure(id, RECEIVER_DEPARTED, departed + " left before answering", departed));
            } else if (expired(ask, nowNanos)) {
                it.remove();
                out.add(new Failure(id, ASK_TIMEOUT, "no answer from " + ask.receivers + " within the ask timeout", null));
            }
        }
        return out;
    }

    public synchronized boolean isEmpty() {
        return asks.isEmpty();
    }

    private static boolean expired(Ask a, long nowNanos) {
        if (a.timeoutNanos <= 0 || nowNanos <= 0)
            return false;
        if (a.startedNanos <= 0) { // the clock was unknown when it was sent
            a.startedNanos = nowNanos;
            return false;
        }
        return nowNanos - a.startedNanos > a.timeoutNanos;
    }
}
