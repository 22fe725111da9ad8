package rason.action;

import java.util.ArrayList;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.IntSupplier;

/**
 * The actions one agent has in flight (thesis §5.2): each gets an id, waits
 * for its feedback, and is settled exactly once, by its feedback, by the
 * timeout or by {@link #failAll}. ROS threads report feedback and ticks; the
 * agent's thread starts actions and takes the settled ones, so Jason's state
 * is only touched there. Generic in the action object so it needs no Jason.
 *
 * @param <A> what the agent waits on (Jason's ActionExec)
 */
public final class ActionTable<A> {

    /** An action that ended, with OK or its failure reason. */
    public record Settled<A>(A action, int id, String result) {
    }

    private static final class Pending<A> {
        final A action;
        long startedNanos; // ROS time; 0 while the clock is not known yet

        Pending(A action, long startedNanos) {
            this.action = action;
            this.startedNanos = startedNanos;
        }
    }

    private final IntSupplier ids;
    private final Map<Integer, Pending<A>> pending = new LinkedHashMap<>();
    private final List<Settled<A>> settled = new ArrayList<>();

    /** @param ids source of action ids, unique in the process */
    public ActionTable(IntSupplier ids) {
        this.ids = ids;
    }

    /**
     * Registers an action before it is published, so its feedback can come back at once.
     *
     * @param nowNanos ROS time, 0 if unknown (the timeout then counts from the first known time)
     * @return its id
     */
    public synchronized int start(A action, long nowNanos) {
        int id = ids.getAsInt();
        pending.put(id, new Pending<>(action, nowNanos));
        return id;
    }

    /**
     * The feedback for id: settles it with result.
     *
     * @return false if no action with that id is pending (unknown, or already settled)
     */
    public synchronized boolean feedback(int id, String result) {
        Pending<A> p = pending.remove(id);
        if (p == null)
            return false;
        settled.add(new Settled<>(p.action, id, result));
        return true;
    }

    /**
     * Settles with reason every action pending for longer than timeoutNanos.
     *
     * @param timeoutNanos 0 or less: no timeout
     * @return true if any was settled
     */
    public synchronized boolean expire(long nowNanos, long timeoutNanos, String reason) {
        if (timeoutNanos <= 0 || nowNanos <= 0)
            return false;
        boolean any = false;
        for (Iterator<Map.Entry<Integer, Pending<A>>> it = pending.entrySet().iterator(); it.hasNext();) {
            Map.Entry<Integer, Pending<A>> e = it.next();
            Pending<A> p = e.getValue();
            if (p.startedNanos <= 0)
                p.startedNanos = nowNanos;
            else if (nowNanos - p.startedNanos > timeoutNanos) {
                it.remove();
                settled.add(new Settled<>(p.action, e.getKey(), reason));
                any = true;
            }
        }
        return any;
    }

    /**
     * Settles every pending action with reason (the node is stopping).
     *
     * @return how many
     */
    public synchronized int failAll(String reason) {
        int n = pending.size();
        for (Map.Entry<Integer, Pending<A>> e : pending.entrySet())
            settled.add(new Settled<>(e.getValue().action, e.getKey(), reason));
        pending.clear();
        return n;
    }

    /** The actions settled since the last call, in the order they ended (agent's thread). */
    public synchronized List<Settled<A>> takeSettled() {
        if (settled.isEmpty())
            return List.of();
        List<Settled<A>> out = new ArrayList<>(settled);
        settled.clear();
        return out;
    }

    public synchronized boolean hasSettled() {
        return !settled.isEmpty();
    }

    /** Actions still waiting for their feedback. */
    public synchronized int pendingCount() {
        return pending.size();
    }
}
