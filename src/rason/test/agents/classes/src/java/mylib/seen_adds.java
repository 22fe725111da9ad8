package mylib;

import jason.asSemantics.DefaultInternalAction;
import jason.asSemantics.TransitionSystem;
import jason.asSemantics.Unifier;
import jason.asSyntax.NumberTermImpl;
import jason.asSyntax.Term;

/** mylib.seen_adds(N): N is how many seen/1 beliefs the agent's CountingBB has taken; fails with another belief base. */
public class seen_adds extends DefaultInternalAction {

    @Override
    public Object execute(TransitionSystem ts, Unifier un, Term[] args) throws Exception {
        if (!(ts.getAg().getBB() instanceof CountingBB bb))
            return false;
        return un.unifies(args[0], new NumberTermImpl(bb.seenAdds()));
    }
}
