package rason.messaging;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.security.MessageDigest;
import java.util.HexFormat;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class FleetKeysTest {

    private static final String A = SigningPeer.KEY_A;
    private static final String B = SigningPeer.KEY_B;

    @TempDir
    Path dir;

    private static String sha256Prefix(String secret) throws Exception {
        byte[] d = MessageDigest.getInstance("SHA-256").digest(secret.getBytes(StandardCharsets.UTF_8));
        return HexFormat.of().formatHex(d).substring(0, 8);
    }

    @Test
    void oneKeyPerLineTheFirstSignsCommentsAndBlankLinesAndSurroundingBlanksIgnored() throws Exception {
        FleetKeys keys = FleetKeys.parse("# the fleet's keys\n\n  " + B + "  \r\n# old one, remove after rotation\n" + A
                + "\n", "fleet.key");
        assertEquals(List.of(sha256Prefix(B), sha256Prefix(A)), keys.ids());
        assertEquals(sha256Prefix(B), keys.signing().id());
        assertNotNull(keys.byId(sha256Prefix(A)));
        assertNull(keys.byId("00000000"));
        assertEquals("fleet.key", keys.origin());
    }

    @Test
    void theIdIsTheStartOfTheSha256AndNeverShowsTheSecret() throws Exception {
        FleetKeys keys = FleetKeys.parse(A, "x");
        assertEquals(8, keys.signing().id().length());
        assertEquals(sha256Prefix(A), keys.signing().id());
        assertTrue(!keys.toString().contains(A) && !keys.signing().toString().contains(A));
    }

    @Test
    void aKeyShorterThan32BytesIsRefusedNamingItsLine() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> FleetKeys.parse(A + "\n# c\nshort-secret\n", "/etc/fleet.key"));
        assertTrue(e.getMessage().startsWith("/etc/fleet.key line 3: a key of 12 bytes is too short (at least 32"),
                e.getMessage());
        assertEquals(32, FleetKeys.parse("x".repeat(32), "x").signing().secret().length);
    }

    @Test
    void aFileWithoutKeysIsRefused() {
        for (String text : new String[] { "", "\n\n", "# only a comment\n   \n" }) {
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> FleetKeys.parse(text, "f"));
            assertEquals("f holds no key (only empty or # lines)", e.getMessage());
        }
    }

    @Test
    void theSameKeyTwiceIsRefused() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> FleetKeys.parse(A + "\n" + B + "\n" + A, "f"));
        assertTrue(e.getMessage().startsWith("f line 3: the same key (id "), e.getMessage());
        assertTrue(e.getMessage().endsWith(") as line 1"), e.getMessage());
    }

    @Test
    void loadReadsAFileAndSaysWhenItIsMissing() throws Exception {
        Path file = dir.resolve("fleet.key");
        Files.writeString(file, A + "\n");
        assertEquals(sha256Prefix(A), FleetKeys.load(file).signing().id());
        assertEquals(file.toString(), FleetKeys.load(file).origin());
        Path missing = dir.resolve("none/fleet.key");
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> FleetKeys.load(missing));
        assertEquals(missing + " does not exist", e.getMessage());
    }

    @Test
    void aDirectoryIsNotAKeyFile() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> FleetKeys.load(dir));
        assertTrue(e.getMessage().startsWith("cannot read " + dir), e.getMessage());
    }

    @Test
    void aKeyFileOthersCanReadIsReported() throws Exception {
        Path file = dir.resolve("fleet.key");
        Files.writeString(file, A + "\n");
        Files.setPosixFilePermissions(file, PosixFilePermissions.fromString("rw-------"));
        assertNull(FleetKeys.tooOpen(file));
        Files.setPosixFilePermissions(file, PosixFilePermissions.fromString("r--------"));
        assertNull(FleetKeys.tooOpen(file));
        Files.setPosixFilePermissions(file, PosixFilePermissions.fromString("rw-r--r--"));
        String why = FleetKeys.tooOpen(file);
        assertNotNull(why);
        assertTrue(why.contains("(rw-r--r--)") && why.endsWith("chmod 600 " + file), why);
        Files.setPosixFilePermissions(file, PosixFilePermissions.fromString("rw--w----"));
        assertNotNull(FleetKeys.tooOpen(file), "writable by the group");
    }
}
