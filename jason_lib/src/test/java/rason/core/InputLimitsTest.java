package rason.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.junit.jupiter.api.Test;

import jason.asSyntax.ASSyntax;

class InputLimitsTest {

    private static String nested(int depth, String open, String close) {
        return open.repeat(depth) + "a" + close.repeat(depth);
    }

    @Test
    void textUpToTheLengthPassesAndOneMoreCharacterIsRefused() {
        String ok = "x(" + "a".repeat(4096 - 3) + ")";
        assertEquals(4096, ok.length());
        assertNull(InputLimits.checkText(ok, 4096, 32, 512));
        assertEquals("longer than 4096 characters", InputLimits.checkText(ok + " ", 4096, 32, 512));
    }

    @Test
    void everyKindOfBracketCountsTowardsTheNesting() {
        assertNull(InputLimits.checkText(nested(32, "f(", ")"), 4096, 32, 512));
        assertEquals("nesting deeper than 32", InputLimits.checkText(nested(33, "f(", ")"), 4096, 32, 512));
        assertEquals("nesting deeper than 32", InputLimits.checkText(nested(33, "[", "]"), 4096, 32, 512));
        assertEquals("nesting deeper than 32", InputLimits.checkText("x" + nested(11, "([{", "}])"), 4096, 32, 512));
    }

    @Test
    void closedBracketsDoNotAddUp() {
        assertNull(InputLimits.checkText("x(" + "f(a),".repeat(500) + "b)", 4096, 2, 512));
    }

    @Test
    void bracketsInStringsAndQuotedAtomsDoNotCount() {
        assertNull(InputLimits.checkText("x(\"" + "(".repeat(100) + "\")", 4096, 32, 512));
        assertNull(InputLimits.checkText("x('" + "[".repeat(100) + "')", 4096, 32, 512));
    }

    @Test
    void anEscapedQuoteDoesNotEndTheString() {
        // the string is "\"" : what follows it is outside and counts
        assertEquals("nesting deeper than 32",
                InputLimits.checkText("x(\"\\\"\", " + nested(32, "f(", ")") + ")", 4096, 32, 512));
        // an escaped quote followed by brackets is still inside the string
        assertNull(InputLimits.checkText("x(\"\\\"" + "(".repeat(100) + "\")", 4096, 32, 512));
    }

    @Test
    void aQuoteInACommentDoesNotHideTheBracketsAfterIt() {
        assertEquals("nesting deeper than 32",
                InputLimits.checkText("x(/* \" */ " + nested(32, "f(", ")") + " /* \" */)", 4096, 32, 512));
        assertEquals("nesting deeper than 32",
                InputLimits.checkText("x(a // \"\n, " + nested(32, "f(", ")") + ") // \"", 4096, 32, 512));
        assertNull(InputLimits.checkText("x(/* " + "(".repeat(100) + " */ a)", 4096, 32, 512));
    }

    @Test
    void longListsAndOperatorChainsAreDeepTerms() throws Exception {
        assertNull(InputLimits.checkDepth(ASSyntax.parseTerm("[" + "a,".repeat(100) + "a]"), 512));
        assertEquals("term deeper than 512 levels (each list element and operator counts one)",
                InputLimits.checkDepth(ASSyntax.parseTerm("[" + "a,".repeat(600) + "a]"), 512));
        assertEquals("term deeper than 512 levels (each list element and operator counts one)",
                InputLimits.checkDepth(ASSyntax.parseTerm("x(1" + "+1".repeat(600) + ")"), 512));
        assertEquals("term deeper than 512 levels (each list element and operator counts one)",
                InputLimits.checkDepth(ASSyntax.parseLiteral("x[" + annots(600) + "]"), 512));
        // arguments of one structure are side by side, not nested
        assertNull(InputLimits.checkDepth(ASSyntax.parseTerm("x(" + "a,".repeat(600) + "a)"), 512));
        assertNull(InputLimits.checkDepth(ASSyntax.parseTerm(nested(10, "f(", ")")), 11));
        assertEquals("term deeper than 10 levels (each list element and operator counts one)",
                InputLimits.checkDepth(ASSyntax.parseTerm(nested(10, "f(", ")")), 10));
    }

    private static String annots(int n) { // annotations are a set: equal ones are merged
        StringBuilder b = new StringBuilder("a0");
        for (int i = 1; i < n; i++)
            b.append(",a").append(i);
        return b.toString();
    }

    @Test
    void longListsAndOperatorChainsAreRefusedBeforeParsing() {
        String tooDeep = "term deeper than 512 levels (each list element and operator counts one)";
        assertEquals(tooDeep, InputLimits.checkText("x([" + "a,".repeat(600) + "a])", 4096, 32, 512));
        assertEquals(tooDeep, InputLimits.checkText("x(1" + "+1".repeat(600) + ")", 4096, 32, 512));
        assertEquals(tooDeep, InputLimits.checkText("x(" + "f([a,".repeat(10) + "1" + "*1".repeat(490) + "])".repeat(10) + ")",
                4096, 32, 512));
        // what closed brackets held no longer counts
        assertNull(InputLimits.checkText("x(" + "f([a,".repeat(10) + "a" + "])".repeat(10) + ", 1" + "*1".repeat(490)
                + ")", 4096, 32, 512));
        assertNull(InputLimits.checkText("x([" + "a,".repeat(400) + "a], [" + "a,".repeat(400) + "a])", 4096, 32, 512));
        assertNull(InputLimits.checkText("x(" + "a,".repeat(2000) + "a)", 4096, 32, 512));
        assertNull(InputLimits.checkText("x(\"" + "+,".repeat(1000) + "\")", 4096, 32, 512));
    }

    @Test
    void limitsBelowOneAreRefused() {
        InputLimits l = new InputLimits();
        assertThrows(IllegalArgumentException.class, () -> l.setMaxNesting(0));
        assertThrows(IllegalArgumentException.class, () -> l.setMaxLiteralLength(-1));
        assertThrows(IllegalArgumentException.class, () -> l.setMaxLiterals(0));
        assertThrows(IllegalArgumentException.class, () -> l.setMaxContentLength(0));
        assertThrows(IllegalArgumentException.class, () -> l.setMaxTermDepth(0));
        assertEquals(32, l.setMaxNesting(64).setMaxNesting(32).maxNesting());
    }

    @Test
    void defaults() {
        InputLimits l = new InputLimits();
        assertEquals(4096, l.maxLiteralLength());
        assertEquals(32, l.maxNesting());
        assertEquals(512, l.maxTermDepth());
        assertEquals(1000, l.maxLiterals());
        assertEquals(65536, l.maxContentLength());
    }

    @Test
    void abbreviation() {
        assertEquals("short", InputLimits.abbreviate("short", 10));
        assertEquals("aaaaa… (12 characters)", InputLimits.abbreviate("a".repeat(12), 5));
    }
}
