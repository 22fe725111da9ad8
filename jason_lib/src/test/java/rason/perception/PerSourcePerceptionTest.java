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

class PerSourcePerceptionTest {

    @Test
    void firstListOfASourceIsPerceivedOnce() {
        PerSourcePerception table = new PerSourcePerception();
        assertTrue(table.update("cam_robots", lits("robot(a,1,2,3)"), 0));
        assertEquals(List.of("robot(a,1,2,3)"), texts(table.perceive()));
        assertNull(table.perceive()); // unchanged: Jason skips belief update
    }

    @Test
    void newListReplacesTheOldOneOfTheSameSourceOnly() {
        PerSourcePerception table = new PerSourcePerception();
        table.update("cam_robots", lits("robot(a,1,2,3)", "robot(b,1,2,3)"), 0);
        table.update("laser_walls", lits("wall(left)"), 0);
        table.perceive();
        assertTrue(table.update("cam_robots", lits("robot(a,5,2,3)"), 1));
        assertEquals(List.of("robot(a,5,2,3)", "wall(left)"), texts(table.perceive()));
    }

    @Test
    void sameListAgainIsNotAChangeButKeepsTheSourceAlive() {
        PerSourcePerception table = new PerSourcePerception();
        table.update("s", lits("p(1)"), 0);
        table.perceive();
        assertFalse(table.update("s", lits("p(1)"), 3 * S / 2));
        assertNull(table.perceive());
        assertFalse(table.expire(3 * S, 2 * S)); // heard at 1.5 s
        assertEquals(List.of("p(1)"), texts(table.current()));
    }

    @Test
    void emptyListClearsTheSource() {
        PerSourcePerception table = new PerSourcePerception();
        table.update("s", lits("p(1)"), 0);
        table.update("t", lits("q(1)"), 0);
        table.perceive();
        assertTrue(table.update("s", lits(), 1));
        assertEquals(List.of("q(1)"), texts(table.perceive()));
        assertFalse(table.update("s", lits(), 2)); // already empty
    }

    @Test
    void silentSourceExpiresAfterTheTtl() {
        PerSourcePerception table = new PerSourcePerception();
        table.update("s", lits("p(1)"), 0);
        table.update("t", lits("q(1)"), 3 * S / 2);
        table.perceive();
        assertFalse(table.expire(2 * S, 2 * S));
        assertTrue(table.expire(2_100_000_000L, 2 * S));
        assertEquals(List.of("q(1)"), texts(table.perceive()));
        assertEquals(List.of("t"), table.sourceNames());
    }

    @ParameterizedTest
    @ValueSource(longs = { 0, -1 })
    void ttlOfZeroOrLessNeverExpires(long ttl) {
        PerSourcePerception table = new PerSourcePerception();
        table.update("s", lits("p(1)"), 0);
        assertFalse(table.expire(1000 * S, ttl));
        assertEquals(List.of("p(1)"), texts(table.current()));
    }

    @Test
    void currentDoesNotConsumeTheChange() {
        PerSourcePerception table = new PerSourcePerception();
        table.update("s", lits("p(1)"), 0);
        assertEquals(List.of("p(1)"), texts(table.current()));
        assertEquals(List.of("p(1)"), texts(table.perceive()));
        assertEquals(List.of("p(1)"), texts(table.current()));
    }

    @Test
    void anExpiryIsPerceivedOnceAndAnExpiryWithNothingToForgetIsNoChange() {
        PerSourcePerception table = new PerSourcePerception();
        table.update("s", lits("p(1)"), 0);
        table.perceive();
        assertTrue(table.expire(3 * S, 2 * S));
        assertEquals(List.of(), texts(table.perceive()));
        assertFalse(table.expire(4 * S, 2 * S));
        assertNull(table.perceive());
    }
}
