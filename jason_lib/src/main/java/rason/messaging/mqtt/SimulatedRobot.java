package rason.messaging.mqtt;

import java.security.SecureRandom;
import java.util.HexFormat;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;

import com.hivemq.client.mqtt.MqttGlobalPublishFilter;
import com.hivemq.client.mqtt.datatypes.MqttQos;
import com.hivemq.client.mqtt.mqtt5.Mqtt5AsyncClient;
import com.hivemq.client.mqtt.mqtt5.lifecycle.Mqtt5ClientReconnector;
import com.hivemq.client.mqtt.mqtt5.message.connect.Mqtt5Connect;
import com.hivemq.client.mqtt.mqtt5.message.disconnect.Mqtt5DisconnectReasonCode;
import com.hivemq.client.mqtt.mqtt5.message.publish.Mqtt5Publish;
import com.hivemq.client.mqtt.mqtt5.message.publish.Mqtt5WillPublish;

import rason.core.Clock;
import rason.core.RateLimitedLog;
import rason.messaging.FleetAuth;
import rason.messaging.FleetKeys;
import rason.messaging.Receipts;
import rason.messaging.WireMessage;

/**
 * A light stand-in for a robot's rason_mas on the fleet's broker, for benchmarks: one MQTT 5
 * connection that announces one agent the way {@link MqttChannel} does (a signed, retained
 * presence every presence period over a connection named by a random link, a signed last will
 * of that link, the same keep-alive and reconnects, and pulses over a second one), sends
 * receipts for what it is sent as rason_mas does, sends signed agent messages and hands the
 * messages that reach its inbox to a consumer. No Jason, no ROS: a hundred fit in one JVM.
 */
public final class SimulatedRobot {

    private final String masId;
    private final String agent;
    private final MqttSettings settings;
    private final MqttTopics topics;
    private final FleetAuth auth;
    private final ScheduledExecutorService ticker;
    private final Mqtt5AsyncClient client;
    private final MqttPulse pulse;
    private final SecureRandom random = new SecureRandom();
    private final Object presenceOrder = new Object();
    private final Object messageOrder = new Object();
    private volatile String link = "";
    private volatile ScheduledFuture<?> heartbeats;
    private volatile boolean gone = false;

    /**
     * @param masId the process this robot pretends to be (e.g. {@code /sim/robot7/rason_mas})
     * @param agent its one agent's name
     * @param keys the fleet keys (it signs with keys.signing())
     * @param ticker runs the heartbeats (shared by all robots of a JVM)
     * @param received what arrives in its inbox, on the client's thread
     */
    public SimulatedRobot(String masId, String agent, FleetKeys keys, MqttSettings settings,
            ScheduledExecutorService ticker, Consumer<WireMessage> received) {
        this.masId = masId;
        this.agent = agent;
        this.settings = settings;
        this.topics = new MqttTopics(settings.prefix());
        this.ticker = ticker;
        this.auth = new FleetAuth();
        auth.require(keys);
        auth.setIncarnation(FleetAuth.wallNanos());
        topics.inbox(masId); // a mas id that cannot name a topic fails here
        client = MqttCredentials.client(settings, MqttChannel.clientId(masId)).addConnectedListener(c -> connected())
                .addDisconnectedListener(c -> ((Mqtt5ClientReconnector) c.getReconnector()).connect(connectMessage(false)))
                .buildAsync();
        pulse = new MqttPulse(masId, auth, null, MqttChannel.clientId(masId), settings, topics, Clock.WALL,
                new RateLimitedLog(java.util.logging.Logger.getLogger("rason.bench.simulated")));
        client.publishes(MqttGlobalPublishFilter.ALL, p -> {
            try {
                if (MqttPayloads.decode(p.getPayloadAsBytes()) instanceof MqttPayloads.Message m) {
                    if (Receipts.wanted(m.message())) // its sender waits for it, as from a rason_mas
                        publishSigned(Receipts.of(m.message(), agent, masId, false));
                    received.accept(m.message());
                }
            } catch (IllegalArgumentException e) {
                // not one of ours: a benchmark robot ignores it
            }
        });
    }

    public String masId() {
        return masId;
    }

    public String agent() {
        return agent;
    }

    /** Connects (a clean start), subscribes its inbox and starts the heartbeats and pulses; completes once connected. */
    public CompletableFuture<?> start() {
        pulse.start();
        return client.connect(connectMessage(true));
    }

    /** A new connection: a fresh link and its signed will, as {@link MqttChannel} makes them. */
    private Mqtt5Connect connectMessage(boolean newRun) {
        byte[] id = new byte[16];
        random.nextBytes(id);
        String newLink = HexFormat.of().formatHex(id);
        byte[] will = MqttPayloads.will(new MqttPayloads.Will(masId, newLink, auth.signWill(masId, newLink)));
        link = newLink;
        Mqtt5WillPublish willPublish = Mqtt5WillPublish.builder().topic(topics.presence(masId))
                .qos(MqttQos.AT_LEAST_ONCE).retain(true).payload(will)
                .messageExpiryInterval(settings.messageTtlSeconds()).delayInterval(0).build();
        return Mqtt5Connect.builder().cleanStart(newRun).sessionExpiryInterval(settings.messageTtlSeconds())
                .keepAlive(MqttChannel.KEEP_ALIVE_SECONDS).willPublish(willPublish).build();
    }

    private void connected() {
        if (gone)
            return;
        client.subscribeWith().topicFilter(topics.inbox(masId)).qos(MqttQos.AT_LEAST_ONCE).send();
        announce(false);
        if (heartbeats == null)
            heartbeats = ticker.scheduleAtFixedRate(() -> {
                announce(false);
                pulse.beatNow(Clock.WALL.nanos());
            }, settings.presencePeriodNanos(),
                    settings.presencePeriodNanos(), TimeUnit.NANOSECONDS);
    }

    /** One signed presence (leaving or not) over the current link; signed and handed on in one step. */
    private CompletableFuture<?> announce(boolean leaving) {
        synchronized (presenceOrder) {
            if (gone && !leaving)
                return CompletableFuture.completedFuture(null);
            String over = link;
            String[] agents = { agent };
            float period = (float) (settings.presencePeriodNanos() / 1e9);
            FleetAuth.Signed signed = auth.signPresence(masId, List.of(agents), List.of(), List.of(), period, leaving,
                    over);
            byte[] payload = MqttPayloads.presence(new MqttPayloads.Presence(masId, agents, new String[0],
                    new String[0], period, leaving, over, signed));
            return client.publish(Mqtt5Publish.builder().topic(topics.presence(masId)).qos(MqttQos.AT_LEAST_ONCE)
                    .retain(true).payload(payload).messageExpiryInterval(settings.messageTtlSeconds()).build());
        }
    }

    /** A signed agent message from this robot's agent to receiver of receiverMas. */
    public CompletableFuture<?> send(String receiverMas, String receiver, String performative, String content,
            String msgId) {
        return publishSigned(new WireMessage(masId, agent, receiverMas, receiver, performative, content, msgId, ""));
    }

    private CompletableFuture<?> publishSigned(WireMessage m) {
        String receiverMas = m.receiverMas();
        synchronized (messageOrder) {
            FleetAuth.Signed signed = auth.sign(m);
            return client.publish(Mqtt5Publish.builder().topic(topics.inbox(receiverMas)).qos(MqttQos.AT_LEAST_ONCE)
                    .payload(MqttPayloads.message(m, signed)).messageExpiryInterval(settings.messageTtlSeconds())
                    .build());
        }
    }

    private void stopHeartbeats() {
        gone = true;
        ScheduledFuture<?> h = heartbeats;
        if (h != null)
            h.cancel(false);
    }

    /** Ends the connections as a dead process would: the broker publishes the will. */
    public CompletableFuture<?> abandon() {
        stopHeartbeats();
        pulse.close(1000);
        return client.disconnectWith().reasonCode(Mqtt5DisconnectReasonCode.DISCONNECT_WITH_WILL_MESSAGE).send()
                .orTimeout(2, TimeUnit.SECONDS).exceptionally(e -> null);
    }

    /** A signed leaving presence, then a clean disconnect that ends the session. */
    public CompletableFuture<?> leave() {
        stopHeartbeats();
        pulse.close(1000);
        return announce(true).orTimeout(2, TimeUnit.SECONDS).exceptionally(e -> null)
                .thenCompose(x -> client.disconnectWith().sessionExpiryInterval(0).send())
                .orTimeout(3, TimeUnit.SECONDS).exceptionally(e -> null);
    }
}
