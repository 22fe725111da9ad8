package rason.action;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class ActionEventTest {

    @Test
    void okWithItsId() {
        assertEquals(new ActionEvent(false, 17, "OK"), ActionEvent.parse("action_feedback", new String[] { "OK", "17" }));
    }

    @Test
    void resultAndIdAreTrimmedAndExtraParametersIgnored() {
        assertEquals(new ActionEvent(false, 3, "no_progress"),
                ActionEvent.parse("action_feedback", new String[] { " no_progress ", " 3", "extra" }));
    }

    @Test
    void startedNamesItsAction() {
        assertEquals(new ActionEvent(true, 5, null), ActionEvent.parse("action_started", new String[] { " 5 " }));
    }

    @Test
    void startedWithoutAnIntegerIdIsRefused() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> ActionEvent.parse("action_started", new String[] { "x" }));
        assertTrue(e.getMessage().contains("non-integer action id 'x'"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> ActionEvent.parse("action_started", new String[0]));
        assertTrue(e.getMessage().contains("needs parameters [action_id]"), e.getMessage());
    }

    @Test
    void unknownEventTypeIsRefused() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> ActionEvent.parse("status", new String[] { "OK", "1" }));
        assertTrue(e.getMessage().contains("unknown event type 'status'"), e.getMessage());
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
            "OK          |             | needs parameters",
            "OK          | seven       | non-integer action id",
            "OK          | 1.5         | non-integer action id",
            "OK          | 2147483648  | action id 2147483648 outside 1..2147483647",
            "OK          | -2147483649 | outside 1..2147483647",
            "OK          | -1          | action id -1 outside 1..2147483647",
            "OK          | 0           | action id 0 outside 1..2147483647",
            "OK          | 00000000000000000000 | outside 1..2147483647",
            "OK          | 1e3         | non-integer action id '1e3'",
            "OK          | 0x10        | non-integer action id",
            "OK          | NaN         | non-integer action id",
            "OK          | '-'         | non-integer action id",
            "OK          | ''          | non-integer action id ''",
            "'  '        | 1           | empty result",
    })
    void malformedParametersAreRefusedWithAReason(String result, String id, String why) {
        String[] parameters = id == null ? new String[] { result } : new String[] { result, id };
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> ActionEvent.parse("action_feedback", parameters));
        assertTrue(e.getMessage().contains(why), e.getMessage());
    }

    @Test
    void idsFromOneToTheLargest32BitIntegerAreTaken() {
        assertEquals(1, ActionEvent.parse("action_feedback", new String[] { "OK", "1" }).actionId());
        assertEquals(Integer.MAX_VALUE, ActionEvent.parse("action_feedback", new String[] { "OK", "2147483647" }).actionId());
        assertEquals(12, ActionEvent.parse("action_feedback", new String[] { "OK", "+0012" }).actionId());
    }

    @Test
    void aMillionDigitIdIsRefusedQuicklyAndShownShort() {
        String id = "9".repeat(1_000_000);
        long t0 = System.nanoTime();
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> ActionEvent.parse("action_started", new String[] { id }));
        assertTrue(System.nanoTime() - t0 < 1_000_000_000L);
        assertTrue(e.getMessage().contains("outside 1..2147483647"), e.getMessage());
        assertTrue(e.getMessage().length() < 300, e.getMessage());
    }

    @Test
    void noParametersAtAllIsRefused() {
        assertThrows(IllegalArgumentException.class, () -> ActionEvent.parse("action_feedback", new String[0]));
        assertThrows(IllegalArgumentException.class, () -> ActionEvent.parse("action_feedback", null));
    }
}
