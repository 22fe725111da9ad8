package rason.messaging.mqtt;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;

import org.junit.jupiter.api.Test;

import rason.messaging.FleetAuth;
import rason.messaging.WireMessage;

/** The MQTT channel's payloads, topics and settings: what goes out comes back the same, and nothing else is taken. */
class MqttWireTest {

    private static final FleetAuth.Signed SIGNED = new FleetAuth.Signed(-5, 7, 123456789L, "k1", new byte[] { 1, 2, 3 });

    @Test
    void aMessageComesBackFieldForField() {
        WireMessage m = new WireMessage("/r1/rason_mas", "alice", "/r2/rason_mas", "bob", "tell", "hello(\"é\")", "mid1", "");
        MqttPayloads.Message back = (MqttPayloads.Message) MqttPayloads.decode(MqttPayloads.message(m, SIGNED));
        assertEquals(m, back.message());
        assertSigned(back.signed());
    }

    @Test
    void aPresenceAndAWillComeBackFieldForField() {
        MqttPayloads.Presence p = new MqttPayloads.Presence("/r1/rason_mas", new String[] { "alice", "carol" },
                new String[] { "alice" }, new String[] { "paint" }, 0.5f, true, "link1", SIGNED);
        MqttPayloads.Presence back = (MqttPayloads.Presence) MqttPayloads.decode(MqttPayloads.presence(p));
        assertEquals(p.mas(), back.mas());
        assertArrayEquals(p.agents(), back.agents());
        assertArrayEquals(p.dfAgents(), back.dfAgents());
        assertArrayEquals(p.dfServices(), back.dfServices());
        assertEquals(0.5f, back.period());
        assertTrue(back.leaving());
        assertEquals("link1", back.link());
        assertSigned(back.signed());
        MqttPayloads.Will w = (MqttPayloads.Will) MqttPayloads
                .decode(MqttPayloads.will(new MqttPayloads.Will("/r1/rason_mas", "link1", SIGNED)));
        assertEquals("link1", w.link());
        assertSigned(w.signed());
    }

    @Test
    void cutShortOverlongOrForeignPayloadsAreRefused() {
        byte[] good = MqttPayloads.message(new WireMessage("/r1/rason_mas", "a", "", "", "tell", "x", "m", ""), SIGNED);
        for (int n = 0; n < good.length; n++) {
            byte[] cut = Arrays.copyOf(good, n);
            assertThrows(IllegalArgumentException.class, () -> MqttPayloads.decode(cut), "cut at " + n);
        }
        byte[] longer = Arrays.copyOf(good, good.length + 1);
        assertThrows(IllegalArgumentException.class, () -> MqttPayloads.decode(longer));
        assertThrows(IllegalArgumentException.class, () -> MqttPayloads.decode(new byte[] { 2, 'M' }));
        assertThrows(IllegalArgumentException.class, () -> MqttPayloads.decode(new byte[] { 1, 'X' }));
        byte[] hugeList = { 1, 'P', 0, 0, 0, 0, 0x7f, 0, 0, 0 };
        assertThrows(IllegalArgumentException.class, () -> MqttPayloads.decode(hugeList));
    }

    @Test
    void topicsNameTheProcessByItsMasId() {
        MqttTopics t = new MqttTopics("rason/");
        assertEquals("rason/presence/robot1/rason_mas", t.presence("/robot1/rason_mas"));
        assertEquals("rason/presence/rason_mas", t.presence("rason_mas"));
        assertEquals("rason/inbox/robot1/rason_mas", t.inbox("/robot1/rason_mas"));
        assertEquals("/robot1/rason_mas", t.presenceOf("rason/presence/robot1/rason_mas"));
        assertNull(t.presenceOf("rason/inbox/robot1/rason_mas"));
        assertTrue(t.isMessages("rason/broadcast") && t.isMessages("rason/inbox/robot1/rason_mas"));
        assertThrows(IllegalArgumentException.class, () -> t.inbox("/robot+/rason_mas"));
    }

    @Test
    void settingsSayWhatIsWrong() {
        MqttSettings s = MqttSettings.of("ssl://broker.lab");
        assertEquals(8883, s.port());
        assertTrue(s.tls());
        assertEquals("lab/", new MqttSettings("tcp://h:1", "lab", 1, 1, null, null, null).prefix());
        assertEquals("mqtt_url 'http://h' must start with tcp:// or ssl://",
                assertThrows(IllegalArgumentException.class, () -> MqttSettings.of("http://h")).getMessage());
        assertThrows(IllegalArgumentException.class, () -> new MqttSettings("tcp://h:1", "a/#", 1, 1, "", "", ""));
        assertThrows(IllegalArgumentException.class, () -> new MqttSettings("tcp://h:1", "a/", 0, 1, "", "", ""));
    }

    private static void assertSigned(FleetAuth.Signed s) {
        assertEquals(-5, s.incarnation());
        assertEquals(7, s.sequence());
        assertEquals(123456789L, s.stamp());
        assertEquals("k1", s.keyId());
        assertArrayEquals(new byte[] { 1, 2, 3 }, s.mac());
    }
}
