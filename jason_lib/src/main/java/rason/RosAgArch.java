package rason;

import rason.infra.RasonLocalMAS;
import rason.messaging.Messages;
import rason.perception.PerSourcePerception;
import rason.perception.PerceptionManager;
import rason.perception.PerceptionManagers;
import rason.perception.Perceptions;
import rason.perception.SelectivePerception;

import java.util.ArrayList;
import java.util.Collection;
import java.util.HashSet;
import java.util.Iterator;
import java.util.List;
import java.util.Map;
import java.util.Queue;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.logging.Level;

import jason.JasonException;
import jason.ReceiverNotFoundException;
import jason.architecture.AgArch;
import jason.asSemantics.ActionExec;
import jason.asSemantics.Intention;
import jason.asSemantics.Message;
import jason.asSemantics.TransitionSystem;
import jason.asSyntax.ASSyntax;
import jason.asSyntax.Atom;
import jason.asSyntax.ListTerm;
import jason.asSyntax.Literal;
import jason.asSyntax.NumberTerm;
import jason.asSyntax.StringTerm;
import jason.asSyntax.Structure;
import jason.asSyntax.Term;

/**
 * Agent architecture of thesis §5.2: actions go out on jason/action and the
 * intention waits for its action_feedback event; perceptions come from the
 * agent's {@link PerceptionManager}. Messages to agents of other rason_mas
 * processes go over ROS (thesis §5.6), and the agent perceives who is
 * reachable as present(Name). ROS threads only enqueue and wake the agent;
 * everything that touches Jason's state runs on the agent's thread.
 */
public class RosAgArch extends AgArch {

    /** A synchronous ask (.send with askOne/askAll and an answer variable) sent to remote agents. */
    private static final class RemoteAsk {
        final Set<String> receivers = ConcurrentHashMap.newKeySet();
        volatile long deadlineNanos = Long.MAX_VALUE; // ROS time; MAX: Jason's own timeout or none
    }

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
    private volatile PerceptionManager perception = new SelectivePerception(new PerSourcePerception(), null);
    // Set when ROS data arrives and cleared when a cycle starts, so an agent
    // woken just before it decides to sleep runs one more cycle instead.
    private volatile boolean newData = false;

    private final Map<String, RemoteAsk> remoteAsks = new ConcurrentHashMap<>(); // by message id
    private final Queue<String> lostReceivers = new ConcurrentLinkedQueue<>();
    private volatile String failAsksReason = null; // set at shutdown
    private volatile List<Literal> presence = List.of();
    private volatile boolean presenceChanged = false;

    @Override
    public void init() throws Exception {
        super.init();
        try {
            perception = PerceptionManagers.forAgent(getTS().getSettings(), hub.defaultPerceptionManager());
        } catch (IllegalArgumentException e) {
            // RasonLocalMAS checks the options before creating agents; this is for agents created later
            RasonHub.log(Level.SEVERE, "[" + getAgName() + "] " + e.getMessage() + "; using " + PerceptionManagers.PER_SOURCE);
        }
        if (!PerceptionManagers.PER_SOURCE.equals(perception.toString()))
            RasonHub.log(Level.INFO, "[" + getAgName() + "] perception: " + perception);
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

    /** Selective perception from now on (null: everything); see {@code rason.perceive_only}. */
    public void perceiveOnly(Set<String> selection) {
        PerceptionManager m = perception;
        if (m instanceof SelectivePerception sel) {
            sel.select(selection);
        } else {
            perception = new SelectivePerception(m, selection);
        }
        dataArrived();
    }

    /** The RosAgArch in an agent's architecture chain (other architectures may come before it). */
    public static RosAgArch of(TransitionSystem ts) {
        for (AgArch a = ts.getAgArch().getFirstAgArch(); a != null; a = a.getNextAgArch())
            if (a instanceof RosAgArch r)
                return r;
        return null;
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
        failAsksReason = reason;
        dataArrived();
    }

    int pendingCount() {
        return pending.size();
    }

    void tick(long nowNanos, long timeoutNanos, long ttlNanos) {
        boolean wake = perception.expire(nowNanos, ttlNanos);
        for (RemoteAsk a : remoteAsks.values())
            wake |= nowNanos > a.deadlineNanos;
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
        settleRemoteAsks();
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
        PerceptionManager m = perception;
        Collection<Literal> fromRos = m.perceive();
        boolean presenceNews = presenceChanged;
        presenceChanged = false;
        // null: nothing changed, and Jason skips its belief update
        if (fromEnvironment == null && fromRos == null && !presenceNews)
            return null;
        // otherwise Jason needs the whole list
        List<Literal> all = new ArrayList<>();
        if (fromEnvironment != null)
            all.addAll(fromEnvironment);
        all.addAll(fromRos != null ? fromRos : m.current());
        for (Literal l : presence)
            if (m.wants(l))
                all.add(l);
        return all;
    }

    /** The reachable agents changed: they become present(Name) percepts. */
    void presenceUpdate(List<String> names) {
        List<Literal> literals = new ArrayList<>(names.size());
        for (String n : names)
            literals.add(ASSyntax.createLiteral("present", new Atom(n)));
        presence = literals;
        presenceChanged = true;
        dataArrived();
    }

    @Override
    public boolean canSleep() {
        return !newData && feedback.isEmpty() && lostReceivers.isEmpty() && super.canSleep();
    }

    // ---- messages to agents of other processes ----------------------------------------

    /**
     * .send: a receiver hosted here (by its name, or by this robot's prefix and
     * its name) gets the message through Jason's own mailbox; a reachable
     * remote one over ROS; anyone else fails the intention with
     * error(receiver_not_found), as Jason does for an unknown local receiver.
     */
    @Override
    public void sendMsg(Message m) throws Exception {
        if (m.getSender() == null)
            m.setSender(getAgName());
        String to = m.getReceiver();
        String local = hub.localNameFor(to);
        if (local != null) {
            m.setReceiver(local);
            super.sendMsg(m);
            return;
        }
        String mas = hub.remoteMasOf(to);
        if (mas == null) {
            if (isSyncAsk(m)) // .send put the intention among the pending ones; it fails instead
                getTS().getC().removePendingIntention(m.getMsgId());
            throw new ReceiverNotFoundException("Could not send " + m + ": " + hub.whyUnreachable(to), to);
        }
        if (isSyncAsk(m))
            trackRemoteAsk(m.getMsgId(), to);
        try {
            hub.publishMessage(mas, m);
        } catch (JasonException e) {
            if (isSyncAsk(m)) {
                remoteAsks.remove(m.getMsgId());
                getTS().getC().removePendingIntention(m.getMsgId());
            }
            throw e;
        }
        // it may have left between the look-up and the tracking: its departure is then already past
        if (isSyncAsk(m) && hub.remoteMasOf(to) == null) {
            lostReceivers.add(to);
            dataArrived();
        }
    }

    /** .broadcast: every other hosted agent through Jason's mailbox, every other process with one ROS message. */
    @Override
    public void broadcast(Message m) throws Exception {
        if (m.getSender() == null)
            m.setSender(getAgName());
        for (String name : new ArrayList<>(RasonHub.jasonAgents().keySet())) {
            if (name.equals(getAgName()))
                continue;
            Message copy = m.clone();
            copy.setReceiver(name);
            try {
                super.sendMsg(copy);
            } catch (ReceiverNotFoundException e) {
                // stopped meanwhile: a broadcast goes to whoever is there
            }
        }
        Message remote = m.clone();
        remote.setReceiver("");
        hub.publishMessage("", remote);
    }

    private static boolean isSyncAsk(Message m) {
        return m.isAsk() && m.getMsgId() != null && m.getMsgId().startsWith(Message.msgIdSyncAskPrefix);
    }

    /** Remembers a pending remote ask so it ends if its receiver leaves or never answers. */
    private void trackRemoteAsk(String msgId, String receiver) {
        RemoteAsk ask = remoteAsks.computeIfAbsent(msgId, id -> {
            RemoteAsk a = new RemoteAsk();
            long timeout = hub.getAskTimeoutNanos();
            if (timeout > 0 && !hasJasonTimeout(id))
                a.deadlineNanos = hub.rosNow() + timeout;
            return a;
        });
        ask.receivers.add(receiver);
    }

    /** Whether the suspended .send has a fifth argument, Jason's own timeout. */
    private boolean hasJasonTimeout(String msgId) {
        Intention i = getTS().getC().getPendingIntentions().get(msgId);
        try {
            Term send = i.peek().getCurrentStep().getBodyTerm();
            return send instanceof Structure s && s.getArity() > 4;
        } catch (RuntimeException e) {
            return false;
        }
    }

    /** Some remote agents left or restarted: asks waiting for them will never be answered. */
    void receiversLost(Collection<String> names) {
        if (remoteAsks.isEmpty())
            return;
        lostReceivers.addAll(names);
        dataArrived();
    }

    /** On the agent's thread: forgets answered asks, fails those whose receiver left, timed out, or the node stops. */
    private void settleRemoteAsks() {
        Set<String> lost = new HashSet<>();
        String gone;
        while ((gone = lostReceivers.poll()) != null)
            lost.add(gone);
        if (remoteAsks.isEmpty())
            return;
        Map<String, Intention> waiting = getTS().getC().getPendingIntentions();
        long now = hub.rosNow();
        String stopping = failAsksReason;
        for (Iterator<Map.Entry<String, RemoteAsk>> it = remoteAsks.entrySet().iterator(); it.hasNext();) {
            Map.Entry<String, RemoteAsk> e = it.next();
            String id = e.getKey();
            RemoteAsk ask = e.getValue();
            if (!waiting.containsKey(id)) { // answered, or ended by Jason's own timeout
                it.remove();
                continue;
            }
            String departed = null;
            for (String r : ask.receivers)
                if (lost.contains(r))
                    departed = r;
            if (stopping != null) {
                it.remove();
                failAsk(id, stopping, "the bridge is stopping", null);
            } else if (departed != null) {
                it.remove();
                failAsk(id, "receiver_departed", departed + " left before answering",
                        ASSyntax.createStructure("agent_departed", new Atom(departed)));
            } else if (now > ask.deadlineNanos) {
                it.remove();
                failAsk(id, "ask_timeout", "no answer from " + ask.receivers + " within the ask timeout", null);
            }
        }
    }

    private void failAsk(String msgId, String error, String text, Term extra) {
        Intention i = getTS().getC().removePendingIntention(msgId);
        if (i == null)
            return;
        ListTerm annots = JasonException.createBasicErrorAnnots(error, text);
        if (extra != null)
            annots.concat(ASSyntax.createList(extra));
        RasonHub.log(Level.INFO, "[" + getAgName() + "] ask " + msgId + " failed: " + text);
        try {
            getTS().generateGoalDeletion(i, annots, ASSyntax.createAtom(error));
        } catch (JasonException e) {
            RasonHub.log(Level.SEVERE, "[" + getAgName() + "] could not fail ask " + msgId + ": " + e.getMessage());
        }
    }

    private void dataArrived() {
        newData = true;
        wakeUpSense();
    }
}
