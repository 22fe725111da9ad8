package rason.action;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.stream.Stream;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.MethodSource;

import jason.asSyntax.ASSyntax;

class ActionTextTest {

    static Stream<Arguments> actions() {
        return Stream.of(
                Arguments.of("move(1)", new String[] { "1" }),
                Arguments.of("move(-0.3)", new String[] { "-0.3" }),
                Arguments.of("turn(5)", new String[] { "5" }),
                Arguments.of("turn(2.0)", new String[] { "2" }),
                Arguments.of("say(\"hello there\", bob)", new String[] { "hello there", "bob" }),
                Arguments.of("go(pos(1,2),[a,b])", new String[] { "pos(1,2)", "[a,b]" }),
                Arguments.of("stop", new String[0]));
    }

    @ParameterizedTest
    @MethodSource("actions")
    void parametersAreSentAsText(String action, String[] expected) throws Exception {
        assertArrayEquals(expected, ActionText.parametersOf(ASSyntax.parseStructure(action)));
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
            "no_progress    | no_progress",
            "bad_move       | bad_move",
            "blocked(left)  | blocked(left)",
            "Motor stalled! | failure_reason(\"Motor stalled!\")",
            "X              | failure_reason(\"X\")",
            "p[a]           | failure_reason(\"p[a]\")",
    })
    void failureReasonsBecomeAnnotations(String result, String literal) {
        assertEquals(literal, ActionText.reasonLiteral(result, new rason.core.InputLimits()).toString());
    }
}
