package rason;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

import jason.asSemantics.Unifier;
import jason.asSyntax.ASSyntax;
import jason.asSyntax.NumberTerm;
import jason.asSyntax.Term;
import jason.asSyntax.VarTerm;
import rason.bridge.Bridge;

/** rason.ros_time_ms reads the ROS time the node pushed; rason.time_ms the monotonic clock. */
class ClockReadingTest {

    private final Bridge bridge = Bridge.get();

    @AfterEach
    void detach() {
        bridge.detach();
    }

    private static double read(ClockReading clock) throws Exception {
        Unifier u = new Unifier();
        VarTerm t = new VarTerm("T");
        assertTrue((Boolean) clock.execute(null, u, new Term[] { t }));
        return ((NumberTerm) u.get(t)).solve();
    }

    @Test
    void rosTimeIsTheTimeTheNodePushedInMilliseconds() throws Exception {
        bridge.attach();
        bridge.tick(123_456_789_000L);
        assertEquals(123456.789, read(new ros_time_ms()), 1e-9);
        bridge.tick(123_500_000_000L);
        assertEquals(123500.0, read(new ros_time_ms()), 1e-9);
    }

    @Test
    void monotonicTimeGoesOn() throws Exception {
        double first = read(new time_ms());
        Thread.sleep(5);
        assertTrue(read(new time_ms()) >= first + 4.0);
    }

    @Test
    void aBoundArgumentThatDiffersDoesNotUnify() throws Exception {
        bridge.attach();
        bridge.tick(1_000_000_000L);
        Unifier u = new Unifier();
        assertFalse((Boolean) new ros_time_ms().execute(null, u, new Term[] { ASSyntax.createNumber(5) }));
        assertTrue((Boolean) new ros_time_ms().execute(null, u, new Term[] { ASSyntax.createNumber(1000) }));
    }
}
