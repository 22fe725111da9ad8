package rason.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.junit.jupiter.api.Test;

import jason.asSyntax.ASSyntax;
import jason.asSyntax.parser.ParseException;
import jason.asSyntax.parser.TokenMgrError;

class JasonParserTest {

    @Test
    void readsWhatJasonsOwnParserReads() throws Exception {
        for (String text : new String[] { "p(a, 1.5, \"s\", [x, y(2)])[src(cam)]", "~q", "-7", "[a | T]", "X + 2 * 3" }) {
            assertEquals(ASSyntax.parseTerm(text), JasonParser.term(text), text);
        }
        assertEquals(ASSyntax.parseLiteral("seen(r1, 30)[d(2)]"), JasonParser.literal("seen(r1, 30)[d(2)]"));
    }

    @Test
    void aTextThatDoesNotParseLeavesTheNextOneUnharmed() throws Exception {
        assertThrows(ParseException.class, () -> JasonParser.term("p(a,"));
        assertThrows(TokenMgrError.class, () -> JasonParser.term("p(\"unterminated"));
        assertThrows(ParseException.class, () -> JasonParser.literal("p(a) q(b)"), "text after the literal");
        assertEquals(ASSyntax.parseTerm("ok(1)"), JasonParser.term("ok(1)"));
        assertEquals(ASSyntax.parseLiteral("ok(2)"), JasonParser.literal("ok(2)"));
    }
}
