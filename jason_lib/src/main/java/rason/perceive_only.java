package rason;

import java.util.ArrayList;
import java.util.List;

import jason.JasonException;
import jason.asSemantics.TransitionSystem;
import jason.asSemantics.Unifier;
import jason.asSyntax.StringTerm;
import jason.asSyntax.Term;

import rason.perception.SelectivePerception;

/**
 * {@code rason.perceive_only(["robot/4", "battery/1"])} (or one string
 * {@code "robot/4, battery/1"}): from now on only literals with these
 * functor/arity pairs reach the agent's belief base from ROS perceptions and
 * the bridge's present/1 (selective perception, thesis §5.5). The pairs are
 * strings because Jason's parser reads {@code robot/4} as a division.
 * {@code rason.perceive_all} lifts the selection.
 */
public class perceive_only extends OneArgumentAction {

    @Override
    public Object execute(TransitionSystem ts, Unifier un, Term[] args) throws Exception {
        checkArguments(args);
        List<String> entries = new ArrayList<>();
        if (args[0].isList()) {
            for (Term t : (Iterable<Term>) args[0])
                entries.add(text(t));
        } else {
            entries.add(text(args[0]));
        }
        RosAgArch arch = RosAgArch.of(ts);
        if (arch == null)
            throw new JasonException("rason.perceive_only needs the agent architecture rason.RosAgArch");
        try {
            arch.perception().perceiveOnly(SelectivePerception.parseSelection(entries));
        } catch (IllegalArgumentException e) {
            throw JasonException.createWrongArgument(this, e.getMessage());
        }
        return true;
    }

    private static String text(Term t) {
        return t.isString() ? ((StringTerm) t).getString() : t.toString();
    }
}
