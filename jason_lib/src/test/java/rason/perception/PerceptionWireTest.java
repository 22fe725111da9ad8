package rason.perception;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

import org.junit.jupiter.api.Test;

import rason.core.InputLimits;

import static rason.perception.SerializedPerceptions.serialized;
import static rason.perception.SerializedPerceptions.string;
import static rason.perception.SerializedPerceptions.uint32;

class PerceptionWireTest {

    private final InputLimits limits = new InputLimits();
    private final List<String> refused = new ArrayList<>();

    private PerceptionWire.Literals read(byte[] message) {
        return PerceptionWire.literals(message, limits, (text, why) -> refused.add(text + ": " + why));
    }

    private String refusedWhy(byte[] message) {
        return assertThrows(IllegalArgumentException.class, () -> read(message)).getMessage();
    }

    @Test
    void readsTheLiteralsInOrder() {
        PerceptionWire.Literals read = read(serialized("cam_robots", "robot(faulty,-3.5,1.5,12)", "name(\"café ✓ 𝄞\")"));
        assertArrayEquals(new String[] { "robot(faulty,-3.5,1.5,12)", "name(\"café ✓ 𝄞\")" }, read.texts());
        assertEquals(0, read.notUtf8());
        assertEquals(List.of(), refused);
    }

    @Test
    void anEmptyListAndAnEmptySourceAreMessagesToo() {
        assertArrayEquals(new String[0], read(serialized("cam")).texts());
        assertArrayEquals(new String[] { "" }, read(serialized("", "")).texts(), "an empty text is the parser's to refuse");
    }

    @Test
    void bytesAfterTheLastLiteralAreIgnoredAsGenpyIgnoresThem() {
        byte[] message = serialized("s", "a(1)");
        byte[] longer = Arrays.copyOf(message, message.length + 5);
        assertArrayEquals(new String[] { "a(1)" }, read(longer).texts());
    }

    @Test
    void everyTruncationIsRefusedWithWhereItEnds() {
        byte[] message = serialized("cam", "a(1)", "b(2)");
        for (int n = 0; n < message.length; n++) {
            String why = refusedWhy(Arrays.copyOf(message, n));
            assertTrue(why.startsWith("not a rason_msgs/Perception: "), why);
        }
        assertEquals("not a rason_msgs/Perception: it ends before the length of the source (byte 0 of 3)",
                refusedWhy(new byte[3]));
        assertEquals("not a rason_msgs/Perception: it ends before the number of literals (byte 7 of 7)",
                refusedWhy(Arrays.copyOf(message, 7)));
        assertEquals("not a rason_msgs/Perception: the length of literal 2 (4 bytes) goes past the end (3 bytes left)",
                refusedWhy(Arrays.copyOf(message, message.length - 1)));
        assertEquals("not a rason_msgs/Perception: no bytes", refusedWhy(null));
    }

    @Test
    void lengthsBeyondTheBufferAreRefusedBeforeAnythingIsAllocated() {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        uint32(out, 0xffff_ffffL); // a source of 4 GB
        assertEquals("not a rason_msgs/Perception: the length of the source (4294967295 bytes) goes past the end "
                + "(0 bytes left)", refusedWhy(out.toByteArray()));
        out.reset();
        string(out, "s".getBytes(StandardCharsets.UTF_8));
        uint32(out, 1);
        uint32(out, Integer.MAX_VALUE + 1L); // a literal of 2 GB
        out.writeBytes("a(1)".getBytes(StandardCharsets.UTF_8));
        assertEquals("not a rason_msgs/Perception: the length of literal 1 (2147483648 bytes) goes past the end "
                + "(4 bytes left)", refusedWhy(out.toByteArray()));
    }

    @Test
    void aHugeCountIsRefusedByTheLimitWithoutReadingFurther() {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        string(out, "flood".getBytes(StandardCharsets.UTF_8));
        uint32(out, 0xffff_ffffL);
        assertEquals("4294967295 literals, more than 1000 (the source's percepts are unchanged)", refusedWhy(out.toByteArray()));
        byte[] within = serialized("s", "x(1)");
        within[5] = 100; // claims 100 literals, has bytes for 1
        assertEquals("not a rason_msgs/Perception: 100 literals cannot be in the 8 bytes left", refusedWhy(within));
    }

    @Test
    void theLiteralLimitCountsTheMessageAsTheStringPathDoes() {
        String[] many = new String[1001];
        Arrays.fill(many, "x(1)");
        assertEquals("1001 literals, more than 1000 (the source's percepts are unchanged)", refusedWhy(serialized("s", many)));
        assertEquals(1000, read(serialized("s", Arrays.copyOf(many, 1000))).texts().length);
    }

    @Test
    void aLiteralTooLongByItsBytesIsRefusedAloneWithoutDecodingIt() {
        String huge = "name(\"" + "a".repeat(1 << 20) + "\")";
        PerceptionWire.Literals read = read(serialized("s", "ok(1)", huge, "ok(2)"));
        assertArrayEquals(new String[] { "ok(1)", "ok(2)" }, read.texts());
        assertEquals(1, refused.size());
        String line = refused.get(0);
        assertTrue(line.endsWith(": longer than 4096 characters"), line);
        assertTrue(line.length() < 1000, "only its beginning is shown: " + line.length());
        // one within four bytes a character is decoded, and left to the parser's own length check
        String near = "n(\"" + "é".repeat(5000) + "\")";
        assertArrayEquals(new String[] { near }, read(serialized("s", near)).texts());
    }

    @Test
    void invalidUtf8IsReadWithReplacementCharactersAsGenpyReadsItAndCounted() {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        string(out, "s".getBytes(StandardCharsets.UTF_8));
        uint32(out, 3);
        string(out, new byte[] { 'n', '(', '"', 'c', 'a', 'f', (byte) 0xe9, '"', ')' }); // Latin-1 é
        string(out, new byte[] { 'x', '(', '"', (byte) 0xed, (byte) 0xa0, (byte) 0x80, '"', ')' }); // a lone surrogate
        string(out, "ok(\"\uFFFD\")".getBytes(StandardCharsets.UTF_8)); // U+FFFD itself is valid
        PerceptionWire.Literals read = read(out.toByteArray());
        assertEquals("n(\"caf\uFFFD\")", read.texts()[0]);
        assertTrue(read.texts()[1].startsWith("x(\"\uFFFD"), read.texts()[1]);
        assertEquals("ok(\"\uFFFD\")", read.texts()[2]);
        assertEquals(2, read.notUtf8());
    }

    @Test
    void randomBytesNeverThrowAnythingButTheRefusal() {
        java.util.Random random = new java.util.Random(35);
        byte[] valid = serialized("cam", "robot(a,1)", "battery(90)", "name(\"x\")");
        for (int i = 0; i < 20_000; i++) {
            byte[] message;
            if (random.nextBoolean()) { // a valid message with a few bytes changed
                message = valid.clone();
                for (int k = 0; k < 1 + random.nextInt(4); k++)
                    message[random.nextInt(message.length)] = (byte) random.nextInt(256);
            } else {
                message = new byte[random.nextInt(64)];
                random.nextBytes(message);
            }
            try {
                PerceptionWire.Literals read = read(message);
                assertTrue(read.texts().length <= limits.maxLiterals());
            } catch (IllegalArgumentException e) {
                assertTrue(e.getMessage().startsWith("not a rason_msgs/Perception: ")
                        || e.getMessage().contains("literals, more than 1000"), e.getMessage());
            }
        }
    }
}
