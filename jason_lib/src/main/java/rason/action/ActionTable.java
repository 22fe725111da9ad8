package rason.action;

import java.util.ArrayList;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.IntSupplier;
import java.util.function.Predicate;

/**
 * The actions one agent has in flight (thesis §5.2): each gets an id, waits
 * for its feedback, and is settled exactly once — by its feedback, the
 * timeout, the decomposer that took it going away, or {@link #failAll}. An
 * action the agent takes back ({@link #cancel}) leaves the table unsettled
 * (Jason has already stopped waiting for it); one whose intention is suspended
 * is {@link #hold held} until the intention is resumed or dropped. ROS threads
 * report feedback and ticks; the agent's thread starts, cancels and takes the
 * settled ones, so Jason's state is only touched there. Generic in the action
 * object so it needs no Jason.
 *
 * @param <A> what the agent waits on (Jason's ActionExec)
 */
public final class ActionTable<A> {

    /** An action that ended, with OK or its failure reason. */
    public record Settled<A>(A action, int id, String result) {
    }

    /** An action the robot must stop (a cancel goes out for it). */
    /** A pending action as it stands: since when (ROS time) and whether it is held. */
    public record Running<A>(A action, int id, long startedNanos, boolean held) {
    }

    public record Taken<A>(A action, int id) {
    }

    /** What a feedback did. */
    public enum FeedbackOutcome {
        /** it settled a pending action */
        SETTLED,
        /** the action was taken back or held: the decomposer's answer to the cancel, or a late one */
        AFTER_CANCEL,
        /** no such action */
        UNKNOWN
    }

    /** Ids of taken-back actions remembered, so their late feedback is told from a wrong id. */
    static final int RECENT_CANCELS = 1000;

    private static final class Pending<A> {
        final A action;
        long startedNanos; // ROS time; 0 while the clock is not known yet
        String decomposer = null; // the node that said it took the action, if any
        long decomposerMissingSinceNanos = 0; // wall clock; 0 while it is connected
        boolean held = false; // stopped because its intention is suspended

        Pending(A action, long startedNanos) {
            this.action = action;
            this.startedNanos = startedNanos;
        }
    }

    private final IntSupplier ids;
    private final Map<Integer, Pending<A>> pending = new LinkedHashMap<>();
    private final List<Settled<A>> settled = new ArrayList<>();
    private final Map<Integer, Boolean> recentCancels = new LinkedHashMap<>() {
        @Override
        protected boolean removeEldestEntry(Map.Entry<Integer, Boolean> eldest) {
            return size() > RECENT_CANCELS;
        }
    };

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

    /** The feedback for id: settles it with result, unless it was taken back or is held. */
    public synchronized FeedbackOutcome feedback(int id, String result) {
        Pending<A> p = pending.get(id);
        if (p == null)
            return recentCancels.containsKey(id) ? FeedbackOutcome.AFTER_CANCEL : FeedbackOutcome.UNKNOWN;
        if (p.held)
            return FeedbackOutcome.AFTER_CANCEL; // the answer to the cancel sent when it was held
        pending.remove(id);
        settled.add(new Settled<>(p.action, id, result));
        return FeedbackOutcome.SETTLED;
    }

    /**
     * Takes back the pending actions the agent no longer waits for: they leave
     * the table unsettled, and their late feedback is recognised.
     *
     * @return the actions taken back, for their cancels
     */
    public synchronized List<Taken<A>> cancel(Predicate<A> which) {
        List<Taken<A>> out = new ArrayList<>();
        for (Iterator<Map.Entry<Integer, Pending<A>>> it = pending.entrySet().iterator(); it.hasNext();) {
            Map.Entry<Integer, Pending<A>> e = it.next();
            if (which.test(e.getValue().action)) {
                it.remove();
                recentCancels.put(e.getKey(), Boolean.TRUE);
                if (!e.getValue().held) // a held one was cancelled when it was held
                    out.add(new Taken<>(e.getValue().action, e.getKey()));
            }
        }
        return out;
    }

    /**
     * Stops the pending actions whose intention was suspended: they stay in the
     * table, without timeout, until {@link #release} or {@link #cancel}.
     *
     * @return the actions newly held, for their cancels
     */
    public synchronized List<Taken<A>> hold(Predicate<A> which) {
        List<Taken<A>> out = new ArrayList<>();
        for (Map.Entry<Integer, Pending<A>> e : pending.entrySet())
            if (!e.getValue().held && which.test(e.getValue().action)) {
                e.getValue().held = true;
                out.add(new Taken<>(e.getValue().action, e.getKey()));
            }
        return out;
    }

    /**
     * Settles the held actions of a resumed intention with reason (the robot stopped them).
     *
     * @return true if any was settled
     */
    public synchronized boolean release(Predicate<A> which, String reason) {
        boolean any = false;
        for (Iterator<Map.Entry<Integer, Pending<A>>> it = pending.entrySet().iterator(); it.hasNext();) {
            Map.Entry<Integer, Pending<A>> e = it.next();
            if (e.getValue().held && which.test(e.getValue().action)) {
                it.remove();
                settled.add(new Settled<>(e.getValue().action, e.getKey(), reason));
                any = true;
            }
        }
        return any;
    }

    /**
     * Records which node took action id (it said so with an action_started event).
     *
     * @return false if no such action is pending
     */
    public synchronized boolean startedBy(int id, String decomposer) {
        Pending<A> p = pending.get(id);
        if (p == null)
            return false;
        p.decomposer = decomposer;
        p.decomposerMissingSinceNanos = 0;
        return true;
    }

    /**
     * Settles with reason the actions whose decomposer has not been connected
     * for longer than graceNanos (wall clock): it died or was cut off.
     *
     * @param connected the nodes publishing on jason/event that are connected now
     * @return the actions settled, for their cancels (a decomposer that comes back must not go on)
     */
    public synchronized List<Taken<A>> decomposersLost(java.util.Set<String> connected, long nowNanos, long graceNanos,
            String reason) {
        List<Taken<A>> out = new ArrayList<>();
        for (Iterator<Map.Entry<Integer, Pending<A>>> it = pending.entrySet().iterator(); it.hasNext();) {
            Map.Entry<Integer, Pending<A>> e = it.next();
            Pending<A> p = e.getValue();
            if (p.decomposer == null || p.held)
                continue;
            if (connected.contains(p.decomposer)) {
                p.decomposerMissingSinceNanos = 0;
            } else if (p.decomposerMissingSinceNanos == 0) {
                p.decomposerMissingSinceNanos = nowNanos;
            } else if (nowNanos - p.decomposerMissingSinceNanos > graceNanos) {
                it.remove();
                recentCancels.put(e.getKey(), Boolean.TRUE);
                settled.add(new Settled<>(p.action, e.getKey(), reason));
                out.add(new Taken<>(p.action, e.getKey()));
            }
        }
        return out;
    }

    /**
     * Settles with reason every action pending for longer than timeoutNanos (held ones wait for the agent).
     *
     * @param timeoutNanos 0 or less: no timeout
     * @return the actions settled, for their cancels
     */
    public synchronized List<Taken<A>> expire(long nowNanos, long timeoutNanos, String reason) {
        if (timeoutNanos <= 0 || nowNanos <= 0)
            return List.of();
        List<Taken<A>> out = new ArrayList<>();
        for (Iterator<Map.Entry<Integer, Pending<A>>> it = pending.entrySet().iterator(); it.hasNext();) {
            Map.Entry<Integer, Pending<A>> e = it.next();
            Pending<A> p = e.getValue();
            if (p.held)
                continue;
            if (p.startedNanos <= 0)
                p.startedNanos = nowNanos;
            else if (nowNanos - p.startedNanos > timeoutNanos) {
                it.remove();
                recentCancels.put(e.getKey(), Boolean.TRUE);
                settled.add(new Settled<>(p.action, e.getKey(), reason));
                out.add(new Taken<>(p.action, e.getKey()));
            }
        }
        return out;
    }

    /**
     * Settles every pending action with reason (the node is stopping).
     *
     * @return the actions the robot may still be doing, for their cancels
     */
    public synchronized List<Taken<A>> failAll(String reason) {
        List<Taken<A>> out = new ArrayList<>();
        for (Map.Entry<Integer, Pending<A>> e : pending.entrySet()) {
            settled.add(new Settled<>(e.getValue().action, e.getKey(), reason));
            recentCancels.put(e.getKey(), Boolean.TRUE);
            if (!e.getValue().held)
                out.add(new Taken<>(e.getValue().action, e.getKey()));
        }
        pending.clear();
        return out;
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

    /** The actions still waiting for their feedback, oldest first (held ones included). */
    public synchronized List<Running<A>> pending() {
        List<Running<A>> out = new ArrayList<>(pending.size());
        for (Map.Entry<Integer, Pending<A>> e : pending.entrySet())
            out.add(new Running<>(e.getValue().action, e.getKey(), e.getValue().startedNanos, e.getValue().held));
        return out;
    }

    /** Actions still waiting for their feedback (held ones included). */
    public synchronized int pendingCount() {
        return pending.size();
    }
}
