package rason;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

import jason.asSemantics.Unifier;
import jason.asSyntax.ASSyntax;
import jason.asSyntax.NumberTerm;
import jason.asSyntax.Term;
import jason.asSyntax.VarTerm;
import java.nio.file.Path;

import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;

import jason.asSemantics.TransitionSystem;
import rason.bridge.Bridge;
import rason.bridge.RunningAgents;

/** rason.ros_time_ms reads the ROS time the node pushed; rason.time_ms the monotonic clock. */
class ClockReadingTest {

    private final Bridge bridge = new Bridge();
    @RegisterExtension
    final RunningAgents agents = new RunningAgents(bridge);

    @TempDir
    Path dir;

    private static double read(ClockReading clock, TransitionSystem ts) throws Exception {
        Unifier u = new Unifier();
        VarTerm t = new VarTerm("T");
        assertTrue((Boolean) clock.execute(ts, u, new Term[] { t }));
        return ((NumberTerm) u.get(t)).solve();
    }

    private static double read(ClockReading clock) throws Exception {
        return read(clock, null);
    }

    @Test
    void rosTimeIsTheTimeTheNodePushedInMilliseconds() throws Exception {
        TransitionSystem ts = agents.start(dir, "reader", "ready.\n").getTS();
        bridge.tick(123_456_789_000L);
        assertEquals(123456.789, read(new ros_time_ms(), ts), 1e-9);
        bridge.tick(123_500_000_000L);
        assertEquals(123500.0, read(new ros_time_ms(), ts), 1e-9);
    }

    @Test
    void monotonicTimeGoesOn() throws Exception {
        double first = read(new time_ms());
        Thread.sleep(5);
        assertTrue(read(new time_ms()) >= first + 4.0);
    }

    @Test
    void aBoundArgumentThatDiffersDoesNotUnify() throws Exception {
        TransitionSystem ts = agents.start(dir, "reader", "ready.\n").getTS();
        bridge.tick(1_000_000_000L);
        Unifier u = new Unifier();
        assertFalse((Boolean) new ros_time_ms().execute(ts, u, new Term[] { ASSyntax.createNumber(5) }));
        assertTrue((Boolean) new ros_time_ms().execute(ts, u, new Term[] { ASSyntax.createNumber(1000) }));
    }
}
