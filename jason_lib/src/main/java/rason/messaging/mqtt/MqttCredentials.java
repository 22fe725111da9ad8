package rason.messaging.mqtt;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.GeneralSecurityException;
import java.security.KeyStore;
import java.security.cert.Certificate;
import java.security.cert.CertificateFactory;
import java.util.concurrent.TimeUnit;

import javax.net.ssl.TrustManagerFactory;

import com.hivemq.client.mqtt.mqtt5.Mqtt5Client;
import com.hivemq.client.mqtt.mqtt5.Mqtt5ClientBuilder;

/** The broker's credentials as the ~params give them (the CA certificates to trust, the password file), and a client that uses them. */
final class MqttCredentials {

    private MqttCredentials() {
    }

    /**
     * A client of settings' broker named clientId, reconnecting with the channel's backoff, with
     * the TLS and the user name and password that settings ask for.
     *
     * @throws IllegalArgumentException a CA or password file that cannot be read
     */
    static Mqtt5ClientBuilder client(MqttSettings settings, String clientId) {
        Mqtt5ClientBuilder b = Mqtt5Client.builder().identifier(clientId).serverHost(settings.host())
                .serverPort(settings.port()).automaticReconnect()
                .initialDelay(MqttChannel.RECONNECT_INITIAL_MS, TimeUnit.MILLISECONDS)
                .maxDelay(MqttChannel.RECONNECT_MAX_MS, TimeUnit.MILLISECONDS).applyAutomaticReconnect();
        if (settings.tls())
            b = b.sslConfig().trustManagerFactory(trust(settings.caFile())).applySslConfig();
        if (!settings.username().isEmpty())
            b = b.simpleAuth().username(settings.username()).password(password(settings.passwordFile()))
                    .applySimpleAuth();
        return b;
    }

    /**
     * The trust of a TLS connection: the system's, or the certificates of caFile alone.
     *
     * @throws IllegalArgumentException naming mqtt_ca_file and what is wrong with it
     */
    static TrustManagerFactory trust(String caFile) {
        try {
            TrustManagerFactory tmf = TrustManagerFactory.getInstance(TrustManagerFactory.getDefaultAlgorithm());
            if (caFile.isEmpty()) {
                tmf.init((KeyStore) null);
                return tmf;
            }
            KeyStore store = KeyStore.getInstance(KeyStore.getDefaultType());
            store.load(null, null);
            try (InputStream in = Files.newInputStream(Path.of(caFile))) {
                int i = 0;
                for (Certificate c : CertificateFactory.getInstance("X.509").generateCertificates(in))
                    store.setCertificateEntry("ca" + i++, c);
            }
            tmf.init(store);
            return tmf;
        } catch (IOException | GeneralSecurityException e) {
            throw new IllegalArgumentException("mqtt_ca_file '" + caFile + "': " + e.getMessage());
        }
    }

    /**
     * The password: the first line of file, without surrounding blanks (empty file name: none).
     *
     * @throws IllegalArgumentException naming mqtt_password_file and why it cannot be read
     */
    static byte[] password(String file) {
        if (file.isEmpty())
            return new byte[0];
        try {
            String text = Files.readString(Path.of(file), StandardCharsets.UTF_8);
            int end = text.indexOf('\n');
            return (end < 0 ? text : text.substring(0, end)).strip().getBytes(StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new IllegalArgumentException("mqtt_password_file '" + file + "': " + e.getMessage());
        }
    }
}
