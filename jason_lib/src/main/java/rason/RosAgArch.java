package rason;

import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import java.util.Map;
import java.util.Queue;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.logging.Level;

import jason.architecture.AgArch;
import jason.asSemantics.ActionExec;
import jason.asSyntax.ASSyntax;
import jason.asSyntax.Literal;
import jason.asSyntax.NumberTerm;
import jason.asSyntax.StringTerm;
import jason.asSyntax.Structure;
import jason.asSyntax.Term;

/**
 * Agent architecture of thesis §5.2: actions go out on jason/action and the
 * intention waits for its action_feedback event; perceptions come from the
 * agent's {@link PerceptionManager}. ROS threads only enqueue and wake the
 * agent; everything that touches Jason's state runs on the agent's thread.
 */
public class RosAgArch extends AgArch {

    private static final class Pending {
        final ActionExec action;
        volatile long deadlineNanos = Long.MAX_VALUE; // set once the action is published
        volatile boolean expired = false;

        Pending(ActionExec action) {
            this.action = action;
        }
    }

    private record Feedback(int actionId, String result) {
    }

    private final RasonHub hub = RasonHub.get();
    private final Map<Integer, Pending> pending = new ConcurrentHashMap<>();
    private final Queue<Feedback> feedback = new ConcurrentLinkedQueue<>();
    private volatile PerceptionManager perception = new PerSourcePerception();
    // Set when ROS data arrives and cleared when a cycle starts, so an agent
    // woken just before it decides to sleep runs one more cycle instead.
    private volatile boolean newData = false;

    @Override
    public void init() throws Exception {
        super.init();
        hub.register(this);
    }

    @Override
    public void stop() {
        hub.unregister(this);
        super.stop();
    }

    public PerceptionManager getPerceptionManager() {
        return perception;
    }

    public void setPerceptionManager(PerceptionManager m) {
        perception = m;
        dataArrived();
    }

    // ---- actions ---------------------------------------------------------------------

    @Override
    public void act(ActionExec action) {
        String stopping = hub.shutdownReason();
        if (stopping != null) {
            complete(action, stopping);
            return;
        }
        Structure term = action.getActionTerm();
        int id = hub.nextActionId();
        Pending p = new Pending(action);
        pending.put(id, p); // before publishing: feedback may come back at once
        long stamp;
        try {
            stamp = hub.publishAction(getAgName(), id, term.getFunctor(), parametersOf(term));
        } catch (Exception e) {
            pending.remove(id);
            RasonHub.log(Level.SEVERE, "[" + getAgName() + "] could not publish " + term + ": " + e);
            complete(action, "bridge_error");
            return;
        }
        if (stamp == RosConnector.NO_DECOMPOSER) {
            if (pending.remove(id) != null)
                complete(action, "no_decomposer");
            return;
        }
        long timeout = hub.getActionTimeoutNanos();
        if (timeout > 0)
            p.deadlineNanos = stamp + timeout;
    }

    /**
     * Action parameters as text: numbers plainly ("-0.3", "1"), strings without
     * their quotes, other terms in Jason syntax.
     */
    public static String[] parametersOf(Structure term) {
        String[] out = new String[term.getArity()];
        for (int i = 0; i < out.length; i++) {
            Term t = term.getTerm(i);
            if (t.isString())
                out[i] = ((StringTerm) t).getString();
            else
                out[i] = t.isNumeric() && t.isGround() ? numberText((NumberTerm) t) : t.toString();
        }
        return out;
    }

    private static String numberText(NumberTerm n) {
        double v;
        try {
            v = n.solve();
        } catch (Exception e) {
            return n.toString();
        }
        if (v == Math.rint(v) && !Double.isInfinite(v) && Math.abs(v) < 1e15)
            return Long.toString((long) v);
        return Double.toString(v);
    }

    void feedback(int actionId, String result) {
        feedback.add(new Feedback(actionId, result));
        dataArrived();
    }

    void failPending(String reason) {
        for (Map.Entry<Integer, Pending> e : pending.entrySet())
            if (!e.getValue().expired) {
                e.getValue().expired = true;
                feedback.add(new Feedback(e.getKey(), reason));
            }
        dataArrived();
    }

    int pendingCount() {
        return pending.size();
    }

    void tick(long nowNanos, long timeoutNanos, long ttlNanos) {
        boolean wake = perception.expire(nowNanos, ttlNanos);
        for (Map.Entry<Integer, Pending> e : pending.entrySet()) {
            Pending p = e.getValue();
            if (!p.expired && nowNanos > p.deadlineNanos) {
                p.expired = true;
                feedback.add(new Feedback(e.getKey(), "timeout"));
                wake = true;
            }
        }
        if (wake)
            dataArrived();
    }

    @Override
    public void reasoningCycleStarting() {
        newData = false;
        Feedback f;
        while ((f = feedback.poll()) != null) {
            Pending p = pending.remove(f.actionId());
            if (p == null) {
                RasonHub.log(Level.INFO, "[" + getAgName() + "] ignored feedback '" + f.result()
                        + "' for action id " + f.actionId() + ": no such action pending");
                continue;
            }
            complete(p.action, f.result());
        }
        super.reasoningCycleStarting();
    }

    /** Ends an action: OK resumes the intention, anything else fails it with that reason. */
    private void complete(ActionExec action, String result) {
        if ("OK".equals(result)) {
            action.setResult(true);
        } else {
            action.setResult(false);
            action.setFailureReason(reasonLiteral(result), action.getActionTerm() + " failed: " + result);
        }
        actionExecuted(action);
    }

    /** The reason as it appears among the failure event's annotations. */
    public static Literal reasonLiteral(String result) {
        try {
            Literal l = Perceptions.parse(result);
            if (!l.hasAnnot())
                return l;
        } catch (IllegalArgumentException e) {
            // not a Jason literal: keep the text
        }
        return ASSyntax.createLiteral("failure_reason", ASSyntax.createString(result));
    }

    // ---- perception ------------------------------------------------------------------

    void perceptionUpdate(String source, List<Literal> literals, long nowNanos) {
        if (perception.update(source, literals, nowNanos))
            dataArrived();
    }

    @Override
    public Collection<Literal> perceive() {
        Collection<Literal> fromEnvironment = super.perceive();
        if (fromEnvironment == null)
            return perception.perceive();
        // A Jason environment is also configured: Jason needs the whole list every time.
        List<Literal> all = new ArrayList<>(fromEnvironment);
        perception.perceive(); // consume the change flag
        all.addAll(perception.current());
        return all;
    }

    @Override
    public boolean canSleep() {
        return !newData && feedback.isEmpty() && super.canSleep();
    }

    private void dataArrived() {
        newData = true;
        wakeUpSense();
    }
}
