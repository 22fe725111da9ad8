package rason.messaging;

import java.util.ArrayList;
import java.util.Collection;
import java.util.HashMap;
import java.util.HashSet;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.function.Predicate;

/**
 * One agent's {@code .send}s to agents of other processes whose intention waits for
 * the receipts: each receiving process confirms that the message reached its agent's
 * mailbox (or that its trust policy refused it). A send ends when every receiver
 * confirmed, or fails when one refused, left, or did not confirm within the message
 * TTL, or when the node stops: a remote message is delivered or its send fails,
 * never lost silently. Thread-safe: receipts and departures arrive on channel
 * threads, the agent's thread expects and settles.
 */
public final class SentReceipts {

    /** How a send ends: resumed (error null), or failed with a Jason error atom, a text and the departed agent (or null). */
    public record Outcome(String msgId, String error, String text, String departed) {
        public boolean delivered() {
            return error == null;
        }
    }

    /** No receipt within the message TTL. */
    public static final String UNDELIVERED = "undelivered";
    /** The receiver's trust policy refused the message. */
    public static final String REFUSED = "refused";

    private static final class Send {
        final Map<String, String> waitingFor = new HashMap<>(); // receiver -> its process
        final long sentNanos;
        String refusedBy;

        Send(long sentNanos) {
            this.sentNanos = sentNanos;
        }
    }

    private final Map<String, Send> sends = new LinkedHashMap<>(); // by message id
    private final Set<String> lost = new HashSet<>();
    private boolean changed;

    /** The message msgId went to receiver of process receiverMas at nowNanos (wall clock). */
    public synchronized void expect(String msgId, String receiver, String receiverMas, long nowNanos) {
        sends.computeIfAbsent(msgId, id -> new Send(nowNanos)).waitingFor.put(receiver, receiverMas);
    }

    /** The send failed at once after all: nothing waits for its receipts. */
    public synchronized void forget(String msgId) {
        sends.remove(msgId);
    }

    /**
     * A receipt: receiver of process fromMas took msgId into its mailbox (refused: its
     * trust policy turned it away). A receipt from any other process is ignored.
     *
     * @return true if a send waited for it (the agent should run a cycle)
     */
    public synchronized boolean arrived(String msgId, String receiver, String fromMas, boolean refused) {
        Send s = sends.get(msgId);
        if (s == null || !fromMas.equals(s.waitingFor.get(receiver)))
            return false;
        s.waitingFor.remove(receiver);
        if (refused && s.refusedBy == null)
            s.refusedBy = receiver;
        changed = true;
        return true;
    }

    /**
     * Agents of other processes left or restarted: their receipts will never come.
     *
     * @return true if a send waits for one of them
     */
    public synchronized boolean receiversLost(Collection<String> names) {
        if (sends.isEmpty())
            return false;
        lost.addAll(names);
        changed = true;
        return true;
    }

    /** Whether a send waited longer than ttlNanos at nowNanos: the oldest, as sends are kept in the order made. */
    public synchronized boolean due(long nowNanos, long ttlNanos) {
        Iterator<Send> oldest = sends.values().iterator();
        return oldest.hasNext() && nowNanos - oldest.next().sentNanos > ttlNanos;
    }

    /** Whether {@link #settle} has something to end. */
    public synchronized boolean hasNews() {
        return changed;
    }

    public synchronized boolean isEmpty() {
        return sends.isEmpty();
    }

    /**
     * On the agent's thread: the sends that end now, in the order they were made. A send whose
     * intention was dropped meanwhile ends silently, when its receipts come or its TTL passes:
     * asking Jason about every send still waiting would cost each settle as much as there are
     * sends in flight.
     *
     * @param waiting whether Jason still has the intention of a message id suspended
     * @param stopping non-null when the node stops: every waiting send fails with it
     */
    public synchronized List<Outcome> settle(Predicate<String> waiting, long nowNanos, long ttlNanos, String stopping) {
        List<Outcome> out = new ArrayList<>();
        Set<String> gone = new HashSet<>(lost);
        lost.clear();
        changed = false;
        for (Iterator<Map.Entry<String, Send>> it = sends.entrySet().iterator(); it.hasNext();) {
            Map.Entry<String, Send> e = it.next();
            String id = e.getKey();
            Send s = e.getValue();
            Outcome o = outcome(id, s, gone, nowNanos, ttlNanos, stopping);
            if (o == null)
                continue;
            it.remove();
            if (waiting.test(id))
                out.add(o);
        }
        return out;
    }

    private static Outcome outcome(String id, Send s, Set<String> gone, long nowNanos, long ttlNanos, String stopping) {
        if (s.refusedBy != null)
            return new Outcome(id, REFUSED, s.refusedBy + " refused it (its trust policy)", null);
        if (s.waitingFor.isEmpty())
            return new Outcome(id, null, "delivered", null);
        if (stopping != null)
            return new Outcome(id, stopping, "the bridge is stopping before " + s.waitingFor.keySet() + " confirmed it", null);
        for (String r : s.waitingFor.keySet())
            if (gone.contains(r))
                return new Outcome(id, RemoteAsks.RECEIVER_DEPARTED, r + " left before confirming it", r);
        if (nowNanos - s.sentNanos > ttlNanos)
            return new Outcome(id, UNDELIVERED, "no receipt from " + s.waitingFor.keySet() + " within the message TTL ("
                    + ttlNanos / 1_000_000_000L + " s)", null);
        return null;
    }
}
