package rason.messaging.mqtt;

import rason.messaging.FleetAuth;
import rason.messaging.WireMessage;

/** Payloads as the MQTT channel encodes them, for tests that publish as some other client. */
public final class TestPayloads {

    private TestPayloads() {
    }

    public static byte[] message(WireMessage m, FleetAuth.Signed s) {
        return MqttPayloads.message(m, s);
    }

    public static byte[] presence(String mas, String[] agents, String link, FleetAuth.Signed s) {
        return MqttPayloads.presence(new MqttPayloads.Presence(mas, agents, new String[0], new String[0], 0.5f, false,
                link, s));
    }

    public static byte[] will(String mas, String link, FleetAuth.Signed s) {
        return MqttPayloads.will(new MqttPayloads.Will(mas, link, s));
    }
}
