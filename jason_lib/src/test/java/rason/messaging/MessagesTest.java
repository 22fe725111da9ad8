package rason.messaging;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.function.Function;
import java.util.stream.Stream;

import org.junit.jupiter.api.Disabled;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.MethodSource;
import org.junit.jupiter.params.provider.NullAndEmptySource;
import org.junit.jupiter.params.provider.ValueSource;

import jason.asSemantics.Message;
import jason.asSyntax.ASSyntax;
import jason.asSyntax.Literal;
import jason.asSyntax.StringTerm;
import jason.asSyntax.Term;
import jason.asSyntax.parser.ParseException;

class MessagesTest {

    private static void assertRoundTrips(Term term) {
        String text = Messages.contentText(new Message("tell", "alice", "bob", term));
        Term back = Messages.parseContent(text);
        assertEquals(term, back, "sent as " + text);
        assertEquals(term.toString(), back.toString(), "sent as " + text);
    }

    // Jason text as an agent would write it; escapes are Java's, so "\\\"" is \" in the text.
    @ParameterizedTest
    @ValueSource(strings = {
            "hello",
            "hello(1)",
            "robot(faulty,-3.5,1.5,12)",
            "value(42)[source(bob),quality(high)]",
            "name(\"green \\\"big\\\" cylinder\")",
            "[a,b(1),\"c\"]",
            "ns1::pos(1,2)",
            "~door(open)",
            "42",
            "\"just text\"",
            "go(pos(1,2),[a,b])",
            "path(\"C:\\\\temp\")",
            "say(\"two\\nlines\\tand a tab\")",
            "said(x)[how(\"loudly, \\\"really\\\"\")]",
            "[p(\"a\\\"b\"),[q(\"c\\\\d\")]]",
            // beyond the Python cases
            "ns1::said(\"he \\\"hi\\\"\")[how(\"x\\ny\")]",
            "value(X,Y)[source(Z)]",
            "[a|T]",
            "[]",
            "\"\"",
            "p(\"\",[])",
    })
    void contentRoundTripsAsText(String content) throws ParseException {
        assertRoundTrips(ASSyntax.parseTerm(content));
    }

    /** Strings as an agent's program builds them: with a real quote, newline or tab in the value. */
    private static Stream<Arguments> stringsInEveryPlace() {
        List<String> values = List.of("say \"hi\"", "two\nlines", "\"\n\"", "tab\tand \u00e9 \u2713", "C:\\temp", "");
        List<Function<StringTerm, Term>> places = List.of(
                s -> s,
                s -> ASSyntax.createStructure("say", s),
                s -> ASSyntax.createList(ASSyntax.createAtom("a"), ASSyntax.createList(s)),
                s -> ASSyntax.createLiteral("said", ASSyntax.createAtom("x"))
                        .addAnnots(ASSyntax.createStructure("how", s)),
                s -> ASSyntax.createLiteral(ASSyntax.createAtom("ns1"), Literal.LNeg, "said", s)
                        .addAnnots(ASSyntax.createStructure("how", s)));
        return values.stream().flatMap(v -> places.stream()
                .map(place -> Arguments.of(place.apply(ASSyntax.createString(v)))));
    }

    @ParameterizedTest
    @MethodSource("stringsInEveryPlace")
    void stringsWithQuotesAndNewlinesRoundTripWherever(Term term) {
        assertRoundTrips(term);
    }

    @Test
    void aGeneratedPlanLabelLeavesWithTheProcessTagAndAWrittenOneAsItIs() throws Exception {
        jason.asSyntax.Plan generated = ASSyntax.parsePlan("@p__3[source(teacher)] +!greet(X) <- .print(X).");
        jason.asSyntax.Plan written = ASSyntax.parsePlan("@wave[source(teacher)] +!wave <- .print(hi).");
        generated.setAsPlanTerm(true); // as in an askHow's answer: { @label ... }
        written.setAsPlanTerm(true);
        Message m = new Message("tellHow", "teacher", "pupil", ASSyntax.createList(generated, written));
        Term back = Messages.parseContent(Messages.contentText(m));
        String text = back.toString();
        assertTrue(text.contains("@p__3_" + Messages.PROCESS_TAG + "[source(teacher)]"), text);
        assertTrue(text.contains("@wave[source(teacher)]"), text);
        assertFalse(text.contains("@p__3["), "another process has its own p__3: " + text);
        assertTrue(Messages.PROCESS_TAG.matches("[a-z0-9]+"), Messages.PROCESS_TAG);
    }

    @Test
    void sendingLeavesTheMessageContentAsItWas() {
        Term sent = ASSyntax.createLiteral("said", ASSyntax.createString("a \"b\""),
                ASSyntax.createList(ASSyntax.createString("c\nd"))).addAnnots(
                        ASSyntax.createStructure("how", ASSyntax.createString("\"e\"")));
        Term copy = sent.clone();
        Messages.contentText(new Message("tell", "alice", "bob", sent));
        assertEquals(copy, sent);
        assertEquals(copy.toString(), sent.toString());
    }

    @Test
    void contentThatIsNotATermTravelsAsItsText() {
        assertEquals("plain text", Messages.contentText(new Message("tell", "alice", "bob", "plain text")));
        assertEquals("", Messages.contentText(new Message("tell", "alice", "bob", null)));
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
            "''           | empty content",
            "'   '        | empty content",
            "foo(         | not a Jason term",
            "foo(a) bar   | not a Jason term",
            "@#!          | not a Jason term",
            // beyond the Python cases
            "a :- b       | not a Jason term",
            "+!g <- true. | not a Jason term",
    })
    void malformedContentIsRefusedWithAReason(String text, String why) {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> Messages.parseContent(text));
        assertTrue(e.getMessage().contains(why), e.getMessage());
        assertFalse(e.getMessage().contains("\n"), "a one-line reason: " + e.getMessage());
    }

    @Test
    void missingContentIsRefusedAsEmpty() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> Messages.parseContent(null));
        assertEquals("empty content", e.getMessage());
    }

    @Test
    void receivedMessageKeepsIdsSoAReplyFindsItsAsk() throws ParseException {
        Message m = Messages.toJason("tell", "bob", "alice", ASSyntax.parseTerm("secret(1)"), "mid7", "samid3");
        assertEquals("mid7", m.getMsgId());
        assertEquals("samid3", m.getInReplyTo());
        assertTrue(m.isReplyToSyncAsk());
        assertEquals("bob", m.getSender());
        assertEquals("alice", m.getReceiver());
        assertEquals("tell", m.getIlForce());
        assertEquals("secret(1)", m.getPropCont().toString());
    }

    @ParameterizedTest
    @NullAndEmptySource
    void receivedMessageWithoutIdGetsAFreshOne(String none) throws ParseException {
        Message m = Messages.toJason("achieve", "bob", "alice", ASSyntax.parseTerm("go"), none, none);
        assertTrue(m.getMsgId().startsWith("mid"), m.getMsgId());
        assertNull(m.getInReplyTo());
        Message other = Messages.toJason("achieve", "bob", "alice", ASSyntax.parseTerm("go"), none, none);
        assertNotEquals(m.getMsgId(), other.getMsgId());
    }

    @Disabled("bug: Jason's string syntax has no escape for a backslash at the end of a string, a backslash"
            + " before n or \", nor a carriage return; contentText sends such a value as it is, so the receiver"
            + " refuses the content (and drops the message) or reads another string")
    @ParameterizedTest
    @ValueSource(strings = { "C:\\", "a backslash then n: \\n", "a backslash then a quote: \\\"", "CR LF\r\n" })
    void everyStringValueRoundTrips(String value) {
        assertRoundTrips(ASSyntax.createStructure("say", ASSyntax.createString(value)));
    }
}
