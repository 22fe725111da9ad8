package rason.messaging.mqtt;

import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;

import com.hivemq.client.mqtt.MqttClientState;
import com.hivemq.client.mqtt.MqttGlobalPublishFilter;
import com.hivemq.client.mqtt.datatypes.MqttQos;
import com.hivemq.client.mqtt.lifecycle.MqttDisconnectSource;
import com.hivemq.client.mqtt.mqtt5.Mqtt5AsyncClient;
import com.hivemq.client.mqtt.mqtt5.message.publish.Mqtt5Publish;

import rason.core.Clock;
import rason.core.RateLimitedLog;
import rason.messaging.FleetAuth;

/**
 * The MQTT channel's second connection, which carries nothing but pulses: ours, signed, every
 * presence period, and everyone else's. TCP hands bytes over in order, so when a segment of the
 * main connection is lost several times in a row (at 10 % loss and 100 ms delay a stall of about
 * 3 s comes every few minutes), all that follows it waits for the retransmission, heartbeats
 * included, and the process would look gone although it is alive. A pulse on a connection of
 * its own stalls only if this one stalls at the same time: a second, independent chance. Pulses
 * keep a present process present and bring back one that went away, and a last will counts for
 * nothing while its pulses are heard (see {@link rason.messaging.PresenceTable#pulse}); they
 * never announce a process, which only its presence does. QoS 0, no session: a late pulse is
 * worth nothing.
 */
final class MqttPulse {

    /** Where the pulses of others go (see {@link rason.messaging.Fleet#pulseArrived}). */
    interface Heard {
        void pulseArrived(String mas, FleetAuth.Signed signed, String publisher);
    }

    private final FleetAuth auth;
    private final Heard heard;
    private final String masId;
    private final MqttSettings settings;
    private final MqttTopics topics;
    private final Clock wall;
    private final RateLimitedLog limited;
    private final Mqtt5AsyncClient client;
    private volatile boolean subscribed; // on the current connection
    private long nextPulse; // on the caller's thread only

    /**
     * @param auth signs our pulses
     * @param heard takes the pulses of others; null: ours are sent, others' not listened to
     * @throws IllegalArgumentException the settings cannot be used (see {@link MqttCredentials#client})
     */
    MqttPulse(String masId, FleetAuth auth, Heard heard, String clientId, MqttSettings settings, MqttTopics topics,
            Clock wall, RateLimitedLog limited) {
        this.auth = auth;
        this.heard = heard;
        this.masId = masId;
        this.settings = settings;
        this.topics = topics;
        this.wall = wall;
        this.limited = limited;
        client = MqttCredentials.client(settings, clientId + ".pulse").addConnectedListener(c -> subscribe()).addDisconnectedListener(c -> {
                    subscribed = false;
                    if (c.getSource() != MqttDisconnectSource.USER)
                        limited.warn(MqttChannel.LINK, "mqtt: the pulse connection of " + clientId + " to "
                                + settings.url() + " is down (" + c.getCause().getMessage() + "); retrying", wall.nanos());
                }).buildAsync();
        client.publishes(MqttGlobalPublishFilter.ALL, this::arrived);
    }

    void start() {
        nextPulse = wall.nanos();
        client.connectWith().cleanStart(true).keepAlive(MqttChannel.KEEP_ALIVE_SECONDS).send()
                .exceptionally(e -> null); // failures: the disconnected listener, then reconnects
    }

    private void subscribe() {
        if (heard == null) {
            subscribed = true;
            return;
        }
        client.subscribeWith().topicFilter(topics.allPulses()).qos(MqttQos.AT_MOST_ONCE).noLocal(true).send()
                .whenComplete((ack, e) -> subscribed = e == null);
    }

    /** Sends our pulse when one is due (call from one thread, often). */
    void beat() {
        long now = wall.nanos();
        if (now - nextPulse >= 0)
            beatNow(now);
    }

    /** Sends our pulse now if the connection is up (call from one thread). */
    void beatNow(long now) {
        if (!subscribed || client.getState() != MqttClientState.CONNECTED)
            return;
        nextPulse = now + settings.presencePeriodNanos();
        byte[] payload = MqttPayloads.pulse(new MqttPayloads.Pulse(masId, auth.signPulse(masId)));
        client.publish(Mqtt5Publish.builder().topic(topics.pulse(masId)).qos(MqttQos.AT_MOST_ONCE).payload(payload)
                .build()).exceptionally(e -> null); // a lost pulse is what the next one is for
    }

    private void arrived(Mqtt5Publish p) {
        String topic = p.getTopic().toString();
        try {
            Object payload = MqttPayloads.decode(p.getPayloadAsBytes());
            String publisher = topics.pulseOf(topic);
            if (publisher != null && payload instanceof MqttPayloads.Pulse pulse)
                heard.pulseArrived(pulse.mas(), pulse.signed(), publisher);
            else
                limited.warn(MqttChannel.UNREADABLE, "mqtt: dropped a " + payload.getClass().getSimpleName() + " on "
                        + topic, wall.nanos());
        } catch (RuntimeException e) { // unreadable, or a bug: neither may kill the client's thread
            limited.warn(MqttChannel.UNREADABLE, "mqtt: dropped what arrived on " + topic + ": " + e.getMessage(),
                    wall.nanos());
        }
    }

    /** Closes the connection (no more pulses); completes when closed, or after timeoutMillis. */
    CompletableFuture<?> close(long timeoutMillis) {
        return client.disconnect().orTimeout(timeoutMillis, TimeUnit.MILLISECONDS).exceptionally(e -> null);
    }
}
