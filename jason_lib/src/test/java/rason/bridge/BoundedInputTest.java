package rason.bridge;

import rason.core.InputLimits;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.Arrays;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;

import rason.RosAgArch;
import rason.core.RateLimitedLog;

/** Hostile perceptions through the bridge to a running agent. */
class BoundedInputTest {

    @TempDir
    Path dir;

    private final Bridge bridge = new Bridge();
    @RegisterExtension
    final RunningAgents agents = new RunningAgents(bridge);
    @RegisterExtension
    final CapturedLog log = new CapturedLog("rason.bridge");

    @Test
    void hostilePerceptionsAreDroppedAndTheAgentGoesOn() throws Exception {
        RosAgArch arch = agents.start(dir, "bob", "+go <- +went.\n");
        log.attach();

        String[] tooMany = new String[1001];
        Arrays.fill(tooMany, "x(1)");
        assertEquals(0, bridge.perception().perceive("flood", tooMany, 100 * RunningAgents.SECOND));
        assertTrue(log.containing("dropped perception message from source 'flood': 1001 literals, more than 1000") <= 1);

        String deep = "f(".repeat(100_000) + "a" + ")".repeat(100_000);
        String[] bad = new String[50];
        Arrays.fill(bad, deep);
        assertEquals(0, bridge.perception().perceive("deep", bad, 100 * RunningAgents.SECOND));
        assertTrue(log.containing("from source 'deep'") <= RateLimitedLog.DEFAULT_LINES,
                "at most a few lines per period: " + log.lines().size());
        assertTrue(log.lines().stream().allMatch(l -> l.length() < 1000), "no line echoes a whole literal");

        String[] many = new String[1000];
        for (int i = 0; i < many.length; i++)
            many[i] = "x(" + i + ")";
        assertEquals(1000, bridge.perception().perceive("many", many, 100 * RunningAgents.SECOND));
        assertEquals(1, bridge.perception().perceive("s", new String[] { "go" }, 100 * RunningAgents.SECOND));
        RunningAgents.await("the agent reacts to go", () -> RunningAgents.believes(arch, "went"));
        assertTrue(RunningAgents.believes(arch, "x(999)"));
    }

    @Test
    void aPerceptionCannotSayWhoSaidIt() throws Exception {
        RosAgArch arch = agents.start(dir, "bob", "+go <- +went.\n");
        log.attach();
        assertEquals(2, bridge.perception().perceive("synth", new String[] { "fake(1)[source(alice)]", "~fake(2)[source(self)]",
                "real(1)[certainty(0.9)]", "go" }, 100 * RunningAgents.SECOND));
        RunningAgents.await("the agent reacts to go", () -> RunningAgents.believes(arch, "went"));
        assertTrue(RunningAgents.believes(arch, "real(1)[certainty(0.9),source(percept)]"));
        assertTrue(!RunningAgents.believes(arch, "fake(1)") && !RunningAgents.believes(arch, "~fake(2)"));
        assertEquals(2, log.containing("annotation source(...) is reserved: Jason sets source(percept)"));
        assertEquals(1, log.containing("dropped perception 'fake(1)[source(alice)]' from source 'synth'"));
    }

    @Test
    void aFloodOfNewSourcesIsBoundedAndKnownSourcesGoOn() throws Exception {
        RosAgArch arch = agents.start(dir, "bob", "+go <- +went.\n");
        log.attach();
        bridge.perception().setTtlNanos(2 * RunningAgents.SECOND);
        assertEquals(1, bridge.perception().perceive("known", new String[] { "early(1)" }, 100 * RunningAgents.SECOND));
        assertEquals(0, bridge.perception().perceive("s".repeat(InputLimits.MAX_SOURCE_LENGTH + 1), new String[] { "x(1)" },
                100 * RunningAgents.SECOND));
        assertTrue(log.containing("source name longer than 256 characters") == 1, log.lines().toString());
        int max = bridge.limits().maxSources();
        for (int i = 0; i < 3 * max; i++)
            bridge.perception().perceive("flood_" + i, new String[] { "s(" + i + ")" }, 100 * RunningAgents.SECOND);
        assertEquals(max, bridge.perception().sources());
        assertTrue(log.containing("more than " + max + " sources heard within ~perception_ttl and this one is new")
                <= RateLimitedLog.DEFAULT_LINES);
        assertEquals(2, bridge.perception().perceive("known", new String[] { "early(1)", "go" }, 100 * RunningAgents.SECOND));
        RunningAgents.await("the agent reacts to go", () -> RunningAgents.believes(arch, "went"));
        assertTrue(RunningAgents.believes(arch, "early(1)"));
        bridge.tick(103 * RunningAgents.SECOND); // all silent for longer than the TTL (2 s)
        assertEquals(0, bridge.perception().sources());
        assertEquals(1, bridge.perception().perceive("late", new String[] { "late(1)" }, 103 * RunningAgents.SECOND));
    }

    @Test
    void eventsWithBadIdsOrHugeNamesAreIgnoredWithAReason() throws Exception {
        agents.start(dir, "bob", "+go <- +went.\n");
        log.attach();
        for (String id : new String[] { "2147483648", "-1", "0", "abc", "1e3", "9".repeat(100_000) }) {
            assertTrue(!bridge.actions().event("bob", "action_feedback", new String[] { "OK", id }));
            assertTrue(!bridge.actions().event("bob", "action_started", new String[] { id }, "/decomposer"));
        }
        assertTrue(log.containing("action id 2147483648 outside 1..2147483647") == 2, log.lines().toString());
        assertTrue(log.containing("non-integer action id '1e3'") == 2, log.lines().toString());
        String huge = "n".repeat(1 << 20);
        for (int i = 0; i < 20; i++)
            assertTrue(!bridge.actions().event(huge + i, "action_feedback", new String[] { "OK", "1" }));
        assertTrue(log.lines().stream().allMatch(l -> l.length() < 1000), "no line echoes a whole name or id");
    }
}
