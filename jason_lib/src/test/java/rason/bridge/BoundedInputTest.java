package rason.bridge;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.logging.Handler;
import java.util.logging.LogRecord;
import java.util.logging.Logger;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import rason.RosAgArch;
import rason.messaging.RateLimitedLog;

/** Hostile perceptions through the bridge to a running agent. */
class BoundedInputTest {

    @TempDir
    Path dir;

    private final RunningAgents agents = new RunningAgents();
    private final Bridge bridge = Bridge.get();
    private final Logger logger = Logger.getLogger("rason.bridge");
    private final List<String> lines = new ArrayList<>();
    private final Handler handler = new Handler() {
        @Override
        public synchronized void publish(LogRecord r) {
            lines.add(r.getMessage());
        }

        @Override
        public void flush() {
        }

        @Override
        public void close() {
        }
    };

    @AfterEach
    void stop() throws Exception {
        logger.removeHandler(handler);
        agents.stop();
    }

    private synchronized long linesContaining(String s) {
        return lines.stream().filter(l -> l.contains(s)).count();
    }

    @Test
    void hostilePerceptionsAreDroppedAndTheAgentGoesOn() throws Exception {
        RosAgArch arch = agents.start(dir, "bob", "+go <- +went.\n");
        logger.addHandler(handler);

        String[] tooMany = new String[1001];
        Arrays.fill(tooMany, "x(1)");
        assertEquals(0, bridge.perceive("flood", tooMany, 100 * RunningAgents.SECOND));
        assertTrue(linesContaining("dropped perception message from source 'flood': 1001 literals, more than 1000") <= 1);

        String deep = "f(".repeat(100_000) + "a" + ")".repeat(100_000);
        String[] bad = new String[50];
        Arrays.fill(bad, deep);
        assertEquals(0, bridge.perceive("deep", bad, 100 * RunningAgents.SECOND));
        assertTrue(linesContaining("from source 'deep'") <= RateLimitedLog.DEFAULT_LINES,
                "at most a few lines per period: " + lines.size());
        assertTrue(lines.stream().allMatch(l -> l.length() < 1000), "no line echoes a whole literal");

        String[] many = new String[1000];
        for (int i = 0; i < many.length; i++)
            many[i] = "x(" + i + ")";
        assertEquals(1000, bridge.perceive("many", many, 100 * RunningAgents.SECOND));
        assertEquals(1, bridge.perceive("s", new String[] { "go" }, 100 * RunningAgents.SECOND));
        RunningAgents.await("the agent reacts to go", () -> RunningAgents.believes(arch, "went"));
        assertTrue(RunningAgents.believes(arch, "x(999)"));
    }
}
