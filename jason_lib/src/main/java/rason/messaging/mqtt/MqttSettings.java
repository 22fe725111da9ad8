package rason.messaging.mqtt;

import java.net.URI;
import java.net.URISyntaxException;

/**
 * How a process reaches the fleet's MQTT broker.
 *
 * @param url {@code tcp://host:port}, or {@code ssl://host:port} for TLS
 * @param prefix what every topic of the fleet starts with (ends with '/')
 * @param messageTtlSeconds how long the broker keeps a message nobody took (MQTT message expiry),
 *                          and how long it keeps our session while we are away
 * @param presencePeriodNanos time between our presence heartbeats (wall clock)
 * @param username the broker user ("" for none)
 * @param passwordFile a file whose first line is that user's password ("" for none)
 * @param caFile PEM certificates of the authorities that sign the broker's TLS certificate
 *               ("" for the JVM's default trust store)
 */
public record MqttSettings(String url, String prefix, long messageTtlSeconds, long presencePeriodNanos,
        String username, String passwordFile, String caFile) {

    public static final String DEFAULT_URL = "tcp://127.0.0.1:1883";
    public static final String DEFAULT_PREFIX = "rason/";
    public static final long DEFAULT_TTL_SECONDS = 60;
    public static final long DEFAULT_PERIOD_NANOS = 500_000_000L;

    /**
     * @throws IllegalArgumentException saying which value is wrong
     */
    public MqttSettings {
        url = url == null || url.isEmpty() ? DEFAULT_URL : url;
        prefix = prefix == null ? DEFAULT_PREFIX : prefix;
        if (!prefix.isEmpty() && !prefix.endsWith("/"))
            prefix = prefix + "/";
        if (prefix.contains("+") || prefix.contains("#") || prefix.indexOf('\0') >= 0)
            throw new IllegalArgumentException("mqtt_prefix '" + prefix + "' must not contain '+', '#' or NUL");
        if (messageTtlSeconds < 1 || messageTtlSeconds > 0xFFFF_FFFFL)
            throw new IllegalArgumentException("message_ttl must be 1 s or more, not " + messageTtlSeconds);
        if (presencePeriodNanos <= 0)
            throw new IllegalArgumentException("the presence period must be more than 0");
        username = username == null ? "" : username;
        passwordFile = passwordFile == null ? "" : passwordFile;
        caFile = caFile == null ? "" : caFile;
        URI u = uri(url);
        if (!tls(u) && !u.getScheme().equals("tcp") && !u.getScheme().equals("mqtt"))
            throw new IllegalArgumentException("mqtt_url '" + url + "' must start with tcp:// or ssl://");
        if (u.getHost() == null)
            throw new IllegalArgumentException("mqtt_url '" + url + "' names no host");
    }

    /** The defaults with the broker at url. */
    public static MqttSettings of(String url) {
        return new MqttSettings(url, DEFAULT_PREFIX, DEFAULT_TTL_SECONDS, DEFAULT_PERIOD_NANOS, "", "", "");
    }

    public String host() {
        return uri(url).getHost();
    }

    public int port() {
        URI u = uri(url);
        return u.getPort() > 0 ? u.getPort() : tls(u) ? 8883 : 1883;
    }

    public boolean tls() {
        return tls(uri(url));
    }

    private static boolean tls(URI u) {
        return u.getScheme().equals("ssl") || u.getScheme().equals("mqtts") || u.getScheme().equals("tls");
    }

    private static URI uri(String url) {
        try {
            URI u = new URI(url);
            if (u.getScheme() == null)
                throw new IllegalArgumentException("mqtt_url '" + url + "' must start with tcp:// or ssl://");
            return u;
        } catch (URISyntaxException e) {
            throw new IllegalArgumentException("mqtt_url '" + url + "' is not a URL: " + e.getMessage());
        }
    }
}
