package rason.messaging;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermission;
import java.nio.file.attribute.PosixFilePermissions;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.ArrayList;
import java.util.Collections;
import java.util.EnumSet;
import java.util.HexFormat;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * The fleet's shared secrets, as read from a key file (or the ~fleet_key
 * parameter): one key per line, empty lines and lines starting with '#'
 * skipped, surrounding blanks trimmed, the line's UTF-8 bytes used as the key.
 * The first key signs; every key verifies. That is what makes rotation
 * possible without a moment when two robots cannot talk: add the new key as a
 * second line everywhere, then move it first everywhere, then remove the old.
 */
public final class FleetKeys {

    /** Shorter secrets are refused: 32 bytes is HMAC-SHA256's own key size. */
    public static final int MIN_KEY_BYTES = 32;

    /** One key and the id that names it in messages (key_id). */
    public static final class Key {
        private final String id;
        private final byte[] secret;

        private Key(byte[] secret) {
            this.secret = secret.clone();
            this.id = idOf(secret);
        }

        public String id() {
            return id;
        }

        byte[] secret() {
            return secret;
        }

        @Override
        public String toString() {
            return "key " + id; // never the secret
        }
    }

    private final List<Key> keys;
    private final Map<String, Key> byId;
    private final String origin;

    private FleetKeys(List<Key> keys, String origin) {
        this.keys = List.copyOf(keys);
        Map<String, Key> m = new LinkedHashMap<>();
        for (Key k : keys)
            m.put(k.id(), k);
        this.byId = Collections.unmodifiableMap(m);
        this.origin = origin;
    }

    /**
     * Reads the keys in text.
     *
     * @param origin where text comes from, for the error messages (a path, "~fleet_key")
     * @throws IllegalArgumentException no key, a key shorter than {@link #MIN_KEY_BYTES}, two keys with one id
     */
    public static FleetKeys parse(String text, String origin) {
        List<Key> keys = new ArrayList<>();
        Map<String, Integer> lineOfId = new LinkedHashMap<>();
        String[] lines = text.split("\n", -1);
        for (int i = 0; i < lines.length; i++) {
            String line = lines[i].strip();
            if (line.isEmpty() || line.startsWith("#"))
                continue;
            byte[] secret = line.getBytes(StandardCharsets.UTF_8);
            int number = i + 1;
            if (secret.length < MIN_KEY_BYTES)
                throw new IllegalArgumentException(origin + " line " + number + ": a key of " + secret.length
                        + " bytes is too short (at least " + MIN_KEY_BYTES + "; make one with `rosrun rason_bridge fleet_key`)");
            Key k = new Key(secret);
            Integer earlier = lineOfId.putIfAbsent(k.id(), number);
            if (earlier != null)
                throw new IllegalArgumentException(origin + " line " + number + ": the same key (id " + k.id()
                        + ") as line " + earlier);
            keys.add(k);
        }
        if (keys.isEmpty())
            throw new IllegalArgumentException(origin + " holds no key (only empty or # lines)");
        return new FleetKeys(keys, origin);
    }

    /**
     * Reads the key file at path.
     *
     * @throws IllegalArgumentException it cannot be read, or holds no usable key (the message says which and why)
     */
    public static FleetKeys load(Path path) {
        byte[] bytes;
        try {
            bytes = Files.readAllBytes(path);
        } catch (NoSuchFileException e) {
            throw new IllegalArgumentException(path + " does not exist");
        } catch (IOException e) {
            throw new IllegalArgumentException("cannot read " + path + ": " + e);
        }
        return parse(new String(bytes, StandardCharsets.UTF_8), path.toString());
    }

    /**
     * Why a key file is too open: null if only its owner can read it (or the
     * file system has no POSIX permissions), else a sentence to log.
     */
    public static String tooOpen(Path path) {
        Set<PosixFilePermission> p;
        try {
            p = Files.getPosixFilePermissions(path);
        } catch (UnsupportedOperationException | IOException e) {
            return null;
        }
        Set<PosixFilePermission> others = EnumSet.of(PosixFilePermission.GROUP_READ, PosixFilePermission.GROUP_WRITE,
                PosixFilePermission.OTHERS_READ, PosixFilePermission.OTHERS_WRITE);
        others.retainAll(p);
        if (others.isEmpty())
            return null;
        return "fleet key file " + path + " can be read or written by other users (" + PosixFilePermissions.toString(p)
                + "): anyone who reads it can command this robot's agents; chmod 600 " + path;
    }

    /** First 8 hex digits of the SHA-256 of secret: names a key without revealing it. */
    public static String idOf(byte[] secret) {
        try {
            byte[] digest = MessageDigest.getInstance("SHA-256").digest(secret);
            return HexFormat.of().formatHex(digest, 0, 4);
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("this JVM has no SHA-256", e);
        }
    }

    /** The key that signs (the first). */
    public Key signing() {
        return keys.get(0);
    }

    /** The key with this id, or null. */
    public Key byId(String id) {
        return byId.get(id);
    }

    /** Ids of every key, the signing one first. */
    public List<String> ids() {
        return new ArrayList<>(byId.keySet());
    }

    /** Where the keys came from (a path, "~fleet_key"). */
    public String origin() {
        return origin;
    }

    @Override
    public String toString() {
        return "fleet keys " + ids() + " from " + origin;
    }
}
