package rason.perception;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static rason.perception.Percepts.S;
import static rason.perception.Percepts.lits;
import static rason.perception.Percepts.selection;
import static rason.perception.Percepts.texts;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Set;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;

class SelectivePerceptionTest {

    @Test
    void keepsOnlyTheDeclaredFunctors() {
        SelectivePerception m = new SelectivePerception(new PerSourcePerception(), selection("robot/4", "battery/1"));
        m.update("cam", lits("robot(a,1,2,3)", "robot(b)", "battery(50)", "temp(3)", "~battery(0,1)"), 0);
        assertEquals(List.of("battery(50)", "robot(a,1,2,3)"), texts(m.perceive()));
    }

    @Test
    void ignoresChangesOfUnwantedLiterals() {
        SelectivePerception m = new SelectivePerception(new PerSourcePerception(), selection("robot/4"));
        m.update("cam", lits("robot(a,1,2,3)", "temp(1)"), 0);
        m.perceive();
        assertFalse(m.update("cam", lits("robot(a,1,2,3)", "temp(2)"), 1));
        assertNull(m.perceive());
    }

    @Test
    void changeOfSelectionAppliesAtOnce() {
        SelectivePerception m = new SelectivePerception(new PerSourcePerception(), selection("robot/4"));
        m.update("cam", lits("robot(a,1,2,3)", "battery(50)"), 0);
        m.perceive();
        m.select(selection("battery/1"));
        assertEquals(List.of("battery(50)"), texts(m.perceive()));
        m.select(null);
        assertEquals(List.of("battery(50)", "robot(a,1,2,3)"), texts(m.perceive()));
    }

    @Test
    void withoutSelectionPassesEverything() {
        SelectivePerception m = new SelectivePerception(new AccumulatePerception(), null);
        m.update("cam", lits("robot(a,1,2,3)", "temp(1)"), 0);
        assertEquals(List.of("robot(a,1,2,3)", "temp(1)"), texts(m.perceive()));
        assertTrue(m.wants(Perceptions.parse("anything(1)")));
    }

    @Test
    void wantsIsWhatTheBridgeFiltersItsOwnPerceptsWith() {
        SelectivePerception m = new SelectivePerception(new PerSourcePerception(), selection("present/1"));
        assertTrue(m.wants(Perceptions.parse("present(bob)")));
        assertFalse(m.wants(Perceptions.parse("robot(a,1,2,3)")));
    }

    @Test
    void aNegatedLiteralIsWantedByItsFunctorAndArity() {
        SelectivePerception m = new SelectivePerception(new PerSourcePerception(),
                SelectivePerception.parseSelection("~door/1"));
        assertTrue(m.wants(Perceptions.parse("~door(open)")));
        assertTrue(m.wants(Perceptions.parse("door(closed)")));
        assertFalse(m.wants(Perceptions.parse("~door(open,left)")));
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
            "'robot/4, battery/1'  | battery/1,robot/4",
            "(robot/4)             | robot/4",
            "'\"robot/4\"'         | robot/4",
            "~door/1               | door/1",
            "' , '                 | ''",
            "robot/04              | robot/4",
            "' robot / 4 '         | robot/4",
    })
    void selectionParsing(String spec, String expected) {
        List<String> parsed = new ArrayList<>(SelectivePerception.parseSelection(spec));
        parsed.sort(null);
        List<String> wanted = expected.isEmpty() ? List.of() : Arrays.asList(expected.split(","));
        assertEquals(wanted, parsed);
    }

    @Test
    void selectionParsingJoinsSeveralEntries() {
        assertEquals(Set.of("robot/4", "battery/1", "temp/0"),
                SelectivePerception.parseSelection(List.of("robot/4", "battery/1, temp/0")));
    }

    @ParameterizedTest
    @ValueSource(strings = { "robot", "robot/", "/4", "Robot/4", "robot/x", "robot/4/5", "~/1", "robot/-1" })
    void selectionParsingRefusesWhatIsNotFunctorArity(String spec) {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> SelectivePerception.parseSelection(spec));
        assertTrue(e.getMessage().contains("functor/arity"), e.getMessage());
    }

    @Test
    void narrowingTheSelectionHidesAtOnceWhatTheWrappedManagerStillHolds() {
        SelectivePerception m = new SelectivePerception(new AccumulatePerception(), null); // replaces nothing
        m.update("cam", lits("robot(a,1,2,3)", "battery(50)"), 0);
        m.perceive();
        m.select(selection("battery/1"));
        assertEquals(List.of("battery(50)"), texts(m.perceive()));
        assertEquals(List.of("battery(50)"), texts(m.current()));
    }

    @Test
    void aSelectionChangeIsPerceivedOnceEvenWhenTheWrappedManagerSawNoChange() {
        SelectivePerception m = new SelectivePerception(new AccumulatePerception(), null);
        m.update("cam", lits("robot(a,1,2,3)"), 0);
        m.perceive();
        m.select(selection("temp/1")); // nothing of it heard: the accumulator gets an empty list, no change
        assertEquals(List.of(), texts(m.perceive()));
        assertNull(m.perceive());
    }

    @Test
    void aSelectionChangeDoesNotBringBackAnExpiredSource() {
        SelectivePerception m = new SelectivePerception(new PerSourcePerception(), selection("robot/4"));
        m.update("cam", lits("robot(a,1,2,3)", "battery(50)"), 0);
        m.perceive();
        assertTrue(m.expire(3 * S, 2 * S));
        m.select(selection("battery/1"));
        assertEquals(List.of(), texts(m.perceive()));
        assertEquals(List.of(), texts(m.current()));
    }

    @Test
    void aSelectionChangeDoesNotBringBackAClearedSource() {
        SelectivePerception m = new SelectivePerception(new PerSourcePerception(), selection("robot/4"));
        m.update("cam", lits("robot(a,1,2,3)", "battery(50)"), 0);
        m.update("cam", lits(), 1);
        m.select(null);
        assertEquals(List.of(), texts(m.current()));
    }

    @Test
    void reFilteringKeepsTheTimeTheSourceWasHeard() {
        SelectivePerception m = new SelectivePerception(new PerSourcePerception(), selection("robot/4"));
        m.update("cam", lits("robot(a,1,2,3)", "battery(50)"), 0);
        m.select(selection("battery/1")); // at 1.5 s, say: not a sign of life of cam
        assertFalse(m.expire(2 * S, 2 * S));
        assertTrue(m.expire(2 * S + 1, 2 * S));
        assertEquals(List.of(), texts(m.current()));
    }

    @Test
    void theSelectionIsACopyAndNullMeansEverything() {
        Set<String> chosen = selection("robot/4");
        SelectivePerception m = new SelectivePerception(new PerSourcePerception(), chosen);
        chosen.add("battery/1");
        assertEquals(Set.of("robot/4"), m.selection());
        assertFalse(m.wants(Perceptions.parse("battery(50)")));
        m.select(null);
        assertNull(m.selection());
        assertTrue(m.wants(Perceptions.parse("battery(50)")));
    }
}
