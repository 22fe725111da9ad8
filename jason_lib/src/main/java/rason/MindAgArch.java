package rason;

import java.util.Collection;
import java.util.List;

import jason.architecture.AgArch;
import jason.asSemantics.Event;
import jason.asSemantics.Message;

import rason.action.AgentActions;
import rason.mind.MindPort;
import rason.mind.MindRecorder;

/**
 * jason/mind's link in an agent's architecture chain, as Jason's own mind inspector
 * is one: while the node wants minds, it notes each handled event and each message
 * received or sent, and has the agent read its own state at the end of a cycle (at
 * most once per period) and before it sleeps. Put before {@link RosAgArch} by the
 * infrastructure, so it sees messages to other robots too.
 */
public class MindAgArch extends AgArch {

    private AgentHost host;
    private MindPort port;
    private MindRecorder mind;
    private final MindRecorder.Reader read = (events, messages) -> port.reader().read(getTS(), getCycleNumber(),
            host.rosClock().nanos(), pendingActions(), events.items(), messages.items());

    @Override
    public void init() throws Exception {
        super.init();
        host = AgentHost.of(this);
        port = host.mind();
        mind = port.join(getAgName(), this::wakeUpSense);
    }

    @Override
    public void stop() {
        port.leave(getAgName(), mind);
        super.stop();
    }

    private boolean on() {
        return port.periodNanos() > 0;
    }

    private List<rason.mind.AgentMind.ActionView> pendingActions() {
        AgentActions actions = host.actions().of(getAgName());
        return actions == null ? List.of() : actions.pendingView();
    }

    /** The MindAgArch in an agent's architecture chain, null if it has none. */
    public static MindAgArch of(jason.asSemantics.TransitionSystem ts) {
        for (AgArch a = ts.getAgArch().getFirstAgArch(); a != null; a = a.getNextAgArch())
            if (a instanceof MindAgArch m)
                return m;
        return null;
    }

    /** This agent's side of jason/mind (its snapshots, read by the node's thread). */
    public MindRecorder recorder() {
        return mind;
    }

    @Override
    public void reasoningCycleFinished() {
        long period = port.periodNanos();
        if (period > 0) {
            Event selected = getTS().getC().getSelectedEvent();
            if (selected != null)
                mind.event(selected.getTrigger().toString());
            mind.cycleEnded(period, host.wallClock().nanos(), read);
        }
        super.reasoningCycleFinished();
    }

    /** A snapshot asked for is taken in one more cycle; otherwise the state the agent pauses in is read now. */
    @Override
    public boolean canSleep() {
        if (on() && mind.isRequested())
            return false;
        boolean sleep = super.canSleep();
        if (sleep && on())
            mind.goingToSleep(host.wallClock().nanos(), read);
        return sleep;
    }

    @Override
    public void checkMail() {
        if (!on()) {
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

    @Override
    public void sendMsg(Message m) throws Exception {
        if (on()) {
            if (m.getSender() == null)
                m.setSender(getAgName());
            mind.message(dialogueLine(m));
        }
        super.sendMsg(m);
    }

    @Override
    public void broadcast(Message m) throws Exception {
        if (on()) {
            Message all = m.clone();
            if (all.getSender() == null)
                all.setSender(getAgName());
            all.setReceiver("");
            mind.message(dialogueLine(all));
        }
        super.broadcast(m);
    }

    /** "sender -> receiver: performative content", as rason_dialogue prints a message. */
    static String dialogueLine(Message m) {
        String to = m.getReceiver() == null || m.getReceiver().isEmpty() ? "all" : m.getReceiver();
        return m.getSender() + " -> " + to + ": " + m.getIlForce() + " " + m.getPropCont();
    }
}
