package rason.messaging.mqtt;

import java.io.ByteArrayOutputStream;
import java.nio.BufferUnderflowException;
import java.nio.ByteBuffer;
import java.nio.charset.StandardCharsets;

import rason.messaging.FleetAuth;
import rason.messaging.WireMessage;

/**
 * What the MQTT channel publishes, as bytes: a version, a kind, then the fields (strings as a
 * 4-byte length and UTF-8, integers big-endian) and the authentication fields. The MAC is
 * checked over FleetAuth's canonical encoding of the fields, not over these bytes.
 */
final class MqttPayloads {

    static final byte VERSION = 1;
    static final byte MESSAGE = 'M', PRESENCE = 'P', WILL = 'W', PULSE = 'L';

    /** An agent message with its authentication fields. */
    record Message(WireMessage message, FleetAuth.Signed signed) {
    }

    /** A presence announced over the connection named link. */
    record Presence(String mas, String[] agents, String[] dfAgents, String[] dfServices, float period,
            boolean leaving, String link, FleetAuth.Signed signed) {
    }

    /** The last will of mas's connection named link. */
    record Will(String mas, String link, FleetAuth.Signed signed) {
    }

    /** A pulse of mas: alive (see {@link FleetAuth#signPulse}). */
    record Pulse(String mas, FleetAuth.Signed signed) {
    }

    private MqttPayloads() {
    }

    static byte[] message(WireMessage m, FleetAuth.Signed s) {
        Writer w = new Writer(MESSAGE);
        w.string(m.senderMas()).string(m.sender()).string(m.receiverMas()).string(m.receiver())
                .string(m.performative()).string(m.content()).string(m.msgId()).string(m.inReplyTo());
        return w.signed(s).bytes();
    }

    static byte[] presence(Presence p) {
        Writer w = new Writer(PRESENCE);
        w.string(p.mas()).strings(p.agents()).strings(p.dfAgents()).strings(p.dfServices());
        w.int32(Float.floatToIntBits(p.period())).int8(p.leaving() ? 1 : 0).string(p.link());
        return w.signed(p.signed()).bytes();
    }

    static byte[] will(Will will) {
        return new Writer(WILL).string(will.mas()).string(will.link()).signed(will.signed()).bytes();
    }

    static byte[] pulse(Pulse pulse) {
        return new Writer(PULSE).string(pulse.mas()).signed(pulse.signed()).bytes();
    }

    /**
     * @return a {@link Message}, {@link Presence}, {@link Will} or {@link Pulse}
     * @throws IllegalArgumentException not one of ours, or cut short (the text says which)
     */
    static Object decode(byte[] payload) {
        ByteBuffer b = ByteBuffer.wrap(payload);
        try {
            if (b.get() != VERSION)
                throw new IllegalArgumentException("not a version " + VERSION + " payload");
            byte kind = b.get();
            Object out = switch (kind) {
            case MESSAGE -> new Message(new WireMessage(string(b), string(b), string(b), string(b), string(b),
                    string(b), string(b), string(b)), signed(b));
            case PRESENCE -> new Presence(string(b), strings(b), strings(b), strings(b),
                    Float.intBitsToFloat(b.getInt()), b.get() != 0, string(b), signed(b));
            case WILL -> new Will(string(b), string(b), signed(b));
            case PULSE -> new Pulse(string(b), signed(b));
            default -> throw new IllegalArgumentException("unknown kind " + kind);
            };
            if (b.hasRemaining())
                throw new IllegalArgumentException(b.remaining() + " bytes after the fields");
            return out;
        } catch (BufferUnderflowException e) {
            throw new IllegalArgumentException("cut short");
        }
    }

    private static String string(ByteBuffer b) {
        return new String(bytes(b), StandardCharsets.UTF_8);
    }

    private static byte[] bytes(ByteBuffer b) {
        int n = b.getInt();
        if (n < 0 || n > b.remaining())
            throw new IllegalArgumentException("a field of " + n + " bytes, with " + b.remaining() + " left");
        byte[] out = new byte[n];
        b.get(out);
        return out;
    }

    private static String[] strings(ByteBuffer b) {
        int n = b.getInt();
        if (n < 0 || n > b.remaining() / 4)
            throw new IllegalArgumentException("a list of " + n + " strings, with " + b.remaining() + " bytes left");
        String[] out = new String[n];
        for (int i = 0; i < n; i++)
            out[i] = string(b);
        return out;
    }

    private static FleetAuth.Signed signed(ByteBuffer b) {
        return new FleetAuth.Signed(b.getLong(), b.getLong(), b.getLong(), string(b), bytes(b));
    }

    private static final class Writer {
        private final ByteArrayOutputStream out = new ByteArrayOutputStream(256);

        Writer(byte kind) {
            out.write(VERSION);
            out.write(kind);
        }

        Writer string(String s) {
            return bytes((s == null ? "" : s).getBytes(StandardCharsets.UTF_8));
        }

        Writer bytes(byte[] b) {
            int32(b.length);
            out.write(b, 0, b.length);
            return this;
        }

        Writer strings(String[] list) {
            int32(list.length);
            for (String s : list)
                string(s);
            return this;
        }

        Writer signed(FleetAuth.Signed s) {
            return int64(s.incarnation()).int64(s.sequence()).int64(s.stamp()).string(s.keyId()).bytes(s.mac());
        }

        Writer int64(long v) {
            for (int shift = 56; shift >= 0; shift -= 8)
                out.write((int) (v >>> shift));
            return this;
        }

        Writer int32(int v) {
            for (int shift = 24; shift >= 0; shift -= 8)
                out.write(v >>> shift);
            return this;
        }

        Writer int8(int v) {
            out.write(v);
            return this;
        }

        byte[] bytes() {
            return out.toByteArray();
        }
    }
}
