package rason;

import jason.asSemantics.DefaultInternalAction;
import jason.asSemantics.TransitionSystem;
import jason.asSemantics.Unifier;
import jason.asSyntax.NumberTermImpl;
import jason.asSyntax.Term;

/**
 * {@code rason.time_ms(X)}: X is the time in milliseconds, with a fractional
 * part down to the microsecond, on the monotonic clock of this machine (Java's
 * {@code System.nanoTime}, Python's {@code time.monotonic} on Linux). Meant for
 * differences, as thesis Listing 5.4 uses its modified {@code .time}; Jason's
 * own {@code .time} gives hours, minutes and seconds only.
 */
public class time_ms extends DefaultInternalAction {

    @Override
    public int getMinArgs() {
        return 1;
    }

    @Override
    public int getMaxArgs() {
        return 1;
    }

    @Override
    public Object execute(TransitionSystem ts, Unifier un, Term[] args) throws Exception {
        checkArguments(args);
        return un.unifies(args[0], new NumberTermImpl(nowMillis()));
    }

    /** Milliseconds on the monotonic clock, rounded to the microsecond. */
    static double nowMillis() {
        return Math.rint(System.nanoTime() / 1e3) / 1e3;
    }
}
