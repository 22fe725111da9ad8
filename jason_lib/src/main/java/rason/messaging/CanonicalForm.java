package rason.messaging;

import java.io.ByteArrayOutputStream;
import java.nio.charset.StandardCharsets;
import java.util.List;

/**
 * The bytes a fleet MAC covers ({@link FleetAuth}): the fields of a message, a presence, a
 * last will or a pulse, each length-prefixed or fixed-width, so that no two field lists encode alike and
 * every channel signs the same bytes.
 */
public final class CanonicalForm {

    private CanonicalForm() {
    }

    /** The bytes the MAC of an agent message covers (s's MAC itself excluded). */
    public static byte[] message(WireMessage m, FleetAuth.Signed s) {
        Canonical c = header(FleetAuth.Kind.MESSAGE, m.senderMas(), s);
        c.string(m.sender()).string(m.receiverMas()).string(m.receiver()).string(m.performative())
                .string(m.content()).string(m.msgId()).string(m.inReplyTo());
        return c.bytes();
    }

    /** The bytes the MAC of a presence covers (s's MAC itself excluded). */
    public static byte[] presence(String masId, List<String> agents, List<String> dfAgents,
            List<String> dfServices, float period, boolean leaving, FleetAuth.Signed s) {
        return presence(masId, agents, dfAgents, dfServices, period, leaving, "", s);
    }

    /** The same, with the connection it is announced over (appended only when there is one). */
    public static byte[] presence(String masId, List<String> agents, List<String> dfAgents,
            List<String> dfServices, float period, boolean leaving, String link, FleetAuth.Signed s) {
        Canonical c = header(FleetAuth.Kind.PRESENCE, masId, s);
        c.strings(agents);
        c.int32(Float.floatToIntBits(period)).int8(leaving ? 1 : 0);
        c.strings(dfAgents).strings(dfServices);
        if (link != null && !link.isEmpty())
            c.string(link);
        return c.bytes();
    }

    /** The bytes the MAC of a last will covers. */
    public static byte[] will(String masId, String link, FleetAuth.Signed s) {
        return header(FleetAuth.Kind.WILL, masId, s).string(link).bytes();
    }

    /** The bytes the MAC of a pulse covers: the header alone. */
    public static byte[] pulse(String masId, FleetAuth.Signed s) {
        return header(FleetAuth.Kind.PULSE, masId, s).bytes();
    }

    private static Canonical header(FleetAuth.Kind kind, String mas, FleetAuth.Signed s) {
        return new Canonical().string(kind.tag).string(s.keyId()).string(mas).int64(s.incarnation())
                .int64(s.sequence()).int64(s.stamp());
    }

    /** Length-prefixed UTF-8 strings and big-endian integers: no two field lists encode alike. */
    private static final class Canonical {
        private final ByteArrayOutputStream out = new ByteArrayOutputStream(256);

        Canonical string(String s) {
            byte[] b = (s == null ? "" : s).getBytes(StandardCharsets.UTF_8);
            int32(b.length);
            out.write(b, 0, b.length);
            return this;
        }

        /** A list: its size (4 bytes), then each string. */
        Canonical strings(List<String> list) {
            int32(list.size());
            for (String s : list)
                string(s);
            return this;
        }

        Canonical int64(long v) {
            for (int shift = 56; shift >= 0; shift -= 8)
                out.write((int) (v >>> shift));
            return this;
        }

        Canonical int32(int v) {
            for (int shift = 24; shift >= 0; shift -= 8)
                out.write(v >>> shift);
            return this;
        }

        Canonical int8(int v) {
            out.write(v);
            return this;
        }

        byte[] bytes() {
            return out.toByteArray();
        }
    }
}
