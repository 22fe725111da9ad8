package rason.perception;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class PerceptionsTest {

    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
            "robot(faulty,-3.5,1.5,12) | robot(faulty,(-3.5),1.5,12)",
            "'  hot '                  | hot",
            "pos(a)[quality(high)]     | pos(a)[quality(high)]",
    })
    void validPerceptionsParse(String text, String expected) {
        assertEquals(expected, Perceptions.parse(text).toString());
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
            "robot(     | not a Jason literal",
            "robot(X,1) | ground",
            ".print(x)  | internal action",
    })
    void malformedPerceptionsAreRefusedWithAReason(String text, String why) {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> Perceptions.parse(text));
        assertTrue(e.getMessage().contains(why), e.getMessage());
    }
}
