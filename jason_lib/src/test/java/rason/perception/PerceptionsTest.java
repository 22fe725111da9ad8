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

    @Test
    void missingPerceptionIsRefusedAsEmpty() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> Perceptions.parse(null));
        assertEquals("empty perception", e.getMessage());
    }
}
