package rason.perception;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static rason.perception.Percepts.MS;
import static rason.perception.Percepts.S;

import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;

import jason.asSyntax.Literal;

import rason.core.InputLimits;

class PerceptionSourcesTest {

    private final PerceptionSources sources = new PerceptionSources();
    private final InputLimits limits = new InputLimits().setMaxSources(3);
    private final List<String> refused = new ArrayList<>();

    private List<Literal> parse(String source, long now, String... texts) {
        return sources.parse(source, texts, now, limits, (text, why) -> refused.add(text + ": " + why));
    }

    @Test
    void aLiteralRepeatedByTheNextMessageIsNotParsedAgain() {
        List<Literal> first = parse("cam", 0, "robot(a,1)", "battery(90)");
        List<Literal> second = parse("cam", 50 * MS, "robot(a,2)", "battery(90)");
        assertEquals("[robot(a,1), battery(90)]", first.toString());
        assertEquals("[robot(a,2), battery(90)]", second.toString());
        assertSame(first.get(1), second.get(1), "the same literal object: not parsed again");
        // only the previous message is remembered
        List<Literal> third = parse("cam", 100 * MS, "robot(a,1)");
        assertNotSame(first.get(0), third.get(0));
        assertEquals(first.get(0), third.get(0));
    }

    @Test
    void sourcesDoNotShareLiterals() {
        List<Literal> a = parse("a", 0, "door(open)");
        List<Literal> b = parse("b", 0, "door(open)");
        assertNotSame(a.get(0), b.get(0));
    }

    @Test
    void refusedTextsAreReportedEachTimeAndTheRestKept() {
        assertEquals("[ok(1)]", parse("s", 0, "bad(", "ok(1)").toString());
        assertEquals("[ok(1)]", parse("s", 1, "bad(", "ok(1)").toString());
        assertEquals(2, refused.size());
        assertTrue(refused.get(0).startsWith("bad(: not a Jason literal"), refused.get(0));
        refused.clear();
        parse("s", 2, "said(1)[source(alice)]");
        assertEquals(List.of("said(1)[source(alice)]: annotation source(...) is reserved: Jason sets source(percept)"),
                refused);
    }

    @Test
    void aNewSourceBeyondTheLimitIsRefusedWhileKnownOnesGoOn() {
        for (String s : List.of("a", "b", "c"))
            assertNotNull(parse(s, 0, "x(1)"));
        assertNull(parse("d", 0, "x(1)"), "a fourth source is refused");
        assertEquals(3, sources.size());
        assertEquals("[x(2)]", parse("a", 10 * MS, "x(2)").toString(), "a known source still updates");
        assertEquals(List.of(), parse("e", 10 * MS), "an empty list of an unknown source changes nothing");
        assertEquals(3, sources.size());
    }

    @Test
    void aClearedOrSilentSourceMakesRoom() {
        for (String s : List.of("a", "b", "c"))
            parse(s, 0, "x(1)");
        assertEquals(List.of(), parse("a", 1 * S));
        assertTrue(!sources.remembers("a"));
        assertNotNull(parse("d", 1 * S, "x(1)"));
        assertNull(parse("e", 1 * S, "x(1)"));
        sources.expire(2500 * MS, 2 * S); // b and c were heard at 0
        assertEquals(1, sources.size());
        assertNotNull(parse("e", 2500 * MS, "x(1)"));
    }

    @Test
    void aMessageWithNothingLeftForgetsItsSource() {
        parse("a", 0, "x(1)");
        assertEquals(List.of(), parse("a", 1, "bad("));
        assertTrue(!sources.remembers("a"));
    }

    @Test
    void aFloodOfDistinctSourcesStaysBounded() {
        InputLimits defaults = new InputLimits();
        int accepted = 0;
        for (int i = 0; i < 100_000; i++)
            if (sources.parse("flood_" + i, new String[] { "x(" + i + ")" }, i * MS, defaults, (t, w) -> {
            }) != null)
                accepted++;
        assertEquals(InputLimits.DEFAULT_MAX_SOURCES, accepted);
        assertEquals(InputLimits.DEFAULT_MAX_SOURCES, sources.size());
        sources.expire(100 * S, 2 * S);
        assertEquals(0, sources.size(), "all silent for longer than the TTL");
    }

    @Test
    void withoutTtlSourcesStayUntilCleared() {
        parse("a", 0, "x(1)");
        sources.expire(1000 * S, 0);
        assertTrue(sources.remembers("a"));
    }
}
