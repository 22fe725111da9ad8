package rason.messaging.mqtt;

import java.util.LinkedHashMap;
import java.util.Map;
import java.util.concurrent.atomic.AtomicLong;

import rason.messaging.FleetAuth;

/**
 * Without fleet authentication, the channel drops a redelivered message itself: one whose
 * sequence is not above the last one accepted from its sender's run (with authentication on,
 * {@link FleetAuth#admit} does this). Remembers a bounded number of senders.
 */
final class SequenceGate {

    private final Map<String, long[]> last; // sender -> {incarnation, sequence}; guarded by itself
    private final AtomicLong dropped = new AtomicLong();

    SequenceGate(int maxSenders) {
        last = new LinkedHashMap<>(16, 0.75f, true) {
            @Override
            protected boolean removeEldestEntry(Map.Entry<String, long[]> eldest) {
                return size() > maxSenders;
            }
        };
    }

    /** Whether this message of senderMas came before (then it is counted as dropped); else it is remembered. */
    boolean seenBefore(String senderMas, FleetAuth.Signed s) {
        synchronized (last) {
            long[] l = last.get(senderMas);
            if (l != null && l[0] == s.incarnation() && Long.compareUnsigned(s.sequence(), l[1]) <= 0) {
                dropped.incrementAndGet();
                return true;
            }
            last.put(senderMas, new long[] { s.incarnation(), s.sequence() });
            return false;
        }
    }

    long dropped() {
        return dropped.get();
    }
}
