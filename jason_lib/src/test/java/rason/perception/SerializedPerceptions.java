package rason.perception;

import java.io.ByteArrayOutputStream;
import java.nio.charset.StandardCharsets;

/** rason_msgs/Perception messages as genpy serializes them, for tests. */
public final class SerializedPerceptions {

    private SerializedPerceptions() {
    }

    /** The message of source with these literals (strings as UTF-8). */
    public static byte[] serialized(String source, String... literals) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        string(out, source.getBytes(StandardCharsets.UTF_8));
        uint32(out, literals.length);
        for (String l : literals)
            string(out, l.getBytes(StandardCharsets.UTF_8));
        return out.toByteArray();
    }

    /** A string field: its length, then its bytes. */
    public static void string(ByteArrayOutputStream out, byte[] bytes) {
        uint32(out, bytes.length);
        out.writeBytes(bytes);
    }

    /** A uint32, little-endian. */
    public static void uint32(ByteArrayOutputStream out, long n) {
        for (int i = 0; i < 4; i++)
            out.write((int) (n >>> (8 * i)) & 0xff);
    }
}
