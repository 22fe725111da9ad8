package rason;

import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.logging.Level;

import jason.JasonException;
import jason.ReceiverNotFoundException;
import jason.architecture.AgArch;
import jason.asSemantics.ActionExec;
import jason.asSemantics.CircumstanceListener;
import jason.asSemantics.Event;
import jason.asSemantics.Intention;
import jason.asSemantics.Message;
import jason.asSemantics.TransitionSystem;
import jason.asSyntax.ASSyntax;
import jason.asSyntax.Atom;
import jason.asSyntax.ListTerm;
import jason.asSyntax.Literal;
import jason.asSyntax.Structure;
import jason.asSyntax.Term;

import rason.action.ActionTable;
import rason.action.AgentActions;
import rason.action.ActionText;
import rason.bridge.AgentRegistry;
import rason.bridge.Bridge;
import rason.bridge.Outbound;
import rason.bridge.Protocol;
import rason.messaging.Messages;
import rason.mind.MindRecorder;
import rason.messaging.RemoteAsks;
import rason.messaging.SentAsks;
import rason.perception.PerSourcePerception;
import rason.perception.PerceptionManager;
import rason.perception.PerceptionManagers;
import rason.perception.SelectivePerception;

/**
 * Agent architecture of thesis §5.2, a link in Jason's AgArch chain that only
 * overrides Jason's hooks and hands each concern to its own class: actions to
 * {@link AgentActions} (out through the bridge's {@link rason.bridge.Outbox}, taken back
 * when the agent changes its mind),
 * perception to the agent's {@link PerceptionManager}, asks to agents of other
 * processes to {@link RemoteAsks}. ROS threads only record and wake the agent;
 * everything that touches Jason's state runs on the agent's thread, and that
 * thread never calls into Python nor waits for ROS.
 */
public class RosAgArch extends AgArch {

    private final Bridge bridge = Bridge.get();
    private final AgentActions actions = new AgentActions(bridge::nextActionId, bridge.outbox(), this::getAgName,
            this::dataArrived);
    private final RemoteAsks asks = new RemoteAsks();
    private final SentAsks sentAsks = new SentAsks();
    // Jason's take-back hooks, in the agent's circumstance only while it has actions pending:
    // with any listener there, Jason makes an event of every belief change, plans or not
    // (Agent.buf), and the agent spends a reasoning cycle on each: 1000 new percepts delayed
    // its next plan by 1000 cycles. Added and removed on the agent's thread only.
    private final CircumstanceListener takeBack = actions.listener();
    private boolean listening = false;
    private volatile PerceptionManager perception = new SelectivePerception(new PerSourcePerception(), null);
    private volatile String failAsksReason = null; // set at shutdown
    private volatile List<Literal> presence = List.of();
    private volatile boolean presenceChanged = false;
    // Set when ROS data arrives and cleared when a cycle starts, so an agent
    // woken just before it decides to sleep runs one more cycle instead.
    private volatile boolean newData = false;
    // jason/mind: recent events and messages, snapshots on this agent's thread while the bridge wants them
    private final MindRecorder mind = new MindRecorder();
    private final MindRecorder.Reader readMind = (events, messages) -> bridge.mindReader().read(getTS(),
            getCycleNumber(), bridge.clock().now(), actions.pendingView(), events.items(), messages.items());

    @Override
    public void init() throws Exception {
        super.init();
        try {
            perception = PerceptionManagers.forAgent(getTS().getSettings(), bridge.defaultPerceptionManager());
        } catch (IllegalArgumentException e) {
            // RasonLocalMAS checks the options before creating agents; this is for agents created later
            Bridge.log(Level.SEVERE, "[" + getAgName() + "] " + e.getMessage() + "; using " + PerceptionManagers.PER_SOURCE);
        }
        if (!PerceptionManagers.PER_SOURCE.equals(perception.toString()))
            Bridge.log(Level.INFO, "[" + getAgName() + "] perception: " + perception);
        bridge.register(this);
    }

    @Override
    public void stop() {
        bridge.unregister(this);
        super.stop();
    }

    /** The RosAgArch in an agent's architecture chain (other architectures may come before it). */
    public static RosAgArch of(TransitionSystem ts) {
        for (AgArch a = ts.getAgArch().getFirstAgArch(); a != null; a = a.getNextAgArch())
            if (a instanceof RosAgArch r)
                return r;
        return null;
    }

    // ---- actions ---------------------------------------------------------------------

    /** Registers the action and queues it for the node; the intention waits for its feedback. */
    @Override
    public void act(ActionExec action) {
        String stopping = bridge.shutdownReason();
        if (stopping != null)
            complete(action, stopping);
        else {
            actions.start(action, bridge.clock().now());
            if (!listening) { // before the intention can be dropped: that happens in a later step of this thread
                getTS().getC().addEventListener(takeBack);
                listening = true;
            }
        }
    }

    /** Feedback for one of this agent's actions (from a ROS thread); false if none such is pending. */
    public boolean feedback(int actionId, String result) {
        return actions.feedback(actionId, result);
    }

    /** A decomposer said it took action actionId (from a ROS thread). */
    public boolean startedBy(int actionId, String decomposer) {
        return actions.startedBy(actionId, decomposer);
    }

    /** Periodic: actions whose decomposer went away fail decomposer_lost. */
    public void decomposersTick(Set<String> connected, long nowNanos, long graceNanos) {
        actions.decomposersTick(connected, nowNanos, graceNanos);
    }

    /** Actions still waiting for their feedback. */
    public int pendingActions() {
        return actions.pendingCount();
    }

    /** The node stops: pending actions fail with reason and the robot is told to stop them; asks fail too. */
    public void failPending(String reason) {
        actions.failAll(reason);
        failAsksReason = reason;
        dataArrived();
    }

    /** Periodic, with the ROS time: perception expiry, action and ask timeouts. */
    public void tick(long nowNanos, long actionTimeoutNanos, long ttlNanos) {
        boolean wake = perception.expire(nowNanos, ttlNanos);
        wake |= actions.expire(nowNanos, actionTimeoutNanos);
        wake |= asks.due(nowNanos);
        if (wake)
            dataArrived();
    }

    @Override
    public void reasoningCycleStarting() {
        newData = false;
        actions.takeBackOrphans(getTS().getC().getPendingActions());
        for (ActionTable.Settled<ActionExec> s : actions.takeSettled())
            complete(s.action(), s.result());
        settleRemoteAsks();
        if (listening && actions.pendingCount() == 0) { // nothing left to take back
            getTS().getC().removeEventListener(takeBack);
            listening = false;
        }
        super.reasoningCycleStarting();
    }

    /** Records the cycle's event and, when due, a snapshot of the agent's state for jason/mind. */
    @Override
    public void reasoningCycleFinished() {
        long period = bridge.mindPeriodNanos();
        if (period > 0) {
            Event selected = getTS().getC().getSelectedEvent();
            if (selected != null)
                mind.event(selected.getTrigger().toString());
            mind.cycleEnded(period, System.nanoTime(), readMind);
        }
        super.reasoningCycleFinished();
    }

    /** This agent's side of jason/mind (its snapshots, read by the node's thread). */
    public MindRecorder mind() {
        return mind;
    }

    /** A snapshot at the end of the next cycle, which this wakes the agent for (any thread). */
    public void requestMind() {
        mind.request();
        dataArrived();
    }

    /** Ends an action: OK resumes the intention, anything else fails it with that reason. */
    private void complete(ActionExec action, String result) {
        if (Protocol.OK.equals(result)) {
            action.setResult(true);
        } else {
            action.setResult(false);
            action.setFailureReason(ActionText.reasonLiteral(result), action.getActionTerm() + " failed: " + result);
        }
        actionExecuted(action);
    }

    // ---- perception ------------------------------------------------------------------

    /** A source's current literals (from a ROS thread). */
    public void perceptionUpdate(String source, List<Literal> literals, long nowNanos) {
        if (perception.update(source, literals, nowNanos))
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
    public void presenceUpdate(List<String> names) {
        List<Literal> literals = new ArrayList<>(names.size());
        for (String n : names)
            literals.add(ASSyntax.createLiteral("present", new Atom(n)));
        presence = literals;
        presenceChanged = true;
        dataArrived();
    }

    @Override
    public boolean canSleep() {
        actions.takeBackOrphans(getTS().getC().getPendingActions());
        boolean sleep = !newData && !actions.hasSettled() && !asks.hasLost() && super.canSleep();
        if (sleep && bridge.mindPeriodNanos() > 0)
            mind.goingToSleep(System.nanoTime(), readMind); // the state it pauses in is never missed
        return sleep;
    }

    /** Moves the mail into Jason's circumstance, noting each message for jason/mind. */
    @Override
    public void checkMail() {
        if (bridge.mindPeriodNanos() <= 0) {
            super.checkMail();
            return;
        }
        Collection<Message> box = getTS().getC().getMailBox();
        int before = box.size();
        super.checkMail();
        int i = 0;
        for (Message m : box)
            if (i++ >= before) // the new ones are at the end
                mind.message(dialogueLine(m));
    }

    /** "sender -> receiver: performative content", as rason_dialogue prints a message. */
    static String dialogueLine(Message m) {
        String to = m.getReceiver() == null || m.getReceiver().isEmpty() ? "all" : m.getReceiver();
        return m.getSender() + " -> " + to + ": " + m.getIlForce() + " " + m.getPropCont();
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
        if (bridge.mindPeriodNanos() > 0)
            mind.message(dialogueLine(m));
        String to = m.getReceiver();
        String local = bridge.registry().localNameFor(to);
        if (local != null) {
            m.setReceiver(local);
            super.sendMsg(m);
            return;
        }
        String mas = bridge.fleet().sendableMasOf(to);
        boolean syncAsk = isSyncAsk(m);
        if (mas == null) {
            if (syncAsk) // .send put the intention among the pending ones; it fails instead
                getTS().getC().removePendingIntention(m.getMsgId());
            throw new ReceiverNotFoundException("Could not send " + m + ": " + bridge.fleet().whyUnreachable(to), to);
        }
        if (syncAsk)
            asks.track(m.getMsgId(), to, bridge.clock().now(),
                    hasJasonTimeout(m.getMsgId()) ? 0 : bridge.askTimeoutNanos());
        if (m.isAsk())
            sentAsks.sent(m.getMsgId(), to);
        try {
            publish(mas, m);
        } catch (JasonException e) {
            if (syncAsk) {
                asks.forget(m.getMsgId());
                getTS().getC().removePendingIntention(m.getMsgId());
            }
            throw e;
        }
        // it may have left between the look-up and the tracking: its departure is then already past
        if (syncAsk && bridge.fleet().sendableMasOf(to) == null) {
            asks.receiversLost(List.of(to));
            dataArrived();
        }
    }

    /** .broadcast: every other hosted agent through Jason's mailbox, every other process with one ROS message. */
    @Override
    public void broadcast(Message m) throws Exception {
        if (m.getSender() == null)
            m.setSender(getAgName());
        if (bridge.mindPeriodNanos() > 0) {
            Message all = m.clone();
            all.setReceiver("");
            mind.message(dialogueLine(all));
        }
        for (String name : new ArrayList<>(AgentRegistry.jasonAgents().keySet())) {
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
        if (remote.isAsk())
            sentAsks.sent(remote.getMsgId(), "");
        publish("", remote);
    }

    /**
     * Whether a message of another process from sender answers an ask this
     * agent sent it (then the trust policy lets it in whatever its performative).
     */
    public boolean asked(String sender, String inReplyTo) {
        return sentAsks.answeredBy(inReplyTo, sender);
    }

    /** Queues m for another process (receiverMas empty: every other process). */
    private void publish(String receiverMas, Message m) throws JasonException {
        Outbound.AgentMessage out = new Outbound.AgentMessage(receiverMas, m.getSender(), m.getReceiver(),
                m.getIlForce(), Messages.contentText(m), m.getMsgId(), m.getInReplyTo() == null ? "" : m.getInReplyTo());
        if (!bridge.outbox().offer(out))
            throw new JasonException("could not send " + m + ": the bridge is not running",
                    ASSyntax.createAtom(Protocol.BRIDGE_ERROR));
    }

    private static boolean isSyncAsk(Message m) {
        return m.isAsk() && m.getMsgId() != null && m.getMsgId().startsWith(Message.msgIdSyncAskPrefix);
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

    /** Some remote agents left or restarted (from a ROS thread): asks waiting for them will never be answered. */
    public void receiversLost(Collection<String> names) {
        if (asks.receiversLost(names))
            dataArrived();
    }

    /** On the agent's thread: fails asks whose receiver left, that timed out, or that the stopping node leaves. */
    private void settleRemoteAsks() {
        if (asks.isEmpty() && !asks.hasLost())
            return;
        Map<String, Intention> waiting = getTS().getC().getPendingIntentions();
        for (RemoteAsks.Failure f : asks.settle(waiting::containsKey, bridge.clock().now(), failAsksReason))
            failAsk(f);
    }

    private void failAsk(RemoteAsks.Failure f) {
        Intention i = getTS().getC().removePendingIntention(f.msgId());
        if (i == null)
            return;
        ListTerm annots = JasonException.createBasicErrorAnnots(f.error(), f.text());
        if (f.departed() != null)
            annots.concat(ASSyntax.createList(ASSyntax.createStructure("agent_departed", new Atom(f.departed()))));
        Bridge.log(Level.INFO, "[" + getAgName() + "] ask " + f.msgId() + " failed: " + f.text());
        try {
            getTS().generateGoalDeletion(i, annots, ASSyntax.createAtom(f.error()));
        } catch (JasonException e) {
            Bridge.log(Level.SEVERE, "[" + getAgName() + "] could not fail ask " + f.msgId() + ": " + e.getMessage());
        }
    }

    private void dataArrived() {
        newData = true;
        wakeUpSense();
    }
}
