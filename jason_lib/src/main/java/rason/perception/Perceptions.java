package rason.perception;

import java.io.StringReader;
import java.util.ArrayDeque;
import java.util.Deque;

import jason.asSyntax.Atom;
import jason.asSyntax.ListTerm;
import jason.asSyntax.Literal;
import jason.asSyntax.NumberTerm;
import jason.asSyntax.Structure;
import jason.asSyntax.Term;
import jason.asSyntax.parser.ParseException;
import jason.asSyntax.parser.as2j;
import jason.asSyntax.parser.as2jConstants;

import rason.core.InputLimits;

/** Parses the text of one perception into a Jason literal, refusing what cannot be a percept. */
public final class Perceptions {

    /**
     * The annotation a perception may not carry: Jason adds {@code source(percept)} to every
     * percept and keeps the literal's own annotations, so {@code fake(1)[source(alice)]}
     * would be believed as something alice said. No other annotation means anything to
     * Jason's belief base (the bridge adds none), so the others are kept as data.
     */
    public static final String RESERVED_ANNOTATION = "source";

    /**
     * One Jason parser per thread, re-read for each text: a new one per literal (as
     * {@code ASSyntax.parseLiteral} makes) cost more than the parsing itself (its buffers and
     * an exception with its stack trace, made at every construction).
     */
    private static final ThreadLocal<as2j> PARSER = ThreadLocal.withInitial(() -> new as2j(new StringReader("")));

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
            literal = parseLiteral(text.strip());
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

    /** As {@code ASSyntax.parseLiteral}, with this thread's parser. */
    private static Literal parseLiteral(String text) throws ParseException {
        as2j parser = PARSER.get();
        parser.ReInit(new StringReader(text));
        Literal literal = parser.literal();
        if (parser.getNextToken().kind != as2jConstants.EOF)
            throw new ParseException("Expected <EOF> after " + literal + " for parameter '" + text + "'");
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
