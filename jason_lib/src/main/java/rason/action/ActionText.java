package rason.action;

import jason.asSyntax.ASSyntax;
import jason.asSyntax.Literal;
import jason.asSyntax.NumberTerm;
import jason.asSyntax.StringTerm;
import jason.asSyntax.Structure;
import jason.asSyntax.Term;

import rason.core.InputLimits;
import rason.perception.Perceptions;

/** How an action's terms cross to ROS as text, and how a result comes back as a failure reason. */
public final class ActionText {

    private ActionText() {
    }

    /**
     * Action parameters as text: numbers plainly ("-0.3", "1"), strings without
     * their quotes, other terms in Jason syntax.
     */
    public static String[] parametersOf(Structure term) {
        String[] out = new String[term.getArity()];
        for (int i = 0; i < out.length; i++) {
            Term t = term.getTerm(i);
            if (t.isString())
                out[i] = ((StringTerm) t).getString();
            else
                out[i] = t.isNumeric() && t.isGround() ? numberText((NumberTerm) t) : t.toString();
        }
        return out;
    }

    private static String numberText(NumberTerm n) {
        double v;
        try {
            v = n.solve();
        } catch (Exception e) {
            return n.toString();
        }
        if (v == Math.rint(v) && !Double.isInfinite(v) && Math.abs(v) < 1e15)
            return Long.toString((long) v);
        return Double.toString(v);
    }

    /**
     * The reason as it appears among the failure event's annotations: a Jason
     * literal without annotations as it is (so {@code -!g[no_progress]} matches),
     * anything else as {@code failure_reason("text")}.
     */
    public static Literal reasonLiteral(String result, InputLimits limits) {
        try {
            Literal l = Perceptions.parse(result, limits);
            if (!l.hasAnnot())
                return l;
        } catch (IllegalArgumentException e) {
            // not a Jason literal: keep the text
        }
        return ASSyntax.createLiteral("failure_reason", ASSyntax.createString(result));
    }
}
