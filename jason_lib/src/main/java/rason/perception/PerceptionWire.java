package rason.perception;

import java.nio.ByteBuffer;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;
import java.util.Arrays;
import java.util.function.BiConsumer;

import rason.core.InputLimits;

/**
 * Reads the literals of one rason_msgs/Perception from its ROS 1 serialization, the bytes rospy
 * receives for one message: {@code uint32} length and UTF-8 bytes of the source, {@code uint32}
 * count of literals, then each literal's {@code uint32} length and UTF-8 bytes (little-endian).
 * <p>
 * Every length is checked against the bytes left before anything is read or allocated, so a
 * truncated message, a length past the end or a huge count is refused with its reason and
 * allocates nothing in proportion to what it claims. Bytes after the last literal are ignored,
 * as genpy ignores them. Invalid UTF-8 becomes U+FFFD, as genpy decodes it.
 */
public final class PerceptionWire {

    /**
     * The most bytes of UTF-8 one character of a Java string comes from (1 to 3 for a character,
     * 4 for a surrogate pair of 2, up to 3 for the U+FFFD of an invalid sequence): a literal of
     * more bytes than this times the characters allowed is too long, without decoding it.
     */
    static final int MAX_BYTES_PER_CHARACTER = 4;
    /** Characters of a refused literal shown in its line. */
    static final int SHOWN_CHARACTERS = 200;

    /** The texts of one message's literals, and how many of them were not valid UTF-8. */
    public record Literals(String[] texts, int notUtf8) {
    }

    private static final int SOURCE = -1;
    private static final int COUNT = -2;

    private final byte[] message;
    private int position;

    private PerceptionWire(byte[] message) {
        this.message = message;
    }

    /**
     * The texts of the message's literals within limits. A literal too long to be a
     * perception ({@link InputLimits#maxLiteralLength()}) by its bytes alone is not decoded
     * but told to {@code refused} (its beginning, why) and left out; the other literals are
     * kept in order, for the parser to check.
     *
     * @throws IllegalArgumentException the message as a whole is refused: it is not a
     *         rason_msgs/Perception (truncated, a length past its end) or has more than
     *         {@link InputLimits#maxLiterals()} literals; the message says which
     */
    public static Literals literals(byte[] message, InputLimits limits, BiConsumer<String, String> refused) {
        if (message == null)
            throw new IllegalArgumentException("not a rason_msgs/Perception: no bytes");
        return new PerceptionWire(message).read(limits, refused);
    }

    /** Why a message of {@code count} literals is refused: more than {@code max}. */
    static String tooManyLiterals(long count, int max) {
        return count + " literals, more than " + max + " (the source's percepts are unchanged)";
    }

    private Literals read(InputLimits limits, BiConsumer<String, String> refused) {
        int sourceBytes = length(SOURCE); // skipped: the node read the source to coalesce by it
        position += sourceBytes;
        long count = unsigned(COUNT);
        if (count > limits.maxLiterals())
            throw new IllegalArgumentException(tooManyLiterals(count, limits.maxLiterals()));
        if (count * Integer.BYTES > left())
            throw malformed(count + " literals cannot be in the " + left() + " bytes left");
        long maxBytes = (long) MAX_BYTES_PER_CHARACTER * limits.maxLiteralLength();
        String[] texts = new String[(int) count];
        int kept = 0;
        int notUtf8 = 0;
        for (int i = 0; i < count; i++) {
            int bytes = length(i);
            if (bytes > maxBytes) {
                refused.accept(decode(position, Math.min(bytes, MAX_BYTES_PER_CHARACTER * SHOWN_CHARACTERS)),
                        "longer than " + limits.maxLiteralLength() + " characters");
            } else {
                String text = decode(position, bytes);
                if (text.indexOf('\uFFFD') >= 0 && !validUtf8(position, bytes))
                    notUtf8++;
                texts[kept++] = text;
            }
            position += bytes;
        }
        return new Literals(kept == texts.length ? texts : Arrays.copyOf(texts, kept), notUtf8);
    }

    /** Reads the length of a string (the source, or literal i from 0) and checks that its bytes are there. */
    private int length(int field) {
        long n = unsigned(field);
        if (n > left())
            throw malformed("the length of " + name(field) + " (" + n + " bytes) goes past the end (" + left()
                    + " bytes left)");
        return (int) n;
    }

    /** Reads the uint32 of a field (the source's length, the count, or literal i's length). */
    private long unsigned(int field) {
        if (left() < Integer.BYTES)
            throw malformed("it ends before " + (field == COUNT ? "the number of literals" : "the length of " + name(field))
                    + " (byte " + position + " of " + message.length + ")");
        long n = (message[position] & 0xffL) | (message[position + 1] & 0xffL) << 8
                | (message[position + 2] & 0xffL) << 16 | (message[position + 3] & 0xffL) << 24;
        position += Integer.BYTES;
        return n;
    }

    private static String name(int field) {
        return field == SOURCE ? "the source" : "literal " + (field + 1);
    }

    private int left() {
        return message.length - position;
    }

    private String decode(int from, int bytes) {
        return new String(message, from, bytes, StandardCharsets.UTF_8);
    }

    /** Whether the bytes are valid UTF-8 (asked only of a text with U+FFFD in it, which valid UTF-8 may also spell). */
    private boolean validUtf8(int from, int bytes) {
        try {
            StandardCharsets.UTF_8.newDecoder().onMalformedInput(CodingErrorAction.REPORT)
                    .onUnmappableCharacter(CodingErrorAction.REPORT).decode(ByteBuffer.wrap(message, from, bytes));
            return true;
        } catch (CharacterCodingException e) {
            return false;
        }
    }

    private static IllegalArgumentException malformed(String why) {
        return new IllegalArgumentException("not a rason_msgs/Perception: " + why);
    }
}
