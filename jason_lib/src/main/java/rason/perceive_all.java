package rason;

import jason.JasonException;
import jason.asSemantics.DefaultInternalAction;
import jason.asSemantics.TransitionSystem;
import jason.asSemantics.Unifier;
import jason.asSyntax.Term;

/** {@code rason.perceive_all}: lifts the selection of {@code rason.perceive_only} (or of the .mas2j option perceive). */
public class perceive_all extends DefaultInternalAction {

    @Override
    public Object execute(TransitionSystem ts, Unifier un, Term[] args) throws Exception {
        RosAgArch arch = RosAgArch.of(ts);
        if (arch == null)
            throw new JasonException("rason.perceive_all needs the agent architecture rason.RosAgArch");
        arch.perception().perceiveOnly(null);
        return true;
    }
}
