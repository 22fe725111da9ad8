package rason.perception;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static rason.perception.Percepts.S;
import static rason.perception.Percepts.lits;
import static rason.perception.Percepts.texts;

import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

class AccumulatePerceptionTest {

    @Test
    void addsEveryMessageAndReplacesNothing() {
        AccumulatePerception m = new AccumulatePerception();
        assertTrue(m.update("a", lits("p(1)"), 0));
        assertTrue(m.update("a", lits("p(2)"), 1));
        assertTrue(m.update("b", lits("q(1)"), 2));
        assertEquals(List.of("p(1)", "p(2)", "q(1)"), texts(m.perceive()));
    }

    @Test
    void countsEveryMessageAsAChange() {
        AccumulatePerception m = new AccumulatePerception();
        m.update("a", lits("p(1)"), 0);
        m.perceive();
        assertTrue(m.update("a", lits("p(1)"), 1)); // same content: Jason still runs its belief update
        assertEquals(List.of("p(1)"), texts(m.perceive()));
        assertFalse(m.update("a", lits(), 2)); // an empty list clears nothing
        assertNull(m.perceive());
    }

    @Test
    void forgetsLiteralsNotHeardWithinTheTtl() {
        AccumulatePerception m = new AccumulatePerception();
        m.update("a", lits("p(1)"), 0);
        m.update("a", lits("p(2)"), S);
        assertTrue(m.expire(5 * S / 2, 2 * S));
        assertEquals(List.of("p(2)"), texts(m.current()));
    }

    @Test
    void hearingALiteralAgainKeepsItAlive() {
        AccumulatePerception m = new AccumulatePerception();
        m.update("a", lits("p(1)", "q(1)"), 0);
        m.update("b", lits("p(1)"), 3 * S / 2); // from any source
        assertTrue(m.expire(5 * S / 2, 2 * S));
        assertEquals(List.of("p(1)"), texts(m.current()));
    }

    @Test
    void anExpiryIsAChangeOnlyWhenSomethingIsForgotten() {
        AccumulatePerception m = new AccumulatePerception();
        m.update("a", lits("p(1)"), 0);
        m.perceive();
        assertFalse(m.expire(S, 2 * S));
        assertNull(m.perceive());
        assertTrue(m.expire(3 * S, 2 * S));
        assertEquals(List.of(), texts(m.perceive()));
    }

    @ParameterizedTest
    @ValueSource(longs = { 0, -1 })
    void ttlOfZeroOrLessNeverForgets(long ttl) {
        AccumulatePerception m = new AccumulatePerception();
        m.update("a", lits("p(1)"), 0);
        assertFalse(m.expire(1000 * S, ttl));
        assertEquals(List.of("p(1)"), texts(m.current()));
    }

    @Test
    void aFloodOfNewLiteralsKeepsTheMostRecentlyHeard() {
        AccumulatePerception m = new AccumulatePerception(3);
        m.update("a", lits("p(1)", "p(2)", "p(3)"), 0);
        m.update("a", lits("p(1)"), 1); // heard again: now the most recent
        m.update("a", lits("p(4)"), 2);
        assertEquals(List.of("p(1)", "p(3)", "p(4)"), texts(m.current()));
        for (int i = 0; i < 100_000; i++)
            m.update("flood", lits("f(" + i + ")"), 3 + i);
        assertEquals(List.of("f(99997)", "f(99998)", "f(99999)"), texts(m.current()));
    }

    @Test
    void theDefaultBoundHoldsWithoutTtl() {
        AccumulatePerception m = new AccumulatePerception();
        for (int i = 0; i < 3 * AccumulatePerception.DEFAULT_MAX_LITERALS; i++)
            m.update("flood", lits("f(" + i + ")"), i);
        assertFalse(m.expire(Long.MAX_VALUE / 2, 0));
        assertEquals(AccumulatePerception.DEFAULT_MAX_LITERALS, m.current().size());
    }

    @Test
    void expiryOfTheOldestStopsAtTheFirstOneAlive() {
        AccumulatePerception m = new AccumulatePerception();
        m.update("a", lits("p(1)"), 0);
        m.update("a", lits("p(2)"), 2 * S);
        m.update("a", lits("p(1)"), 3 * S); // p(1) heard again after p(2)
        assertFalse(m.expire(4 * S, 2 * S));
        assertTrue(m.expire(9 * S / 2, 2 * S));
        assertEquals(List.of("p(1)"), texts(m.current()));
    }
}
