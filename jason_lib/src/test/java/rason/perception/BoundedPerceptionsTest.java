package rason.perception;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.atomic.AtomicReference;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

import rason.core.InputLimits;

class BoundedPerceptionsTest {

    /**
     * Parses text on a thread with a small stack and says why it was refused,
     * failing if that took a second or more or overflowed the stack.
     */
    private static String refusedQuickly(String text, InputLimits limits) throws InterruptedException {
        AtomicReference<Throwable> thrown = new AtomicReference<>();
        long[] elapsed = new long[1];
        Thread t = new Thread(null, () -> {
            long t0 = System.nanoTime();
            try {
                Perceptions.parse(text, limits);
            } catch (Throwable e) {
                thrown.set(e);
            }
            elapsed[0] = System.nanoTime() - t0;
        }, "parse", 256 * 1024);
        t.start();
        t.join();
        assertTrue(thrown.get() instanceof IllegalArgumentException, "refused, not " + thrown.get());
        assertTrue(elapsed[0] < 1_000_000_000L, "took " + elapsed[0] / 1e6 + " ms");
        return thrown.get().getMessage();
    }

    @Test
    void aOneMegabyteLiteralIsRefusedAtOnce() throws Exception {
        String text = "name(\"" + "a".repeat(1 << 20) + "\")";
        assertEquals("longer than 4096 characters", refusedQuickly(text, new InputLimits()));
    }

    @Test
    void aHundredThousandDeepNestingIsRefusedAtOnce() throws Exception {
        String text = "f(".repeat(100_000) + "a" + ")".repeat(100_000);
        assertEquals("longer than 4096 characters", refusedQuickly(text, new InputLimits()));
        // and by its nesting when its length is allowed
        assertEquals("nesting deeper than 32",
                refusedQuickly(text, new InputLimits().setMaxLiteralLength(Integer.MAX_VALUE)));
    }

    @Test
    void nestingWithinTheLimitStillParses() {
        String text = "f(".repeat(32) + "a" + ")".repeat(32);
        assertEquals(text, Perceptions.parse(text).toString());
        assertThrows(IllegalArgumentException.class, () -> Perceptions.parse("g(" + text + ")"));
    }

    @Test
    void longListsAndOperatorChainsWithinTheLengthAreRefusedAsTooDeep() {
        for (String text : new String[] { "path([" + "a,".repeat(1500) + "a])", "x(1" + "+1".repeat(1500) + ")" }) {
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> Perceptions.parse(text));
            assertTrue(e.getMessage().startsWith("term deeper than 512 levels"), e.getMessage());
        }
        assertEquals(101, Perceptions.parse("path([" + "a,".repeat(100) + "a])").getTerm(0).toString().split(",").length);
    }

    // Jason reads 1e999 as Infinity; 1/0 and 0 mod 0 stay expressions worth Infinity and NaN
    @ParameterizedTest
    @ValueSource(strings = { "temp(1e999)", "temp(-1e999)", "temp(1.0E400)", "temp(1/0)", "temp(0 mod 0)",
            "temp(2**100000)", "temp(ok)[q(1e999)]", "temp([1,2,1e999])", "temp(s(t(1e999)))" })
    void numbersThatAreNotFiniteAreRefused(String text) {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> Perceptions.parse(text));
        assertTrue(e.getMessage().startsWith("not a finite number: "), e.getMessage());
    }

    @Test
    void finiteNumbersAndTheAtomsNanAndInfAreKept() {
        assertEquals("temp(1.0E308)", Perceptions.parse("temp(1e308)").toString());
        assertEquals("temp((-3.5),(1/2))", Perceptions.parse("temp(-3.5, 1/2)").toString());
        // lower-case nan and inf are atoms to Jason, not numbers; NaN is a variable (refused as not ground)
        assertEquals("temp(nan,inf)", Perceptions.parse("temp(nan, inf)").toString());
        assertThrows(IllegalArgumentException.class, () -> Perceptions.parse("temp(NaN)"));
    }
}
