package rason.perception;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static rason.perception.Percepts.MS;
import static rason.perception.Percepts.S;
import static rason.perception.Percepts.lits;
import static rason.perception.Percepts.selection;
import static rason.perception.Percepts.texts;

import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

class RateLimitedPerceptionTest {

    /** One update per 200 ms and source. */
    private static RateLimitedPerception fivePerSecond() {
        return new RateLimitedPerception(new PerSourcePerception(), 5.0);
    }

    @Test
    void passesTheFirstUpdateAndHoldsTheBurst() {
        RateLimitedPerception m = fivePerSecond();
        assertTrue(m.update("cam", lits("n(1)"), 0));
        for (int k = 2; k < 10; k++)
            assertFalse(m.update("cam", lits("n(" + k + ")"), k * 10 * MS), "update " + k);
        assertEquals(List.of("n(1)"), texts(m.perceive()));
        assertFalse(m.expire(150 * MS, 0)); // window not over
        assertTrue(m.expire(200 * MS, 0)); // the newest held update, not the first held
        assertEquals(List.of("n(9)"), texts(m.perceive()));
    }

    @Test
    void isPerSource() {
        RateLimitedPerception m = fivePerSecond();
        assertTrue(m.update("a", lits("p(1)"), 0));
        assertTrue(m.update("b", lits("q(1)"), MS));
        assertFalse(m.update("a", lits("p(2)"), 2 * MS));
        assertEquals(List.of("p(1)", "q(1)"), texts(m.current()));
    }

    @Test
    void letsUpdatesThroughAtTheDeclaredRate() {
        RateLimitedPerception m = fivePerSecond();
        int applied = 0;
        for (int k = 0; k < 100; k++) { // 100 Hz for one second, ticks every 50 ms
            long now = k * 10 * MS;
            if (m.update("cam", lits("n(" + k + ")"), now))
                applied++;
            if (k % 5 == 0 && m.expire(now, 0))
                applied++;
        }
        m.expire(S + 200 * MS, 0);
        assertTrue(applied >= 4 && applied <= 6, "applied " + applied);
        assertEquals(List.of("n(99)"), texts(m.current())); // nothing stale sticks
    }

    @Test
    void aHeldClearIsAppliedToo() {
        RateLimitedPerception m = fivePerSecond();
        m.update("a", lits("p(1)"), 0);
        assertFalse(m.update("a", lits(), 10 * MS));
        assertTrue(m.expire(200 * MS, 0));
        assertEquals(List.of(), texts(m.current()));
    }

    @ParameterizedTest
    @ValueSource(doubles = { 0.0, -1.0, Double.POSITIVE_INFINITY, Double.NaN, Double.NEGATIVE_INFINITY })
    void refusesARateThatIsNotPositive(double rate) {
        PerSourcePerception inner = new PerSourcePerception();
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> new RateLimitedPerception(inner, rate));
        assertTrue(e.getMessage().contains("positive"), e.getMessage());
    }

    @Test
    void anUpdateAfterTheWindowGoesThroughAndDropsTheHeldOne() {
        RateLimitedPerception m = fivePerSecond();
        m.update("a", lits("p(1)"), 0);
        assertFalse(m.update("a", lits("p(2)"), 10 * MS)); // held, never ticked out
        assertTrue(m.update("a", lits("p(3)"), 250 * MS));
        assertEquals(List.of("p(3)"), texts(m.current()));
        assertFalse(m.expire(500 * MS, 0)); // the held p(2) is stale: not applied after p(3)
        assertEquals(List.of("p(3)"), texts(m.current()));
    }

    @Test
    void aHeldUpdateCountsAsHeardWhenItArrivedNotWhenItWasApplied() {
        RateLimitedPerception m = fivePerSecond();
        m.update("a", lits("p(1)"), 0);
        m.update("a", lits("p(2)"), 100 * MS);
        assertTrue(m.expire(200 * MS, S)); // applied at 200 ms
        assertEquals(List.of("p(2)"), texts(m.current()));
        assertFalse(m.expire(1100 * MS, S)); // heard at 100 ms: exactly the TTL
        assertTrue(m.expire(1100 * MS + 1, S));
        assertEquals(List.of(), texts(m.current()));
    }

    @Test
    void silentSourcesAreForgottenByTheWrappedManager() {
        RateLimitedPerception m = fivePerSecond();
        m.update("a", lits("p(1)"), 0);
        m.update("b", lits("q(1)"), 2 * S);
        assertTrue(m.expire(3 * S, 2 * S));
        assertEquals(List.of("q(1)"), texts(m.current()));
    }

    @Test
    void wantsWhatTheWrappedManagerWants() {
        RateLimitedPerception m = new RateLimitedPerception(
                new SelectivePerception(new PerSourcePerception(), selection("present/1")), 5.0);
        assertTrue(m.wants(Perceptions.parse("present(bob)")));
        assertFalse(m.wants(Perceptions.parse("robot(a,1,2,3)")));
    }
}
