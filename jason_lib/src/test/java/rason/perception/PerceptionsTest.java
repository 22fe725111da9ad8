package rason.perception;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class PerceptionsTest {

    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
            "robot(faulty,-3.5,1.5,12) | robot(faulty,(-3.5),1.5,12)", // Jason's own spelling
            "'  hot '                  | hot",
            "~door(open)               | ~door(open)",
            "pos(a)[quality(high)]     | pos(a)[quality(high)]",
            "name(\"green cylinder\")  | name(\"green cylinder\")",
    })
    void validPerceptionsParse(String text, String expected) {
        assertEquals(expected, Perceptions.parse(text).toString());
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
            "robot(         | not a Jason literal",
            "robot(a) extra | not a Jason literal",
            "''             | empty",
            "'   '          | empty",
            "robot(X, 1)    | ground",
            "a :- b         | not a Jason literal",
            ".print(x)      | internal action",
            "123            | not a Jason literal",
            "robot(@#)      | not a Jason literal",
    })
    void malformedPerceptionsAreRefusedWithAReason(String text, String why) {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> Perceptions.parse(text));
        assertTrue(e.getMessage().contains(why), e.getMessage());
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
            "fake(1)[source(alice)]",
            "~fake(1)[source(bob)]",
            "fake(1)[source(percept)]",
            "fake(1)[quality(high),source(self)]",
            "fake(1)[source]",
            "fake(1)[source(a,b)]",
    })
    void sourceAnnotationsAreReserved(String text) {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> Perceptions.parse(text));
        assertEquals("annotation source(...) is reserved: Jason sets source(percept)", e.getMessage());
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
            "fact(1)[certainty(0.9)]        | fact(1)[certainty(0.9)]",
            "fact(said(x)[source(alice)])   | fact(said(x)[source(alice)])", // an argument's annotations are data
            "fact(1)[sources(2)]            | fact(1)[sources(2)]",
            "fact(1)[\"source\"]            | fact(1)[\"source\"]",
    })
    void otherAnnotationsAreData(String text, String expected) {
        assertEquals(expected, Perceptions.parse(text).toString());
    }

    @Test
    void missingPerceptionIsRefusedAsEmpty() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> Perceptions.parse(null));
        assertEquals("empty perception", e.getMessage());
    }

    @Test
    void aRefusedTextLeavesTheThreadsParserReadyForTheNext() {
        for (String bad : new String[] {"robot(", "robot(a) extra", "robot(@#)", "\"open"})
            assertThrows(IllegalArgumentException.class, () -> Perceptions.parse(bad));
        assertEquals("robot(a,[1,2],\"s\")[q(1)]", Perceptions.parse("robot(a, [1,2], \"s\")[q(1)]").toString());
        assertEquals(jason.asSyntax.ASSyntax.createAtom("hot"), Perceptions.parse("hot"));
    }
}
