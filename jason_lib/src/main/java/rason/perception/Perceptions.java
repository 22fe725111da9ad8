package rason.perception;

import java.util.ArrayDeque;
import java.util.Deque;

import jason.asSyntax.Atom;
import jason.asSyntax.ListTerm;
import jason.asSyntax.Literal;
import jason.asSyntax.NumberTerm;
import jason.asSyntax.Structure;
import jason.asSyntax.Term;

import rason.core.InputLimits;
import rason.core.JasonParser;

/** Parses the text of one perception into a Jason literal, refusing what cannot be a percept. */
public final class Perceptions {

    /**
     * The annotation a perception may not carry: Jason adds {@code source(percept)} to every
     * percept and keeps the literal's own annotations, so {@code fake(1)[source(alice)]}
     * would be believed as something alice said. No other annotation means anything to
     * Jason's belief base (the bridge adds none), so the others are kept as data.
     */
    public static final String RESERVED_ANNOTATION = "source";

    private Perceptions() {
    }

    /**
     * Parses within the default limits (a fresh {@link InputLimits}).
     *
     * @throws IllegalArgumentException with a message saying what is wrong
     */
    public static Literal parse(String text) {
        return parse(text, new InputLimits());
    }

    /**
     * @throws IllegalArgumentException with a message saying what is wrong
     */
    public static Literal parse(String text, InputLimits limits) {
        if (text == null || text.isBlank())
            throw new IllegalArgumentException("empty perception");
        String tooBig = InputLimits.checkText(text, limits.maxLiteralLength(), limits.maxNesting(), limits.maxTermDepth());
        if (tooBig != null)
            throw new IllegalArgumentException(tooBig);
        Literal literal;
        try {
            literal = JasonParser.literal(text.strip());
        } catch (Exception | Error e) { // the parser throws ParseException, its lexer TokenMgrError
            throw new IllegalArgumentException("not a Jason literal: " + firstLine(e.getMessage()));
        }
        String tooDeep = InputLimits.checkDepth(literal, limits.maxTermDepth());
        if (tooDeep != null)
            throw new IllegalArgumentException(tooDeep);
        if (literal.isRule())
            throw new IllegalArgumentException("a rule is not a perception");
        if (literal.getFunctor().startsWith("."))
            throw new IllegalArgumentException("an internal action is not a perception");
        if (!literal.isGround())
            throw new IllegalArgumentException("a perception must be ground (no variables)");
        String nonFinite = nonFinite(literal);
        if (nonFinite != null)
            throw new IllegalArgumentException("not a finite number: " + nonFinite);
        if (reserved(literal))
            throw new IllegalArgumentException("annotation " + RESERVED_ANNOTATION
                    + "(...) is reserved: Jason sets source(percept)");
        return literal;
    }

    /** Whether one of the literal's own annotations is source(...), of any arity (an argument's annotations are data). */
    static boolean reserved(Literal literal) {
        if (!literal.hasAnnot())
            return false;
        for (Term annot : literal.getAnnots())
            if (annot instanceof Atom a && RESERVED_ANNOTATION.equals(a.getFunctor()))
                return true;
        return false;
    }

    /**
     * The first number of a ground term (an expression counts as its value)
     * that is NaN or infinite, as Jason prints it; null if there is none.
     * Jason reads 1e999 as Infinity, and 1/0 or 0 mod 0 stay expressions
     * whose value is infinite or NaN. Walks without recursion.
     */
    static String nonFinite(Term term) {
        Deque<Term> todo = new ArrayDeque<>();
        todo.push(term);
        while (!todo.isEmpty()) {
            Term t = todo.pop();
            if (t.isNumeric() && t instanceof NumberTerm n) {
                double v;
                try {
                    v = n.solve();
                } catch (Exception e) {
                    continue; // not a number after all: left as it was
                }
                if (Double.isNaN(v) || Double.isInfinite(v))
                    return t.toString();
            } else if (t instanceof ListTerm l) {
                if (!l.isEmpty() && !t.isVar()) {
                    todo.push(l.getTerm());
                    if (l.getNext() != null)
                        todo.push(l.getNext());
                }
            } else if (t instanceof Structure s && !t.isVar()) {
                for (int i = 0; i < s.getArity(); i++)
                    todo.push(s.getTerm(i));
                if (t instanceof Literal lit && lit.hasAnnot())
                    todo.push(lit.getAnnots());
            }
        }
        return null;
    }

    private static String firstLine(String s) {
        if (s == null)
            return "parse error";
        int nl = s.indexOf('\n');
        return nl < 0 ? s : s.substring(0, nl);
    }
}
