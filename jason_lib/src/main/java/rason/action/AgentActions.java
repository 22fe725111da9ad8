package rason.action;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.function.IntSupplier;
import java.util.logging.Level;

import jason.asSemantics.ActionExec;
import jason.asSemantics.CircumstanceListener;
import jason.asSemantics.Intention;
import jason.asSyntax.Structure;
import jason.asSyntax.Term;
import jason.asSyntax.Trigger;
import rason.core.Protocol;
import rason.mind.AgentMind;

/**
 * One agent's actions from {@code act()} to the robot and back: each is
 * registered in an {@link ActionTable} and handed to the {@link ActionSink}; its
 * feedback, timeout, the loss of its decomposer or the node stopping settles
 * it; and whenever the agent stops waiting for it for another reason (Jason's
 * take-back constructs, seen through {@link #listener()} and Jason's own
 * pending actions) a cancel follows it to the robot. Never calls Python.
 */
public final class AgentActions {

    private final ActionTable<ActionExec> table;
    private final ActionSink sink;
    private final String agent;
    private final Runnable wake;
    private final ActionPort port;

    /**
     * @param ids  action ids, unique in the process
     * @param wake wakes the agent so it settles what ended in its next cycle
     * @param port where the agent's log lines go
     */
    AgentActions(IntSupplier ids, ActionSink sink, String agent, Runnable wake, ActionPort port) {
        this.table = new ActionTable<>(ids);
        this.sink = sink;
        this.agent = agent;
        this.wake = wake;
        this.port = port;
    }

    /** Registers the action and queues it for the node (agent's thread). */
    public void start(ActionExec action, long nowNanos) {
        Structure term = action.getActionTerm();
        int id = table.start(action, nowNanos); // before queueing: feedback may come back at once
        if (!sink.action(agent, id, term.getFunctor(), ActionText.parametersOf(term)) && table.feedback(id, Protocol.BRIDGE_ERROR) == ActionTable.FeedbackOutcome.SETTLED) {
            log(Level.SEVERE, "could not publish " + term + ": the bridge is not running");
            wake.run();
        }
    }

    /**
     * Feedback for one of the agent's actions (from a ROS thread).
     *
     * @return false if no action with that id is pending (logged)
     */
    public boolean feedback(int actionId, String result) {
        switch (table.feedback(actionId, result)) {
        case SETTLED:
            wake.run();
            return true;
        case AFTER_CANCEL:
            log(Level.FINE, "feedback '" + result + "' for action id " + actionId + " after it was taken back: ignored");
            return false;
        default:
            port.ignoredFeedback(agent, result, actionId);
            return false;
        }
    }

    /** A decomposer said it took action actionId (from a ROS thread): its link is watched from now on. */
    public boolean startedBy(int actionId, String decomposer) {
        return table.startedBy(actionId, decomposer);
    }

    /** Periodic: fails the actions whose decomposer went away, and stops them should it come back. */
    public void decomposersTick(Set<String> connected, long nowNanos, long graceNanos) {
        List<ActionTable.Taken<ActionExec>> lost = table.decomposersLost(connected, nowNanos, graceNanos,
                Protocol.DECOMPOSER_LOST);
        if (!lost.isEmpty()) {
            log(Level.WARNING, describe(lost) + " failed " + Protocol.DECOMPOSER_LOST + ": the node that took it went away");
            cancel(lost, Protocol.DECOMPOSER_LOST);
            wake.run();
        }
    }

    /** Periodic, with the ROS time: actions older than the timeout fail, are cancelled, and the agent wakes. */
    void expire(long nowNanos, long timeoutNanos) {
        List<ActionTable.Taken<ActionExec>> late = table.expire(nowNanos, timeoutNanos, Protocol.TIMEOUT);
        cancel(late, Protocol.TIMEOUT);
        if (!late.isEmpty())
            wake.run();
    }

    /** The node stops: pending actions fail with reason and the robot is told to stop them. */
    void failAll(String reason) {
        cancel(table.failAll(reason), reason);
        wake.run();
    }

    /** The actions that ended since the last call (agent's thread). */
    public List<ActionTable.Settled<ActionExec>> takeSettled() {
        return table.takeSettled();
    }

    public boolean hasSettled() {
        return table.hasSettled();
    }

    public int pendingCount() {
        return table.pendingCount();
    }

    /** The pending actions as {@code jason/mind} shows them, oldest first. */
    public List<AgentMind.ActionView> pendingView() {
        List<AgentMind.ActionView> out = new ArrayList<>();
        for (ActionTable.Running<ActionExec> r : table.pending())
            out.add(new AgentMind.ActionView(r.id(), r.action().getActionTerm().toString(), r.startedNanos(), r.held()));
        return out;
    }

    /**
     * Jason's pending actions are the truth: one of ours Jason no longer waits
     * for was taken back by a construct no listener reports (.succeed_goal of
     * an intention's last goal removes the pending action and nothing else).
     * Called on the agent's thread at the start of a cycle and before it sleeps.
     */
    public void takeBackOrphans(Map<Integer, ActionExec> jasonPending) {
        if (table.pendingCount() == 0)
            return;
        List<ActionTable.Taken<ActionExec>> taken = table.cancel(a -> jasonPending.get(a.getIntention().getId()) != a);
        if (!taken.isEmpty()) {
            log(Level.FINE, "took back " + describe(taken) + ": no longer pending in Jason");
            cancel(taken, Protocol.DROPPED);
        }
    }

    /** Jason's hooks for an agent that changes its mind; add it to the agent's circumstance. */
    public CircumstanceListener listener() {
        return new TakeBack();
    }

    /**
     * Called by Jason on the agent's thread: whenever an intention stops
     * waiting for its action for another reason than the action's feedback,
     * the robot is told to stop that action.
     */
    private final class TakeBack implements CircumstanceListener {

        private static final long serialVersionUID = 1L;

        /** .drop_intention, .drop_desire, .drop_all_intentions/desires: the intention is gone. */
        @Override
        public void intentionDropped(Intention i) {
            takeBack(i, Protocol.DROPPED);
        }

        /** .succeed_goal and .fail_goal take an intention out of its action and resume it. */
        @Override
        public void intentionExecuting(Intention i, Term reason) {
            takeBack(i, Protocol.DROPPED);
        }

        /** .suspend: the robot stops; the action stays pending until .resume, which sees it fail 'suspended'. */
        @Override
        public void intentionSuspended(Trigger t, Intention i, Term reason) {
            cancel(table.hold(a -> a.getIntention().getId() == i.getId()), Protocol.SUSPENDED);
        }

        @Override
        public void intentionResumed(Intention i, Term reason) {
            if (table.release(a -> a.getIntention().getId() == i.getId(), Protocol.SUSPENDED))
                wake.run();
        }

        private void takeBack(Intention i, String reason) {
            List<ActionTable.Taken<ActionExec>> taken = table.cancel(a -> a.getIntention().getId() == i.getId());
            if (!taken.isEmpty()) {
                log(Level.FINE, "took back " + describe(taken) + ": " + reason);
                cancel(taken, reason);
            }
        }
    }

    /** Tells the robot to stop these actions (a cancel follows each on jason/action). */
    private void cancel(List<ActionTable.Taken<ActionExec>> taken, String reason) {
        for (ActionTable.Taken<ActionExec> t : taken)
            sink.cancel(agent, t.id(), reason);
    }

    private static String describe(List<ActionTable.Taken<ActionExec>> taken) {
        List<String> out = new ArrayList<>();
        for (ActionTable.Taken<ActionExec> t : taken)
            out.add(t.action().getActionTerm() + " (id " + t.id() + ")");
        return String.join(", ", out);
    }

    private void log(Level level, String text) {
        port.log(level, agent, text);
    }
}
