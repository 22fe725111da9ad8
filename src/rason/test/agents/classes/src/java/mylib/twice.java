package mylib;

import jason.asSemantics.DefaultInternalAction;
import jason.asSemantics.TransitionSystem;
import jason.asSemantics.Unifier;
import jason.asSyntax.NumberTerm;
import jason.asSyntax.NumberTermImpl;
import jason.asSyntax.Term;

/** mylib.twice(X, Y): Y is twice the number X. */
public class twice extends DefaultInternalAction {

    @Override
    public Object execute(TransitionSystem ts, Unifier un, Term[] args) throws Exception {
        double x = ((NumberTerm) args[0]).solve();
        return un.unifies(args[1], new NumberTermImpl(2 * x));
    }
}
