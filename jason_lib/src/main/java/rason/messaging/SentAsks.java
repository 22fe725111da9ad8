package rason.messaging;

import java.util.LinkedHashMap;
import java.util.Map;

/**
 * The asks (askOne, askAll, askHow) one agent sent to other processes, by
 * message id, so that their answers pass the trust policy: the answer to an
 * askHow is a tellHow, which an agent refuses by default from other robots,
 * but not from the one it asked. An answer counts only if it comes from the
 * agent that was asked (anyone, for a broadcast ask). Bounded: the oldest asks
 * are forgotten first. Thread-safe: the agent's thread records, ROS threads
 * check.
 */
public final class SentAsks {

    public static final int DEFAULT_CAPACITY = 1024;
    private static final String ANYONE = "";

    private final Map<String, String> receiverById;

    public SentAsks() {
        this(DEFAULT_CAPACITY);
    }

    public SentAsks(int capacity) {
        receiverById = new LinkedHashMap<>(16, 0.75f, false) {
            @Override
            protected boolean removeEldestEntry(Map.Entry<String, String> eldest) {
                return size() > capacity;
            }
        };
    }

    /** An ask went to receiver ("" or null: a broadcast). */
    public synchronized void sent(String msgId, String receiver) {
        if (msgId != null && !msgId.isEmpty())
            receiverById.put(msgId, receiver == null ? ANYONE : receiver);
    }

    /**
     * Whether a message from sender replying to inReplyTo answers one of our
     * asks; the ask is then done, unless it was a broadcast (many answer it).
     */
    public synchronized boolean answeredBy(String inReplyTo, String sender) {
        if (inReplyTo == null || inReplyTo.isEmpty())
            return false;
        String asked = receiverById.get(inReplyTo);
        if (asked == null)
            return false;
        if (asked.equals(ANYONE))
            return true;
        if (!asked.equals(sender))
            return false;
        receiverById.remove(inReplyTo);
        return true;
    }

    public synchronized int size() {
        return receiverById.size();
    }
}
