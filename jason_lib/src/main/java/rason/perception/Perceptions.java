package rason.perception;

import jason.asSyntax.ASSyntax;
import jason.asSyntax.Literal;

/** Parses the text of one perception into a Jason literal, refusing what cannot be a percept. */
public final class Perceptions {

    private Perceptions() {
    }

    /**
     * @throws IllegalArgumentException with a message saying what is wrong
     */
    public static Literal parse(String text) {
        if (text == null || text.isBlank())
            throw new IllegalArgumentException("empty perception");
        Literal literal;
        try {
            literal = ASSyntax.parseLiteral(text.strip());
        } catch (Exception | Error e) { // the parser throws ParseException, its lexer TokenMgrError
            throw new IllegalArgumentException("not a Jason literal: " + firstLine(e.getMessage()));
        }
        if (literal.isRule())
            throw new IllegalArgumentException("a rule is not a perception");
        if (literal.getFunctor().startsWith("."))
            throw new IllegalArgumentException("an internal action is not a perception");
        if (!literal.isGround())
            throw new IllegalArgumentException("a perception must be ground (no variables)");
        return literal;
    }

    private static String firstLine(String s) {
        if (s == null)
            return "parse error";
        int nl = s.indexOf('\n');
        return nl < 0 ? s : s.substring(0, nl);
    }
}
