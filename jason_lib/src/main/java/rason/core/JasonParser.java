package rason.core;

import java.io.StringReader;

import jason.asSyntax.Literal;
import jason.asSyntax.Term;
import jason.asSyntax.parser.ParseException;
import jason.asSyntax.parser.as2j;
import jason.asSyntax.parser.as2jConstants;

/**
 * Jason's parser for text that comes in all the time (perceptions, message contents): one
 * parser per thread, re-read for each text. A new one per text, as {@code ASSyntax.parseLiteral}
 * and {@code parseTerm} make, costs more than the parsing itself (its character buffers, its
 * directive processor, an exception with its stack trace, made at every construction).
 */
public final class JasonParser {

    private static final ThreadLocal<as2j> PARSER = ThreadLocal.withInitial(() -> new as2j(new StringReader("")));

    private JasonParser() {
    }

    /** As {@code ASSyntax.parseLiteral}, with this thread's parser. */
    public static Literal literal(String text) throws ParseException {
        as2j parser = reading(text);
        Literal literal = parser.literal();
        expectEnd(parser, literal, text);
        return literal;
    }

    /** As {@code ASSyntax.parseTerm}, with this thread's parser. */
    public static Term term(String text) throws ParseException {
        as2j parser = reading(text);
        Term term = parser.term();
        expectEnd(parser, term, text);
        return term;
    }

    private static as2j reading(String text) {
        as2j parser = PARSER.get();
        parser.ReInit(new StringReader(text));
        return parser;
    }

    private static void expectEnd(as2j parser, Term parsed, String text) throws ParseException {
        if (parser.getNextToken().kind != as2jConstants.EOF)
            throw new ParseException("Expected <EOF> after " + parsed + " for parameter '" + text + "'");
    }
}
