package rason.mind;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;

/** When an agent's state is read for jason/mind, and what counts as a change (no Jason needed). */
class MindRecorderTest {

    private static final long PERIOD = 1_000_000_000L;

    private final MindRecorder recorder = new MindRecorder();
    private List<String> beliefs = List.of("a");
    private long cycle = 0;
    private int reads = 0;

    private final MindRecorder.Reader reader = (events, messages) -> {
        reads++;
        return new AgentMind("bob", ++cycle, cycle * 10, beliefs, List.of(), List.of(), List.of(), List.of(), events.items(),
                messages.items(), 0);
    };

    @Test
    void theFirstCycleIsReadThenAtMostOncePerPeriod() {
        assertTrue(recorder.cycleEnded(PERIOD, 0, reader));
        assertFalse(recorder.cycleEnded(PERIOD, PERIOD / 2, reader));
        assertFalse(recorder.cycleEnded(PERIOD, PERIOD - 1, reader));
        assertTrue(recorder.cycleEnded(PERIOD, PERIOD, reader));
        assertEquals(2, reads);
    }

    @Test
    void goingToSleepReadsTheStateCyclesLeftUnread() {
        recorder.cycleEnded(PERIOD, 0, reader);
        assertFalse(recorder.goingToSleep(1, reader), "nothing ran since the last read");
        beliefs = List.of("a", "b");
        recorder.cycleEnded(PERIOD, 2, reader); // within the period: not read
        assertTrue(recorder.goingToSleep(3, reader));
        assertEquals(List.of("a", "b"), recorder.latest().beliefs());
    }

    @Test
    void onlyAChangeOtherThanTheCycleCountMakesANewVersion() {
        recorder.cycleEnded(PERIOD, 0, reader);
        AgentMind first = recorder.latest();
        assertEquals(1, recorder.version());
        recorder.cycleEnded(PERIOD, PERIOD, reader); // same beliefs, new cycle count
        assertEquals(1, recorder.version());
        assertSame(first, recorder.latest());
        beliefs = List.of("c");
        recorder.cycleEnded(PERIOD, 2 * PERIOD, reader);
        assertEquals(2, recorder.version());
        assertEquals(List.of("c"), recorder.latest().beliefs());
    }

    @Test
    void aRequestReadsAtTheNextCycleWhateverThePeriod() {
        recorder.cycleEnded(PERIOD, 0, reader);
        recorder.request();
        assertTrue(recorder.cycleEnded(PERIOD, 1, reader));
        assertFalse(recorder.cycleEnded(PERIOD, 2, reader));
    }

    @Test
    void eventsAndMessagesAreTheNewestFewCutToLength() {
        for (int i = 0; i < MindRecorder.RECENT + 5; i++)
            recorder.event("+e" + i);
        recorder.message("x".repeat(10 * MindRecorder.RECENT_CHARS));
        recorder.cycleEnded(PERIOD, 0, reader);
        List<String> events = recorder.latest().events();
        assertEquals(MindRecorder.RECENT, events.size());
        assertEquals("+e5", events.get(0));
        assertEquals("+e" + (MindRecorder.RECENT + 4), events.get(events.size() - 1));
        String message = recorder.latest().messages().get(0);
        assertEquals(MindRecorder.RECENT_CHARS, message.length());
        assertTrue(message.endsWith("…"));
    }

    @Test
    void nothingBeforeTheFirstRead() {
        assertNull(recorder.latest());
        assertEquals(0, recorder.version());
    }

    @Test
    void badBoundsAreRefused() {
        assertThrows(IllegalArgumentException.class, () -> new RecentItems(0, 10));
        assertThrows(IllegalArgumentException.class, () -> new MindReader(0, 100));
        assertThrows(IllegalArgumentException.class, () -> new MindReader(10, 3));
    }
}
