package rason;

import jason.asSemantics.TransitionSystem;
import jason.asSemantics.Unifier;
import jason.asSyntax.NumberTermImpl;
import jason.asSyntax.Term;

/** An internal action of one argument that binds it to the time of a clock, in milliseconds. */
abstract class ClockReading extends OneArgumentAction {

    /** The clock's time now, in milliseconds, for the agent of ts. */
    abstract double nowMillis(TransitionSystem ts);

    @Override
    public Object execute(TransitionSystem ts, Unifier un, Term[] args) throws Exception {
        checkArguments(args);
        return un.unifies(args[0], new NumberTermImpl(nowMillis(ts)));
    }
}
