package rason;

import java.util.Collection;

import jason.architecture.AgArch;
import jason.asSemantics.ActionExec;
import jason.asSemantics.CircumstanceListener;
import jason.asSemantics.Message;
import jason.asSemantics.TransitionSystem;
import jason.asSyntax.Literal;
import jason.infra.local.LocalAgArch;

import rason.action.ActionTable;
import rason.action.ActionText;
import rason.action.AgentActions;
import rason.core.Protocol;
import rason.messaging.AgentMessaging;
import rason.perception.AgentPerception;

/**
 * Agent architecture of thesis §5.2, a link in Jason's AgArch chain that only
 * overrides Jason's hooks and hands each concern to its own class: actions to
 * {@link AgentActions} (to the robot, taken back when the agent changes its mind),
 * perception to {@link AgentPerception}, messages to agents of other processes to
 * {@link AgentMessaging}. ROS threads only record and wake the agent; everything
 * that touches Jason's state runs on the agent's thread, and that thread never
 * calls into Python nor waits for ROS.
 */
public class RosAgArch extends AgArch {

    private AgentHost host;
    private AgentActions actions;
    private AgentPerception perception;
    private AgentMessaging messaging;
    // Jason's take-back hooks, in the agent's circumstance only while it has actions pending:
    // with any listener there, Jason makes an event of every belief change, plans or not
    // (Agent.buf), and the agent spends a reasoning cycle on each: 1000 new percepts delayed
    // its next plan by 1000 cycles. Added and removed on the agent's thread only.
    private CircumstanceListener takeBack;
    private boolean listening = false;
    // Set when ROS data arrives and cleared when a cycle starts, so an agent
    // woken just before it decides to sleep runs one more cycle instead.
    private volatile boolean newData = false;

    @Override
    public void init() throws Exception {
        super.init();
        host = AgentHost.of(this);
        String name = getAgName();
        actions = host.actions().join(name, this::dataArrived);
        takeBack = actions.listener();
        perception = host.perception().join(name, getTS().getSettings(), this::dataArrived);
        messaging = host.fleet().join(name, getTS(), super::sendMsg, this::dataArrived);
    }

    /** Whether the .mas2j names an environment (known once the agent runs: .create_agent sets it after init). */
    private boolean hasEnvironment() {
        for (AgArch a = getNextAgArch(); a != null; a = a.getNextAgArch())
            if (a instanceof LocalAgArch local)
                return local.getEnvInfraTier() != null;
        return false;
    }

    @Override
    public void stop() {
        String name = getAgName();
        host.fleet().leave(name, messaging);
        host.perception().leave(name, perception);
        host.actions().leave(name, actions);
        super.stop();
    }

    /** The RosAgArch in an agent's architecture chain (other architectures may come before it). */
    public static RosAgArch of(TransitionSystem ts) {
        for (AgArch a = ts.getAgArch().getFirstAgArch(); a != null; a = a.getNextAgArch())
            if (a instanceof RosAgArch r)
                return r;
        return null;
    }

    /** This agent's actions (pending ones, feedback from ROS threads). */
    public AgentActions actions() {
        return actions;
    }

    /** This agent's perception (selective perception, present/1). */
    public AgentPerception perception() {
        return perception;
    }

    /** ROS time as the node last pushed it. */
    public long rosNanos() {
        return host.rosClock().nanos();
    }

    // ---- actions ---------------------------------------------------------------------

    /**
     * Registers the action and queues it for the node; the intention waits for its feedback.
     * With an environment in the .mas2j, the environment takes it instead.
     */
    @Override
    public void act(ActionExec action) {
        String stopping = host.actions().shutdownReason();
        if (hasEnvironment())
            super.act(action); // as under Jason's runner
        else if (stopping != null)
            complete(action, stopping);
        else {
            actions.start(action, host.rosClock().nanos());
            if (!listening) { // before the intention can be dropped: that happens in a later step of this thread
                getTS().getC().addEventListener(takeBack);
                listening = true;
            }
        }
    }

    @Override
    public void reasoningCycleStarting() {
        newData = false;
        actions.takeBackOrphans(getTS().getC().getPendingActions());
        for (ActionTable.Settled<ActionExec> s : actions.takeSettled())
            complete(s.action(), s.result());
        messaging.settle();
        if (listening && actions.pendingCount() == 0) { // nothing left to take back
            getTS().getC().removeEventListener(takeBack);
            listening = false;
        }
        super.reasoningCycleStarting();
    }

    /** Ends an action: OK resumes the intention, anything else fails it with that reason. */
    private void complete(ActionExec action, String result) {
        if (Protocol.OK.equals(result)) {
            action.setResult(true);
        } else {
            action.setResult(false);
            action.setFailureReason(ActionText.reasonLiteral(result, host.actions().limits()),
                    action.getActionTerm() + " failed: " + result);
        }
        actionExecuted(action);
    }

    // ---- perception ------------------------------------------------------------------

    @Override
    public Collection<Literal> perceive() {
        return perception.perceive(super.perceive());
    }

    @Override
    public boolean canSleep() {
        actions.takeBackOrphans(getTS().getC().getPendingActions());
        return !newData && !actions.hasSettled() && !messaging.hasSomethingToSettle() && super.canSleep();
    }

    // ---- messages to agents of other processes ----------------------------------------

    @Override
    public void sendMsg(Message m) throws Exception {
        messaging.send(m);
    }

    @Override
    public void broadcast(Message m) throws Exception {
        messaging.broadcast(m);
    }

    private void dataArrived() {
        newData = true;
        wakeUpSense();
    }
}
