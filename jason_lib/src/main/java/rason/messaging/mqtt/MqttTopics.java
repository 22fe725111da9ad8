package rason.messaging.mqtt;

/**
 * The fleet's topics under a prefix (default {@code rason/}), a process named by its
 * mas id (a ROS name such as {@code /robot1/rason_mas}, whose slashes become levels):
 * <ul>
 * <li>{@code rason/presence/robot1/rason_mas}: that process's presence, retained (its
 *     heartbeats, its leaving, and the last will of its connection);</li>
 * <li>{@code rason/inbox/robot1/rason_mas}: agent messages to that process;</li>
 * <li>{@code rason/broadcast}: agent messages to every process;</li>
 * <li>{@code rason/pulse/robot1/rason_mas}: that process's pulses (over its second connection).</li>
 * </ul>
 */
final class MqttTopics {

    private final String prefix;

    MqttTopics(String prefix) {
        this.prefix = prefix;
    }

    String presence(String masId) {
        return prefix + "presence" + levels(masId);
    }

    String allPresence() {
        return prefix + "presence/#";
    }

    String inbox(String masId) {
        return prefix + "inbox" + levels(masId);
    }

    String broadcast() {
        return prefix + "broadcast";
    }

    String pulse(String masId) {
        return prefix + "pulse" + levels(masId);
    }

    String allPulses() {
        return prefix + "pulse/#";
    }

    /** The process whose pulse topic this is, or null if it is none. */
    String pulseOf(String topic) {
        String head = prefix + "pulse/";
        return topic.startsWith(head) ? topic.substring(head.length() - 1) : null;
    }

    /** The process whose presence topic this is, or null if it is none. */
    String presenceOf(String topic) {
        String head = prefix + "presence/";
        return topic.startsWith(head) ? topic.substring(head.length() - 1) : null;
    }

    boolean isMessages(String topic) {
        return topic.equals(broadcast()) || topic.startsWith(prefix + "inbox/");
    }

    /** "/robot1/rason_mas" as topic levels ("/robot1/rason_mas"); a relative name gets its slash. */
    private static String levels(String masId) {
        if (masId.isEmpty() || masId.contains("+") || masId.contains("#") || masId.indexOf('\0') >= 0)
            throw new IllegalArgumentException("mas id '" + masId + "' cannot name an MQTT topic");
        return masId.startsWith("/") ? masId : "/" + masId;
    }
}
