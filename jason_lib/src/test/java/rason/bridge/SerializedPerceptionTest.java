package rason.bridge;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static rason.perception.SerializedPerceptions.serialized;
import static rason.perception.SerializedPerceptions.string;
import static rason.perception.SerializedPerceptions.uint32;

import java.io.ByteArrayOutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.Arrays;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;

import rason.RosAgArch;
import rason.core.RateLimitedLog;

/** Perception messages as rospy receives them (serialized) through the bridge to a running agent. */
class SerializedPerceptionTest {

    private static final long NOW = 100 * RunningAgents.SECOND;

    @TempDir
    Path dir;

    private final Bridge bridge = new Bridge();
    @RegisterExtension
    final RunningAgents agents = new RunningAgents(bridge);
    @RegisterExtension
    final CapturedLog log = new CapturedLog("rason.bridge");

    private int perceive(String source, byte[] message) {
        return bridge.perception().perceiveSerialized(source, message, NOW);
    }

    @Test
    void aSerializedMessageBecomesPerceptsAsItsStringsWould() throws Exception {
        RosAgArch arch = agents.start(dir, "bob", "+go <- +went.\n");
        assertEquals(3, perceive("cam", serialized("cam", "robot(faulty,-3.5,1.5,12)", "name(\"café\")", "go")));
        RunningAgents.await("the agent reacts to go", () -> RunningAgents.believes(arch, "went"));
        assertTrue(RunningAgents.believes(arch, "robot(faulty,-3.5,1.5,12)[source(percept)]"));
        assertTrue(RunningAgents.believes(arch, "name(\"café\")"));
        // the next message of the source replaces its list; an empty one clears it
        assertEquals(1, perceive("cam", serialized("cam", "robot(faulty,0,0,13)")));
        RunningAgents.await("the old percept is gone", () -> !RunningAgents.believes(arch, "robot(faulty,-3.5,1.5,12)"));
        assertEquals(0, perceive("cam", serialized("cam")));
        RunningAgents.await("the source is cleared", () -> !RunningAgents.believes(arch, "robot(faulty,0,0,13)"));
    }

    @Test
    void hostileMessagesAreDroppedWithAReasonAndTheAgentGoesOn() throws Exception {
        RosAgArch arch = agents.start(dir, "bob", "+go <- +went.\n");
        assertEquals(1, perceive("cam", serialized("cam", "keep(1)")));
        log.attach();

        byte[] valid = serialized("cam", "keep(2)", "other(1)");
        assertEquals(0, perceive("cam", Arrays.copyOf(valid, valid.length - 2)));
        assertEquals(1, log.containing("dropped perception message from source 'cam': not a rason_msgs/Perception: "
                + "the length of literal 2 (8 bytes) goes past the end"), log.lines().toString());

        ByteArrayOutputStream huge = new ByteArrayOutputStream();
        string(huge, "cam".getBytes(StandardCharsets.UTF_8));
        uint32(huge, 0xffff_ffffL);
        assertEquals(0, perceive("cam", huge.toByteArray()));
        assertEquals(1, log.containing("dropped perception message from source 'cam': 4294967295 literals, more than 1000"));

        String deep = "f(".repeat(100_000) + "a" + ")".repeat(100_000);
        String[] bad = new String[50];
        Arrays.fill(bad, deep);
        assertEquals(0, perceive("deep", serialized("deep", bad)));
        assertTrue(log.containing("from source 'deep'") <= RateLimitedLog.DEFAULT_LINES,
                "at most a few lines per period: " + log.lines().size());
        assertTrue(log.lines().stream().allMatch(l -> l.length() < 1000), "no line echoes a whole literal");
        assertTrue(RunningAgents.believes(arch, "keep(1)"), "a dropped message leaves its source's percepts as they were");

        assertEquals(1, perceive("s", serialized("s", "go")));
        RunningAgents.await("the agent reacts to go", () -> RunningAgents.believes(arch, "went"));
    }

    @Test
    void literalsThatAreNotUtf8AreReadWithReplacementCharactersAndSaidSo() throws Exception {
        RosAgArch arch = agents.start(dir, "bob", "+go <- +went.\n");
        log.attach();
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        string(out, "cam".getBytes(StandardCharsets.UTF_8));
        uint32(out, 2);
        string(out, new byte[] { 'n', '(', '"', 'c', 'a', 'f', (byte) 0xe9, '"', ')' });
        string(out, "go".getBytes(StandardCharsets.UTF_8));
        assertEquals(2, perceive("cam", out.toByteArray()));
        RunningAgents.await("the agent reacts to go", () -> RunningAgents.believes(arch, "went"));
        assertTrue(RunningAgents.believes(arch, "n(\"caf\uFFFD\")"));
        assertEquals(1, log.containing("perception message from source 'cam': 1 literals not valid UTF-8"), log.lines().toString());
    }

    @Test
    void aSourceNameTooLongIsRefusedAsOnTheStringPath() {
        String source = "s".repeat(rason.core.InputLimits.MAX_SOURCE_LENGTH + 1);
        log.attach();
        assertEquals(0, perceive(source, serialized(source, "x(1)")));
        assertEquals(1, log.containing("source name longer than 256 characters"));
        assertEquals(0, bridge.perception().sources());
    }
}
