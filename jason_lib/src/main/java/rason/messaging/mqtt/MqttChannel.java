package rason.messaging.mqtt;

import java.security.SecureRandom;
import java.util.HexFormat;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.Semaphore;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.logging.Level;
import java.util.logging.Logger;


import com.hivemq.client.mqtt.MqttClientState;
import com.hivemq.client.mqtt.MqttGlobalPublishFilter;
import com.hivemq.client.mqtt.datatypes.MqttQos;
import com.hivemq.client.mqtt.mqtt5.Mqtt5AsyncClient;
import com.hivemq.client.mqtt.mqtt5.Mqtt5ClientBuilder;
import com.hivemq.client.mqtt.mqtt5.lifecycle.Mqtt5ClientReconnector;
import com.hivemq.client.mqtt.mqtt5.message.connect.Mqtt5Connect;
import com.hivemq.client.mqtt.mqtt5.message.disconnect.Mqtt5DisconnectReasonCode;
import com.hivemq.client.mqtt.mqtt5.message.publish.Mqtt5Publish;
import com.hivemq.client.mqtt.mqtt5.message.publish.Mqtt5WillPublish;
import com.hivemq.client.mqtt.mqtt5.message.subscribe.Mqtt5RetainHandling;

import rason.core.Clock;
import rason.core.RateLimitedLog;
import rason.messaging.FleetAuth;
import rason.messaging.FleetChannel;
import rason.messaging.FleetDirectory;
import rason.messaging.FleetPort;
import rason.messaging.WireMessage;

/**
 * The fleet over an MQTT 5 broker (see {@link MqttTopics} for the topics): this process's
 * client, which publishes what our agents send and our presence, and hands what arrives to
 * the {@link FleetPort}. Everything is signed end to end ({@link FleetAuth}): the broker
 * is not trusted with anything but passing bytes on.
 * <p>
 * <b>Delivery.</b> QoS 1 everywhere, a persistent session (clean start for a new run of the
 * process, resumed on reconnects) that expires, like each message, after {@code message_ttl}.
 * QoS 1 may deliver a message twice; exactly once into Jason comes from the sender's
 * (incarnation, sequence): with authentication on, {@link FleetAuth#admit} refuses any
 * sequence not above the last accepted one of that run; with it off, this channel applies the
 * same rule itself. That rule also needs each receiver to get one sender's messages in the
 * order they were signed: one thread here signs and publishes (the client keeps publish
 * order, across reconnects too), and the broker hands one subscriber its messages in order
 * (mosquitto keeps one queue per client, over the inbox and the broadcast topic).
 * <p>
 * <b>Presence.</b> A signed presence, retained on our presence topic, every presence period
 * (the heartbeat) and at once when our agents or registrations change; a signed leaving one
 * when we close; a pulse every period over a second connection ({@link MqttPulse}). A process
 * that dies without leaving: the broker publishes the last will of its connection (retained, in
 * place of its presence). A link gone quiet: after the presence timeout with no heartbeat, pulse
 * or message from it, the process counts as gone.
 * <p>
 * <b>Why a will cannot be replayed.</b> A will is signed when the connection is made and sent
 * by the broker whenever that connection ends, maybe hours later: it cannot carry a fresh
 * stamp or a sequence above the presence sent since, so FleetAuth's clock and replay checks
 * would refuse it. Instead each connection gets a random id (its link); our presence names the
 * link it goes out over, under its MAC, and the will names the link it belongs to, under its
 * MAC ({@link FleetAuth#signWill}). A receiver takes a will only if its MAC is good and its
 * link is the one the sender's current run last announced itself over
 * ({@link rason.messaging.Fleet#willArrived}). A keyless client cannot make a will, and a copy
 * of a real one is worthless once its connection is over: every reconnect makes a new link and
 * a new will, and the next presence moves the receivers to it. What is left to a broker (which
 * sees the will while the connection lives) is to publish it early, making us look gone until
 * our next heartbeat, no more than it could do by dropping our traffic.
 * <p>
 * {@link #send} and {@link #announceNow} only queue (a bounded queue, taken by the sender
 * thread): an agent's thread never waits for the network; a full queue refuses (false).
 */
public final class MqttChannel implements FleetChannel, AutoCloseable {

    /** Outgoing items the channel holds at most before refusing sends. */
    public static final int QUEUE_CAPACITY = 1000;
    /** Publishes the client holds at most (unacknowledged or waiting for a reconnect). */
    static final int MAX_IN_FLIGHT = 1000;
    /** How often silences are checked and heartbeats become due (wall clock). */
    static final long TICK_NANOS = 50_000_000L;
    /** The client's MQTT keep-alive (s): how soon the broker notices a connection that went quiet. */
    static final int KEEP_ALIVE_SECONDS = 2;
    /** Reconnect backoff bounds. */
    static final long RECONNECT_INITIAL_MS = 50, RECONNECT_MAX_MS = 1000;
    /** Senders whose last sequence is kept when the channel drops duplicates itself (authentication off). */
    static final int MAX_SENDERS = 1024;
    /** Kind of the rate-limited lines of a connection that failed or was lost. */
    public static final String LINK = "mqtt link";
    /** Kind of the rate-limited lines of what arrives and cannot be read. */
    public static final String UNREADABLE = "unreadable mqtt payload";

    private record Send(WireMessage message) {
    }

    private record Announce(boolean leaving) {
    }

    private final FleetPort port;
    private final MqttSettings settings;
    private final Logger logger;
    private final Clock wall;
    private final RateLimitedLog limited;
    private final MqttTopics topics;
    private final String masId;
    private final Mqtt5AsyncClient client;
    private final BlockingQueue<Object> queue = new ArrayBlockingQueue<>(QUEUE_CAPACITY);
    private final Semaphore inFlight = new Semaphore(MAX_IN_FLIGHT);
    private final AtomicBoolean announceQueued = new AtomicBoolean();
    private volatile boolean subscribed; // on the current connection
    private final AtomicBoolean running = new AtomicBoolean();
    private final SecureRandom random = new SecureRandom();
    private final SequenceGate duplicates = new SequenceGate(MAX_SENDERS);
    private final Thread sender;
    private final MqttPulse pulse;
    private final ScheduledExecutorService ticker;
    private volatile String link = "";
    private volatile long nextHeartbeat;
    private volatile boolean closing = false; // leaving or abandoned: nothing more is taken

    /**
     * A channel for port's process (its mas id must be set); nothing is sent before {@link #start}.
     *
     * @throws IllegalArgumentException the settings cannot be used (a CA or password file that cannot be read)
     */
    public MqttChannel(FleetPort port, MqttSettings settings, Logger logger, Clock wall) {
        this.port = port;
        this.settings = settings;
        this.logger = logger;
        this.wall = wall;
        this.limited = new RateLimitedLog(logger);
        this.topics = new MqttTopics(settings.prefix());
        this.masId = port.masId();
        topics.inbox(masId); // a mas id that cannot name a topic fails here
        Mqtt5ClientBuilder b = MqttCredentials.client(settings, clientId(masId)).addConnectedListener(c -> connected())
                .addDisconnectedListener(c -> {
                    if (c.getSource() != com.hivemq.client.mqtt.lifecycle.MqttDisconnectSource.USER)
                        limited.warn(LINK, "mqtt: " + clientId(masId) + " cannot connect to " + settings.url()
                                + " (" + c.getCause().getMessage() + "); retrying", wall.nanos());
                    // a reconnect is a new connection: a new link and will, and our session resumed
                    ((Mqtt5ClientReconnector) c.getReconnector()).connect(connectMessage(false));
                });
        client = b.buildAsync();
        client.publishes(MqttGlobalPublishFilter.ALL, this::arrived);
        pulse = new MqttPulse(masId, port.auth(), port.fleet()::pulseArrived, clientId(masId), settings, topics, wall, limited);
        sender = new Thread(this::sendLoop, "rason-mqtt-send");
        sender.setDaemon(true);
        ticker = Executors.newSingleThreadScheduledExecutor(r -> {
            Thread t = new Thread(r, "rason-mqtt-presence");
            t.setDaemon(true);
            return t;
        });
    }

    /** The broker's client id of a process: its mas id (unique in the fleet), made of safe characters. */
    static String clientId(String masId) {
        return "rason" + masId.replaceAll("[^A-Za-z0-9_]", "-");
    }

    /** Connects (in the background, retried with backoff) and starts announcing our presence. */
    public void start() {
        if (!running.compareAndSet(false, true))
            return;
        sender.start();
        nextHeartbeat = wall.nanos();
        ticker.scheduleAtFixedRate(this::tick, 0, TICK_NANOS, TimeUnit.NANOSECONDS);
        client.connect(connectMessage(true)).exceptionally(e -> null); // failures: the disconnected listener
        pulse.start();
    }

    /**
     * The CONNECT of a new connection: a fresh link and its signed will.
     *
     * @param newRun clean start (a new run of the process) rather than resuming our session
     */
    private Mqtt5Connect connectMessage(boolean newRun) {
        byte[] id = new byte[16];
        random.nextBytes(id);
        String newLink = HexFormat.of().formatHex(id);
        byte[] will = MqttPayloads.will(new MqttPayloads.Will(masId, newLink, port.signWill(newLink)));
        link = newLink;
        Mqtt5WillPublish willPublish = Mqtt5WillPublish.builder().topic(topics.presence(masId))
                .qos(MqttQos.AT_LEAST_ONCE).retain(true).payload(will)
                .messageExpiryInterval(settings.messageTtlSeconds()).delayInterval(0).build();
        return Mqtt5Connect.builder().cleanStart(newRun).sessionExpiryInterval(settings.messageTtlSeconds())
                .keepAlive(KEEP_ALIVE_SECONDS).willPublish(willPublish).build();
    }

    /** A connection is up: (re)subscribe; announce once subscribed (before, the broker drops what our inbox gets). */
    private void connected() {
        subscribed = false;
        logger.info("mqtt: connected to " + settings.url() + " as " + clientId(masId));
        client.subscribeWith().addSubscription().topicFilter(topics.allPresence()).qos(MqttQos.AT_LEAST_ONCE)
                .noLocal(true).retainHandling(Mqtt5RetainHandling.SEND_IF_SUBSCRIPTION_DOES_NOT_EXIST)
                .applySubscription().addSubscription().topicFilter(topics.inbox(masId)).qos(MqttQos.AT_LEAST_ONCE)
                .applySubscription().addSubscription().topicFilter(topics.broadcast()).qos(MqttQos.AT_LEAST_ONCE)
                .noLocal(true).applySubscription().send().whenComplete((ack, e) -> {
                    if (e != null) {
                        logger.warning("mqtt: subscribing failed: " + e.getMessage());
                        return;
                    }
                    subscribed = true;
                    announceNow();
                });
    }

    public boolean isConnected() {
        return client.getState() == MqttClientState.CONNECTED;
    }

    // ---- FleetChannel: only queues ---------------------------------------------------

    @Override
    public boolean send(WireMessage m) {
        return running.get() && !closing && queue.offer(new Send(m));
    }

    @Override
    public boolean announceNow() {
        if (!running.get() || closing)
            return false;
        if (!announceQueued.compareAndSet(false, true))
            return true; // the one queued will carry this change too
        if (queue.offer(new Announce(false)))
            return true;
        announceQueued.set(false);
        return false;
    }

    // ---- the sender thread: signs in publishing order --------------------------------

    private void sendLoop() {
        while (running.get()) {
            Object item;
            try {
                item = queue.poll(100, TimeUnit.MILLISECONDS);
            } catch (InterruptedException e) {
                return;
            }
            if (item == null)
                continue;
            try {
                if (item instanceof Send s)
                    publish(s.message());
                else if (item instanceof Announce a)
                    send(presence(a.leaving()));
            } catch (InterruptedException e) {
                return;
            } catch (RuntimeException e) {
                limited.warn("mqtt send failed", "mqtt: could not send: " + e, wall.nanos());
            }
        }
    }

    private void publish(WireMessage m) throws InterruptedException {
        FleetAuth.Signed signed = port.sign(m);
        String topic = m.receiverMas().isEmpty() ? topics.broadcast() : topics.inbox(m.receiverMas());
        send(Mqtt5Publish.builder().topic(topic).qos(MqttQos.AT_LEAST_ONCE).payload(MqttPayloads.message(m, signed))
                .messageExpiryInterval(settings.messageTtlSeconds()).build());
    }

    /** Our presence, signed now: call in the order of publishing. */
    private Mqtt5Publish presence(boolean leave) {
        FleetDirectory.Announced df = port.announced();
        announceQueued.set(false);
        String[] agents = port.names().localAgents();
        float period = (float) (settings.presencePeriodNanos() / 1e9);
        String over = link;
        FleetAuth.Signed signed = port.signPresence(agents, df.agents(), df.services(), period, leave, over);
        byte[] payload = MqttPayloads.presence(new MqttPayloads.Presence(masId, agents, df.agents(), df.services(),
                period, leave, over, signed));
        nextHeartbeat = wall.nanos() + settings.presencePeriodNanos();
        return Mqtt5Publish.builder().topic(topics.presence(masId)).qos(MqttQos.AT_LEAST_ONCE).retain(true)
                .payload(payload).messageExpiryInterval(settings.messageTtlSeconds()).build();
    }

    /** Hands one publish to the client; waits (on the sender thread only) while too many are in flight. */
    private CompletableFuture<?> send(Mqtt5Publish publish) throws InterruptedException {
        inFlight.acquire();
        return client.publish(publish).whenComplete((result, e) -> {
            inFlight.release();
            Throwable error = e != null ? e : result.getError().orElse(null);
            if (error != null)
                limited.warn("mqtt publish failed", "mqtt: publishing on " + publish.getTopic() + " failed: "
                        + error.getMessage(), wall.nanos());
        });
    }

    // ---- the presence thread: silences and heartbeats -------------------------------

    private void tick() {
        try {
            long now = wall.nanos();
            if (!closing) {
                port.presenceTickAllLinked();
                pulse.beat();
                if (now - nextHeartbeat >= 0 && isConnected() && subscribed)
                    announceNow();
            }
            limited.tick(now);
        } catch (RuntimeException e) { // a failed tick must not end the ticking
            limited.warn("mqtt tick failed", "mqtt: presence tick failed: " + e, wall.nanos());
        }
    }

    // ---- what arrives (on the client's thread) ---------------------------------------

    private void arrived(Mqtt5Publish p) {
        String topic = p.getTopic().toString();
        Object payload;
        try {
            payload = MqttPayloads.decode(p.getPayloadAsBytes());
        } catch (IllegalArgumentException e) {
            limited.warn(UNREADABLE, "mqtt: dropped what arrived on " + topic + ": " + e.getMessage(), wall.nanos());
            return;
        }
        try {
            String presenceOf = topics.presenceOf(topic);
            if (p.isRetain() && (payload instanceof MqttPayloads.Will
                    || payload instanceof MqttPayloads.Presence pr && pr.leaving()))
                return; // kept by the broker for newcomers: news of a departure we never saw an arrival of
            if (presenceOf != null && payload instanceof MqttPayloads.Presence pr)
                // published on presenceOf's topic: a presence naming another process is forged
                port.presenceAnnounced(pr.mas(), pr.signed().incarnation(), pr.agents(), pr.dfAgents(),
                        pr.dfServices(), pr.period(), pr.leaving(), pr.signed().sequence(), pr.signed().stamp(),
                        pr.signed().keyId(), pr.signed().mac(), presenceOf, pr.link());
            else if (presenceOf != null && payload instanceof MqttPayloads.Will w)
                port.willArrived(w.mas(), w.link(), w.signed(), presenceOf);
            else if (topics.isMessages(topic) && payload instanceof MqttPayloads.Message m) {
                if (!port.auth().required() && duplicates.seenBefore(m.message().senderMas(), m.signed()))
                    return;
                port.deliver(m.message(), m.signed(), "");
            } else
                limited.warn(UNREADABLE, "mqtt: dropped a " + payload.getClass().getSimpleName() + " on " + topic,
                        wall.nanos());
        } catch (RuntimeException e) { // a bug must not kill the client's thread
            logger.log(Level.SEVERE, "mqtt: could not take what arrived on " + topic, e);
        }
    }

    /** Duplicates this channel dropped itself (authentication off; with it on, FleetAuth drops them). */
    public long duplicatesDropped() {
        return duplicates.dropped();
    }

    // ---- leaving -----------------------------------------------------------------------

    /**
     * Leaves the fleet: a signed leaving presence goes out (waiting up to timeoutMillis for the
     * broker to take it), then the connection closes cleanly, so the will is not sent.
     */
    public void leave(long timeoutMillis) {
        if (!running.get())
            return;
        closing = true;
        running.set(false);
        ticker.shutdownNow();
        pulse.close(timeoutMillis).join();
        sender.interrupt();
        try {
            sender.join(timeoutMillis);
            // the sender thread is done: the leaving presence is signed after everything it sent
            if (isConnected())
                client.publish(presence(true)).get(timeoutMillis, TimeUnit.MILLISECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } catch (Exception e) {
            logger.warning("mqtt: the leaving presence may not have gone out: " + e);
        }
        // a clean leave ends the session too: nothing is kept for a process that is gone
        client.disconnectWith().sessionExpiryInterval(0).send().orTimeout(timeoutMillis, TimeUnit.MILLISECONDS)
                .exceptionally(e -> null).join();
    }

    @Override
    public void close() {
        leave(1000);
    }

    /**
     * Ends the connection as if this process died: the broker sends our will; nothing is
     * announced. For tests of departure.
     */
    public void abandon() {
        closing = true;
        running.set(false);
        ticker.shutdownNow();
        pulse.close(1000).join();
        sender.interrupt();
        client.disconnectWith().reasonCode(Mqtt5DisconnectReasonCode.DISCONNECT_WITH_WILL_MESSAGE).send()
                .orTimeout(1, TimeUnit.SECONDS).exceptionally(e -> null).join();
    }
}
