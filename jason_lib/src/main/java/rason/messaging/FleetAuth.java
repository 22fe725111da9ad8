package rason.messaging;

import java.security.GeneralSecurityException;
import java.security.MessageDigest;
import java.time.Instant;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Function;
import java.util.function.LongSupplier;
import java.util.function.Supplier;

import javax.crypto.Mac;
import javax.crypto.spec.SecretKeySpec;

import rason.core.InputLimits;

/**
 * Authentication of what rason_mas processes say to each other
 * (rason_msgs/AgentMessage and rason_msgs/Presence): an HMAC-SHA256 with the
 * fleet's shared key ({@link FleetKeys}) over every field, and the sender's
 * incarnation (start time), a sequence number per process and topic, and a
 * wall-clock stamp, so a recorded message cannot be played again.
 * <p>
 * The MAC covers one canonical encoding of the fields (see {@link #canonicalMessage}
 * and {@link #canonicalPresence}): each string as its UTF-8 length (4 bytes,
 * big-endian) and bytes, each integer as 8 bytes big-endian, and first a tag
 * naming the message type, so a presence can never pass for a message.
 * <p>
 * Incoming checks, in this order: a MAC at all (else unauthenticated), a key
 * we know (unknown key), the MAC itself (bad mac), the stamp within the
 * window of our clock and not before this process started (stale), and per
 * (type, sender process) a newer incarnation or a higher sequence than the
 * last accepted (else replayed). {@link #admit} makes the last check and
 * records the message in one step, together with the caller's own checks.
 * With authentication off nothing is signed and nothing is checked.
 */
public final class FleetAuth {

    /** The two kinds of signed traffic; the tag starts the canonical encoding. */
    public enum Kind {
        MESSAGE("rason_msgs/AgentMessage"), PRESENCE("rason_msgs/Presence"),
        /** A channel's last will: "the connection named link of this process ended" (see {@link #signWill}). */
        WILL("rason/will"),
        /** A sign of life over a channel's second connection (see {@link #signPulse}). */
        PULSE("rason/pulse");

        final String tag;

        Kind(String tag) {
            this.tag = tag;
        }
    }

    /** Why a message or presence is dropped; the word names the kind of the rate-limited log line. */
    public enum Problem {
        UNAUTHENTICATED("unauthenticated"), UNKNOWN_KEY("unknown key"), BAD_MAC("bad mac"), STALE("stale"),
        REPLAYED("replayed"), FORGED("forged"),
        /** Never seen, but after a later one of its sender: reordered, or held back and played late. */
        OUT_OF_ORDER("out of order");

        public final String word;

        Problem(String word) {
            this.word = word;
        }
    }

    /** A refused message or presence: the problem and what exactly was wrong. */
    public record Refusal(Problem problem, String detail) {
        public String text() {
            return problem.word + ": " + detail;
        }
    }

    /**
     * The authentication fields of a message or presence: the sender process's
     * incarnation, its sequence number on that topic, the wall-clock stamp
     * (ns since the epoch), the id of the signing key and the MAC (empty when unsigned).
     * Integers are the uint64 fields' bits: compared unsigned where order matters.
     */
    public record Signed(long incarnation, long sequence, long stamp, String keyId, byte[] mac) {
        public Signed {
            keyId = keyId == null ? "" : keyId;
            mac = mac == null ? new byte[0] : mac;
        }
    }

    /** HMAC-SHA256's output: anything else is not a MAC of ours. */
    public static final int MAC_BYTES = 32;
    public static final long DEFAULT_WINDOW_NANOS = 60_000_000_000L;
    /** Senders whose replay state is kept at most; the least recently heard go first. */
    static final int MAX_SENDERS = 1024;
    /** With the window off, state of senders silent this long is forgotten (with it on: twice the window). */
    static final long FORGET_WITHOUT_WINDOW_NANOS = 600_000_000_000L;

    private static final String HMAC = "HmacSHA256";
    private static final ThreadLocal<Mac> MACS = ThreadLocal.withInitial(() -> {
        try {
            return Mac.getInstance(HMAC);
        } catch (GeneralSecurityException e) {
            throw new IllegalStateException("this JVM has no " + HMAC, e);
        }
    });

    private static final class Seen {
        long incarnation;
        long sequence;
        long accepted, heardNanos; // accepted: bit i set if sequence - i was
    }

    private final LongSupplier wallClock;
    private final AtomicLong messageSequence = new AtomicLong();
    private final AtomicLong presenceSequence = new AtomicLong();
    private final AtomicLong pulseSequence = new AtomicLong();
    // access order: the eldest entry is the sender heard least recently
    private final Map<String, Seen> seen = new LinkedHashMap<>(16, 0.75f, true); // guarded by itself
    private volatile FleetKeys keys = null;
    private volatile boolean required = true;
    private volatile long windowNanos = DEFAULT_WINDOW_NANOS;
    private volatile long incarnation = 0;

    /** Wall clock in ns since the epoch. */
    public FleetAuth() {
        this(FleetAuth::wallNanos);
    }

    /** @param wallClock ns since the epoch (tests pass their own) */
    public FleetAuth(LongSupplier wallClock) {
        this.wallClock = wallClock;
    }

    public static long wallNanos() {
        Instant now = Instant.now();
        return now.getEpochSecond() * 1_000_000_000L + now.getNano();
    }

    // ---- configuration -------------------------------------------------------------

    /** Sign with keys.signing(), accept what any of keys signed, refuse the rest. */
    public void require(FleetKeys keys) {
        this.keys = keys;
        this.required = true;
    }

    /** No signing and no checks: for a trusted network only. */
    public void off() {
        this.required = false;
    }

    public boolean required() {
        return required;
    }

    /** The keys in use, null if none. */
    public FleetKeys keys() {
        return keys;
    }

    /** How far a stamp may be from our clock; 0 or less turns every clock check off. */
    public void setWindowNanos(long t) {
        windowNanos = t;
    }

    /** This process's start time (ns since the epoch): signs our traffic, and nothing stamped earlier is for us. */
    public void setIncarnation(long t) {
        incarnation = t;
    }

    // ---- outgoing --------------------------------------------------------------------

    /**
     * The authentication fields of m, our next message. Call in the order of
     * publishing: the sequence numbers must reach the receivers increasing.
     *
     * @throws IllegalStateException authentication is required and there is no key
     */
    public Signed sign(WireMessage m) {
        return sign(messageSequence.incrementAndGet(), s -> CanonicalForm.message(m, s));
    }

    /** The authentication fields of our next presence announcement (in the order of publishing). */
    public Signed signPresence(String masId, List<String> agents, float period, boolean leaving) {
        return signPresence(masId, agents, List.of(), List.of(), period, leaving);
    }

    /** Our next presence announcement with directory registrations (dfAgents[i] provides dfServices[i]). */
    public Signed signPresence(String masId, List<String> agents, List<String> dfAgents, List<String> dfServices,
            float period, boolean leaving) {
        return signPresence(masId, agents, dfAgents, dfServices, period, leaving, "");
    }

    /**
     * The same, announced over the connection named link (a channel's connection id, "" for none):
     * the MAC covers the link too, so a will naming that link can be matched to it ({@link #signWill}).
     */
    public Signed signPresence(String masId, List<String> agents, List<String> dfAgents, List<String> dfServices,
            float period, boolean leaving, String link) {
        return sign(presenceSequence.incrementAndGet(),
                s -> CanonicalForm.presence(masId, agents, dfAgents, dfServices, period, leaving, link, s));
    }

    /**
     * A last will of our connection named link: signed when the connection is made and sent by
     * the broker whenever it ends, so it carries no sequence (0) and its stamp is the time of
     * signing. A receiver checks only its MAC here ({@link #verifyWill}); that the link is the
     * sender's current one is the receiver's check, which makes a copy worthless once the
     * connection it names is over.
     */
    public Signed signWill(String masId, String link) {
        return sign(0, s -> CanonicalForm.will(masId, link, s));
    }

    /**
     * Our next pulse: "this run of masId is alive", with nothing else, sent over a connection of
     * its own (in the order of publishing there) so that a stall of the connection carrying our
     * messages and presence does not make us look gone.
     */
    public Signed signPulse(String masId) {
        return sign(pulseSequence.incrementAndGet(), s -> CanonicalForm.pulse(masId, s));
    }

    private Signed sign(long sequence, Function<Signed, byte[]> canonical) {
        long stamp = wallClock.getAsLong();
        if (!required)
            return new Signed(incarnation, sequence, stamp, "", new byte[0]);
        FleetKeys k = keys;
        if (k == null)
            throw new IllegalStateException("fleet authentication is required but no fleet key is loaded");
        FleetKeys.Key key = k.signing();
        Signed unsigned = new Signed(incarnation, sequence, stamp, key.id(), new byte[0]);
        return new Signed(incarnation, sequence, stamp, key.id(), mac(key, canonical.apply(unsigned)));
    }

    // ---- incoming ----------------------------------------------------------------------

    /** MAC and clock checks of an incoming message (no state is changed); null if it passes or auth is off. */
    public Refusal verify(WireMessage m, Signed s) {
        if (!required)
            return null;
        Refusal r = macProblem(s, () -> CanonicalForm.message(m, s));
        return r != null ? r : clockProblem(s);
    }

    /** MAC and clock checks of an incoming presence (no state is changed); null if it passes or auth is off. */
    public Refusal verifyPresence(String masId, List<String> agents, float period, boolean leaving, Signed s) {
        return verifyPresence(masId, agents, List.of(), List.of(), period, leaving, s);
    }

    /** The same, for a presence with directory registrations. */
    public Refusal verifyPresence(String masId, List<String> agents, List<String> dfAgents, List<String> dfServices,
            float period, boolean leaving, Signed s) {
        if (!required)
            return null;
        return verifyPresence(masId, agents, dfAgents, dfServices, period, leaving, "", s);
    }

    /** The same, for a presence announced over the connection named link. */
    public Refusal verifyPresence(String masId, List<String> agents, List<String> dfAgents, List<String> dfServices,
            float period, boolean leaving, String link, Signed s) {
        if (!required)
            return null;
        Refusal r = macProblem(s,
                () -> CanonicalForm.presence(masId, agents, dfAgents, dfServices, period, leaving, link, s));
        return r != null ? r : clockProblem(s);
    }

    /**
     * The MAC check of a last will (see {@link #signWill}); no clock check, since a will is
     * sent long after it was signed, and no replay check, which is the caller's (the link).
     */
    public Refusal verifyWill(String masId, String link, Signed s) {
        if (!required)
            return null;
        return macProblem(s, () -> CanonicalForm.will(masId, link, s));
    }

    /** MAC and clock checks of an incoming pulse (no state is changed); null if it passes or auth is off. */
    public Refusal verifyPulse(String masId, Signed s) {
        if (!required)
            return null;
        Refusal r = macProblem(s, () -> CanonicalForm.pulse(masId, s));
        return r != null ? r : clockProblem(s);
    }

    /**
     * The replay check of a verified message or presence from process mas,
     * then the caller's own checks (more, may be null), and if all pass it is
     * recorded as the last accepted one of mas: one step, so no copy can pass
     * between the check and the record.
     *
     * @return null if admitted (always with auth off), else why not
     */
    public Refusal admit(Kind kind, String mas, Signed s, long nowNanos, Supplier<Refusal> more) {
        if (!required)
            return null;
        synchronized (seen) {
            String key = kind.name() + "\n" + mas;
            Seen last = seen.get(key);
            Refusal r = null;
            if (last != null && s.incarnation() < last.incarnation)
                r = new Refusal(Problem.REPLAYED, "from an earlier run of " + mas + " (incarnation " + s.incarnation()
                        + "; it now runs " + last.incarnation + ")");
            else if (last != null && s.incarnation() == last.incarnation
                    && Long.compareUnsigned(s.sequence(), last.sequence) <= 0)
                r = behind(last, s.sequence());
            if (r == null && more != null)
                r = more.get();
            if (r != null)
                return r;
            if (last == null) {
                forgetSilent(nowNanos);
                last = new Seen();
                seen.put(key, last);
            }
            long ahead = s.incarnation() == last.incarnation ? s.sequence() - last.sequence : Long.MAX_VALUE;
            last.accepted = ahead >= Long.SIZE ? 1 : last.accepted << ahead | 1;
            last.incarnation = s.incarnation();
            last.sequence = s.sequence();
            last.heardNanos = nowNanos;
            return null;
        }
    }

    /** Why sequence, not above the last accepted, is refused: seen before, or (within 64) overtaken. */
    private static Refusal behind(Seen last, long sequence) {
        long back = last.sequence - sequence;
        String n = "sequence " + Long.toUnsignedString(sequence), l = Long.toUnsignedString(last.sequence);
        if (back < Long.SIZE && (last.accepted >>> back & 1) == 0)
            return new Refusal(Problem.OUT_OF_ORDER, n + " came after " + l
                    + " (reordered or held back on the way; dropped to keep the sender's order)");
        return new Refusal(Problem.REPLAYED, n + " already seen (the last accepted is " + l + ")");
    }

    /** Number of senders whose replay state is kept (bounded by {@link #MAX_SENDERS}). */
    public int sendersKept() {
        synchronized (seen) {
            return seen.size();
        }
    }

    private void forgetSilent(long nowNanos) {
        long window = windowNanos;
        long forgetAfter = window > 0 ? 2 * window : FORGET_WITHOUT_WINDOW_NANOS;
        for (Iterator<Seen> it = seen.values().iterator(); it.hasNext();) {
            Seen e = it.next(); // eldest (least recently heard) first
            if (seen.size() >= MAX_SENDERS || nowNanos - e.heardNanos > forgetAfter)
                it.remove();
            else
                break;
        }
    }

    private Refusal macProblem(Signed s, Supplier<byte[]> canonical) {
        if (s.mac().length == 0 && s.keyId().isEmpty())
            return new Refusal(Problem.UNAUTHENTICATED, "no mac (is ~fleet_auth off on the sender's robot?)");
        FleetKeys k = keys;
        FleetKeys.Key key = k == null ? null : k.byId(s.keyId());
        if (key == null)
            return new Refusal(Problem.UNKNOWN_KEY, "signed with key '" + InputLimits.abbreviate(s.keyId(), 20)
                    + "', which is not in this robot's fleet keys " + (k == null ? "[]" : k.ids())
                    + ": the robots' key files differ (put the same file on both; docs: Security)");
        if (s.mac().length != MAC_BYTES || !MessageDigest.isEqual(mac(key, canonical.get()), s.mac()))
            return new Refusal(Problem.BAD_MAC, "its mac does not match its fields (altered, or not signed with key "
                    + key.id() + ")");
        return null;
    }

    private Refusal clockProblem(Signed s) {
        long window = windowNanos;
        if (window <= 0)
            return null;
        long age = wallClock.getAsLong() - s.stamp();
        if (age > window)
            return new Refusal(Problem.STALE, String.format(Locale.ROOT, "stamped %.1f s ago, outside the %.0f s window",
                    age / 1e9, window / 1e9));
        if (-age > window)
            return new Refusal(Problem.STALE, String.format(Locale.ROOT,
                    "stamped %.1f s in the future, outside the %.0f s window (are the robots' clocks synchronised?)",
                    -age / 1e9, window / 1e9));
        long start = incarnation;
        if (start != 0 && s.stamp() < start)
            return new Refusal(Problem.STALE, String.format(Locale.ROOT,
                    "stamped %.1f s before this process started", (start - s.stamp()) / 1e9));
        return null;
    }

    private static byte[] mac(FleetKeys.Key key, byte[] data) {
        Mac mac = MACS.get();
        try {
            mac.init(new SecretKeySpec(key.secret(), HMAC));
        } catch (GeneralSecurityException e) {
            throw new IllegalStateException("cannot use fleet " + key, e);
        }
        return mac.doFinal(data);
    }
}
