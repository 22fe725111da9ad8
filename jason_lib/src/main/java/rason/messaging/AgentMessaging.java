package rason.messaging;

import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import java.util.Map;
import java.util.logging.Level;

import jason.JasonException;
import jason.ReceiverNotFoundException;
import jason.asSemantics.Intention;
import jason.asSemantics.Message;
import jason.asSemantics.TransitionSystem;
import jason.asSyntax.ASSyntax;
import jason.asSyntax.Atom;
import jason.asSyntax.ListTerm;
import jason.asSyntax.Structure;
import jason.asSyntax.Term;

import rason.core.Protocol;

/**
 * One agent's messages beyond its process, both ways: {@code .send} and
 * {@code .broadcast} to agents of other robots leave through the fleet channel;
 * synchronous asks to them are tracked until answered, timed out or their receiver
 * leaves; answers to its own asks pass the trust policy. Everything that touches the
 * agent's intentions runs on the agent's thread ({@link #settle}).
 */
public final class AgentMessaging {

    /** Jason's own delivery to an agent of this process (the rest of the architecture chain). */
    @FunctionalInterface
    public interface Local {
        void send(Message m) throws Exception;
    }

    private final String agent;
    private final TransitionSystem ts;
    private final FleetPort port;
    private final Local local;
    private final Runnable wake;
    private final RemoteAsks asks = new RemoteAsks();
    private final SentAsks sentAsks = new SentAsks();
    private final SentReceipts receipts = new SentReceipts();
    private List<String> collecting; // message ids of the running .send that wait for receipts (agent's thread)
    private volatile String stopping = null; // set at shutdown

    AgentMessaging(String agent, TransitionSystem ts, FleetPort port, Local local, Runnable wake) {
        this.agent = agent;
        this.ts = ts;
        this.port = port;
        this.local = local;
        this.wake = wake;
        ReceiptedSend.install(ts.getAg(), this);
    }

    /**
     * .send: a receiver hosted here (by its name, or by this robot's prefix and its
     * name) gets the message through Jason's own mailbox; a reachable remote one through
     * the fleet channel; anyone else fails the intention with error(receiver_not_found),
     * as Jason does for an unknown local receiver.
     */
    public void send(Message m) throws Exception {
        if (m.getSender() == null)
            m.setSender(agent);
        String to = m.getReceiver();
        String localName = port.names().localNameFor(to);
        if (localName != null) {
            m.setReceiver(localName);
            local.send(m);
            return;
        }
        String mas = port.fleet().sendableMasOf(to);
        boolean syncAsk = isSyncAsk(m);
        if (mas == null) {
            if (syncAsk) // .send put the intention among the pending ones; it fails instead
                ts.getC().removePendingIntention(m.getMsgId());
            throw new ReceiverNotFoundException("Could not send " + m + ": " + port.fleet().whyUnreachable(to), to);
        }
        if (syncAsk)
            asks.track(m.getMsgId(), to, port.rosNow(), hasJasonTimeout(m.getMsgId()) ? 0 : port.askTimeoutNanos());
        if (m.isAsk())
            sentAsks.sent(m.getMsgId(), to);
        boolean receipted = !syncAsk && collecting != null;
        if (receipted) {
            receipts.expect(m.getMsgId(), to, mas, port.wallNow());
            collecting.add(m.getMsgId());
        }
        try {
            publish(mas, m);
        } catch (JasonException e) {
            if (syncAsk) {
                asks.forget(m.getMsgId());
                ts.getC().removePendingIntention(m.getMsgId());
            }
            if (receipted)
                receipts.forget(m.getMsgId());
            throw e;
        }
        // it may have left between the look-up and the tracking: its departure is then already past
        if ((syncAsk || receipted) && port.fleet().sendableMasOf(to) == null) {
            asks.receiversLost(List.of(to));
            receipts.receiversLost(List.of(to));
            wake.run();
        }
    }

    /** The pending-intention key of a send waiting for the receipts of message msgId. */
    static String receiptKey(String msgId) {
        return "rason_receipt_" + msgId;
    }

    /** A .send starts: the remote messages it sends (their ids go in the list) wait for receipts. */
    List<String> collectRemote() {
        collecting = new ArrayList<>();
        return collecting;
    }

    /** The .send ended (sent: false if it failed, and nothing waits). */
    void endCollecting(boolean sent) {
        if (!sent)
            for (String id : collecting)
                receipts.forget(id);
        collecting = null;
    }

    /** An authentic receipt for a message of this agent (from a channel's thread). */
    void receiptArrived(WireMessage receipt) {
        if (receipts.arrived(receipt.inReplyTo(), receipt.sender(), receipt.senderMas(), Receipts.refused(receipt)))
            wake.run();
    }

    /** .broadcast: every other hosted agent through Jason's mailbox, every other process with one fleet message. */
    public void broadcast(Message m) throws Exception {
        if (m.getSender() == null)
            m.setSender(agent);
        for (String name : new ArrayList<>(port.jasonAgents().keySet())) {
            if (name.equals(agent))
                continue;
            Message copy = m.clone();
            copy.setReceiver(name);
            try {
                local.send(copy);
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

    /** Whether a message of another process from sender answers an ask this agent sent it. */
    boolean asked(String sender, String inReplyTo) {
        return sentAsks.answeredBy(inReplyTo, sender);
    }

    private void publish(String receiverMas, Message m) throws JasonException {
        if (!port.send(receiverMas, m))
            throw new JasonException("could not send " + m + ": the bridge is not running",
                    ASSyntax.createAtom(Protocol.BRIDGE_ERROR));
    }

    private static boolean isSyncAsk(Message m) {
        return m.isAsk() && m.getMsgId() != null && m.getMsgId().startsWith(Message.msgIdSyncAskPrefix);
    }

    /** Whether the suspended .send has a fifth argument, Jason's own timeout. */
    private boolean hasJasonTimeout(String msgId) {
        Intention i = ts.getC().getPendingIntentions().get(msgId);
        try {
            Term send = i.peek().getCurrentStep().getBodyTerm();
            return send instanceof Structure s && s.getArity() > 4;
        } catch (RuntimeException e) {
            return false;
        }
    }

    /** Some remote agents left or restarted (from a node's thread): asks waiting for them will never be answered. */
    void receiversLost(Collection<String> names) {
        boolean asking = asks.receiversLost(names);
        if (receipts.receiversLost(names) || asking)
            wake.run();
    }

    /** Periodic, with the ROS time. */
    void tick(long rosNanos) {
        if (asks.due(rosNanos) || receipts.due(port.wallNow(), port.messageTtlNanos()))
            wake.run();
    }

    /** The node stops: every waiting ask fails with reason. */
    void stop(String reason) {
        stopping = reason;
        wake.run();
    }

    /** Whether {@link #settle} has asks to fail or sends to end. */
    public boolean hasSomethingToSettle() {
        return asks.hasLost() || receipts.hasNews();
    }

    /**
     * On the agent's thread: fails asks whose receiver left, that timed out, or that the
     * stopping node leaves; resumes sends whose receipts came, fails the others that ended.
     */
    public void settle() {
        Map<String, Intention> waiting = ts.getC().getPendingIntentions();
        if (!asks.isEmpty() || asks.hasLost())
            for (RemoteAsks.Failure f : asks.settle(waiting::containsKey, port.rosNow(), stopping))
                fail(f);
        if (receipts.isEmpty())
            return;
        long now = port.wallNow();
        long ttl = port.messageTtlNanos();
        // nothing can end without a receipt, a loss, the TTL or the stop: no look at every send in every cycle
        if (!receipts.hasNews() && !receipts.due(now, ttl) && stopping == null)
            return;
        for (SentReceipts.Outcome o : receipts.settle(id -> waiting.containsKey(receiptKey(id)), now, ttl, stopping))
            end(o);
    }

    private void end(SentReceipts.Outcome o) {
        Intention i = ts.getC().removePendingIntention(receiptKey(o.msgId()));
        if (i == null)
            return;
        if (o.delivered()) {
            i.peek().removeCurrentStep(); // the .send
            ts.getC().resumeIntention(i, ReceiptedSend.WAITING_RECEIPT);
            return;
        }
        fail(i, o.msgId(), o.error(), o.text(), o.departed(), "send");
    }

    private void fail(RemoteAsks.Failure f) {
        Intention i = ts.getC().removePendingIntention(f.msgId());
        if (i != null)
            fail(i, f.msgId(), f.error(), f.text(), f.departed(), "ask");
    }

    private void fail(Intention i, String msgId, String error, String text, String departed, String what) {
        ListTerm annots = JasonException.createBasicErrorAnnots(error, text);
        if (departed != null)
            annots.concat(ASSyntax.createList(ASSyntax.createStructure("agent_departed", new Atom(departed))));
        port.log(Level.INFO, "[" + agent + "] " + what + " " + msgId + " failed: " + text);
        try {
            ts.generateGoalDeletion(i, annots, ASSyntax.createAtom(error));
        } catch (JasonException e) {
            port.log(Level.SEVERE, "[" + agent + "] could not fail " + what + " " + msgId + ": " + e.getMessage());
        }
    }
}
