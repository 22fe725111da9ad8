package rason.messaging;

import java.util.List;

import jason.asSemantics.Agent;
import jason.asSemantics.TransitionSystem;
import jason.asSemantics.Unifier;
import jason.asSyntax.ASSyntax;
import jason.asSyntax.Atom;
import jason.asSyntax.InternalActionLiteral;
import jason.asSyntax.Plan;
import jason.asSyntax.PlanBody;
import jason.asSyntax.Structure;
import jason.asSyntax.Term;

/**
 * Jason's {@code .send}, except that a message to agents of other processes keeps the
 * sending intention suspended until their receipts come (see {@link SentReceipts}), as
 * Jason's own {@code .send} completes only once a local receiver has the message in its
 * mailbox. Synchronous asks wait for their answer instead, as in Jason; messages to
 * agents of this process and {@code .broadcast} do not wait.
 */
public final class ReceiptedSend extends jason.stdlib.send {

    /** Why a sending intention is suspended (shown by mind inspectors). */
    public static final Atom WAITING_RECEIPT = ASSyntax.createAtom("waiting_receipt");

    private static final String JASON_SEND = "jason.stdlib.send";
    private static final String SEND = ".send";

    private final AgentMessaging messaging;
    private boolean waiting; // only touched on the agent's thread

    ReceiptedSend(AgentMessaging messaging) {
        this.messaging = messaging;
    }

    /**
     * Makes this the {@code .send} of the agent: for code parsed from now on, and for its
     * plans parsed before (Jason binds an internal action when it parses the call).
     */
    static void install(Agent ag, AgentMessaging messaging) {
        ReceiptedSend send = new ReceiptedSend(messaging);
        ag.setIA(JASON_SEND, send);
        for (Plan p : ag.getPL().getPlans())
            rebind(p.getBody(), ag);
    }

    private static void rebind(PlanBody body, Agent ag) {
        for (PlanBody step = body; step != null; step = step.getBodyNext()) {
            Term t = step.getBodyTerm();
            if (!(t instanceof InternalActionLiteral ial))
                continue;
            if (SEND.equals(ial.getFunctor())) {
                try {
                    step.setBodyTerm(new InternalActionLiteral(ial.getNS(), ial, ag));
                } catch (Exception e) {
                    throw new IllegalStateException("cannot bind .send in " + ial + ": " + e.getMessage(), e);
                }
            } else { // if/while/for carry their bodies as arguments
                for (int a = 0; a < ial.getArity(); a++)
                    rebindNested(ial.getTerm(a), ag);
            }
        }
    }

    private static void rebindNested(Term t, Agent ag) {
        if (t instanceof PlanBody pb)
            rebind(pb, ag);
        else if (t instanceof Structure s)
            for (int a = 0; a < s.getArity(); a++)
                rebindNested(s.getTerm(a), ag);
    }

    @Override
    public Object execute(TransitionSystem ts, Unifier un, Term[] args) throws Exception {
        waiting = false;
        List<String> remote = messaging.collectRemote();
        Object result;
        try {
            result = super.execute(ts, un, args);
        } catch (Exception e) {
            messaging.endCollecting(false);
            throw e;
        }
        messaging.endCollecting(true);
        if (!remote.isEmpty() && !super.suspendIntention()) {
            ts.getC().addPendingIntention(AgentMessaging.receiptKey(remote.get(0)), WAITING_RECEIPT,
                    ts.getC().getSelectedIntention(), true);
            waiting = true;
        }
        return result;
    }

    @Override
    public boolean suspendIntention() {
        return waiting || super.suspendIntention();
    }
}
