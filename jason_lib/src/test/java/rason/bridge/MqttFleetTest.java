package rason.bridge;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static rason.bridge.RunningAgents.await;
import static rason.bridge.RunningAgents.believes;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.logging.Handler;
import java.util.logging.LogRecord;
import java.util.logging.Logger;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;

import com.hivemq.client.mqtt.MqttGlobalPublishFilter;
import com.hivemq.client.mqtt.datatypes.MqttQos;
import com.hivemq.client.mqtt.mqtt5.Mqtt5BlockingClient;
import com.hivemq.client.mqtt.mqtt5.Mqtt5Client;
import com.hivemq.client.mqtt.mqtt5.message.publish.Mqtt5Publish;

import jason.asSyntax.ASSyntax;
import rason.RosAgArch;
import rason.messaging.FleetAuth;
import rason.messaging.mqtt.BlackHoleProxy;
import rason.messaging.mqtt.MosquittoBroker;
import rason.messaging.mqtt.MqttSettings;
import rason.messaging.mqtt.TestPayloads;

/**
 * Two robots (two Bridges in this JVM) over a real mosquitto: presence both ways, a tell
 * delivered exactly once, duplicates and whatever a client without the fleet key publishes
 * dropped, and a robot that dies without leaving noticed gone within 2 s.
 */
class MqttFleetTest {

    private static final String ROBOT1 = "/robot1/rason_mas", ROBOT2 = "/robot2/rason_mas";
    /** A test key (never used outside tests): both robots share it. */
    private static final String KEY = "test-mqtt-key-0123456789abcdef0123456789abcdef";
    private static final long PERIOD_NANOS = 200_000_000L;
    private static final long DEPARTURE_LIMIT_NANOS = 2_000_000_000L;

    private final Bridge robot1 = new Bridge();
    private final Bridge robot2 = new Bridge();
    @RegisterExtension
    final RunningAgents agents1 = new RunningAgents(robot1);
    @RegisterExtension
    final RunningAgents agents2 = new RunningAgents(robot2);

    @TempDir
    Path dir;

    private MosquittoBroker broker;
    private boolean authOff = false;
    /** robot1's way to the broker, if not direct. */
    private BlackHoleProxy robot1Link = null;
    private long presenceTimeoutNanos = DEPARTURE_LIMIT_NANOS;
    private java.util.function.Function<String, MqttSettings> settingsOf = url -> new MqttSettings(url, "rason/", 60,
            PERIOD_NANOS, "", "", "");
    private final List<String> warnings = new CopyOnWriteArrayList<>();
    private final Handler capture = new Handler() {
        @Override
        public void publish(LogRecord r) {
            warnings.add(r.getMessage());
        }

        @Override
        public void flush() {
        }

        @Override
        public void close() {
        }
    };
    private final List<Mqtt5BlockingClient> rawClients = new CopyOnWriteArrayList<>();

    @BeforeEach
    void startBroker() throws Exception {
        broker = MosquittoBroker.start(dir);
        Logger.getLogger("rason.bridge").addHandler(capture);
    }

    @AfterEach
    void stopBroker() throws Exception {
        for (Mqtt5BlockingClient c : rawClients)
            if (c.getState().isConnected())
                c.disconnect();
        robot1.leaveFleet(1000);
        robot2.leaveFleet(1000);
        if (robot1Link != null)
            robot1Link.close();
        Logger.getLogger("rason.bridge").removeHandler(capture);
        if (broker != null)
            broker.close();
    }

    /** A robot on the broker with the fleet key, before its agents start. */
    private void join(Bridge robot, String mas) {
        robot.fleet().setMasId(mas);
        robot.fleet().setIncarnation(FleetAuth.wallNanos());
        if (authOff)
            robot.fleet().authOff();
        else
            robot.fleet().requireKeyText(KEY, "test");
        robot.fleet().setPresenceTimeoutNanos(presenceTimeoutNanos);
        String url = robot == robot1 && robot1Link != null ? robot1Link.url() : broker.url();
        robot.useMqtt(settingsOf.apply(url));
    }

    private RosAgArch start(RunningAgents agents, String name, String program) throws Exception {
        Path d = Files.createDirectories(dir.resolve(name));
        return agents.start(d, name, program);
    }

    private static final String ALICE = "+present(bob) : not sent <- +sent; .send(bob, tell, hello(1)); .send(bob, tell, done).";
    private static final String BOB = "heard(0).\n"
            + "+hello(N)[source(S)] : heard(C) <- -+heard(C + 1); -hello(N)[source(S)].\n"
            + "+done[source(S)] <- +finished(S).";

    /** Both robots up, alice's hello at bob (exactly once), and bob's arch. */
    private RosAgArch twoRobotsAndAHello() throws Exception {
        join(robot1, ROBOT1);
        join(robot2, ROBOT2);
        RosAgArch bob = start(agents2, "bob", BOB);
        RosAgArch alice = start(agents1, "alice", ALICE);
        await("robot2 sees alice", () -> robot2.fleet().fleet().reachable().contains("alice"));
        await("robot1 sees bob", () -> robot1.fleet().fleet().reachable().contains("bob"));
        await("alice believes bob present", () -> believes(alice, "present(bob)"));
        await("bob believes alice present", () -> believes(bob, "present(alice)"));
        await("alice's messages at bob", () -> believes(bob, "finished(alice)"));
        assertTrue(believes(bob, "heard(1)"), "the tell arrived exactly once");
        return bob;
    }

    @Test
    void presenceBothWaysAndATellExactlyOnce() throws Exception {
        RosAgArch bob = twoRobotsAndAHello();
        assertTrue(robot1.mqttChannel().isConnected());
        assertFalse(believes(bob, "heard(2)"));
    }

    private Mqtt5BlockingClient keylessClient(String id) {
        Mqtt5BlockingClient c = Mqtt5Client.builder().identifier(id).serverHost("127.0.0.1")
                .serverPort(broker.port()).buildBlocking();
        c.connect();
        rawClients.add(c);
        return c;
    }

    private long warningsWith(String text) {
        return warnings.stream().filter(w -> w != null && w.contains(text)).count();
    }

    @Test
    void copiesOfAMessagePlayedAgainAreDroppedAsDuplicates() throws Exception {
        // a client without the key records what goes to robot2's inbox
        Mqtt5BlockingClient spy = keylessClient("spy");
        BlockingQueue<Mqtt5Publish> seen = new LinkedBlockingQueue<>();
        spy.toAsync().publishes(MqttGlobalPublishFilter.ALL, seen::add);
        spy.subscribeWith().topicFilter("rason/inbox/#").qos(MqttQos.AT_LEAST_ONCE).send();
        RosAgArch bob = twoRobotsAndAHello();
        Mqtt5Publish hello = seen.poll(10, TimeUnit.SECONDS);
        assertNotNull(hello, "the spy saw the hello");
        long before = warningsWith("replayed");
        for (int i = 0; i < 3; i++)
            spy.publish(Mqtt5Publish.builder().topic(hello.getTopic()).qos(MqttQos.AT_LEAST_ONCE)
                    .payload(hello.getPayloadAsBytes()).build());
        await("three copies dropped as replayed", () -> warningsWith("replayed") >= before + 3);
        assertTrue(believes(bob, "heard(1)"), "still heard once");
        assertFalse(believes(bob, "heard(2)"));
    }

    @Test
    void withAuthenticationOffTheChannelItselfDropsDuplicates() throws Exception {
        authOff = true;
        Mqtt5BlockingClient spy = keylessClient("spy");
        BlockingQueue<Mqtt5Publish> seen = new LinkedBlockingQueue<>();
        spy.toAsync().publishes(MqttGlobalPublishFilter.ALL, seen::add);
        spy.subscribeWith().topicFilter("rason/inbox/#").qos(MqttQos.AT_LEAST_ONCE).send();
        RosAgArch bob = twoRobotsAndAHello();
        Mqtt5Publish hello = seen.poll(10, TimeUnit.SECONDS);
        assertNotNull(hello, "the spy saw the hello");
        for (int i = 0; i < 3; i++)
            spy.publish(Mqtt5Publish.builder().topic(hello.getTopic()).qos(MqttQos.AT_LEAST_ONCE)
                    .payload(hello.getPayloadAsBytes()).build());
        await("three copies dropped", () -> robot2.mqttChannel().duplicatesDropped() >= 3);
        assertTrue(believes(bob, "heard(1)"), "still heard once");
        assertFalse(believes(bob, "heard(2)"));
    }

    @Test
    void aChannelThatLeftTakesNoMoreMessages() throws Exception {
        join(robot1, ROBOT1);
        join(robot2, ROBOT2);
        RosAgArch bob = start(agents2, "bob", BOB);
        RosAgArch alice = start(agents1, "alice", ALICE
                + "\n+!late <- .send(bob, tell, late).\n-!late[error(E)] <- +failed(E).");
        await("alice's messages at bob", () -> believes(bob, "finished(alice)"));
        robot1.leaveFleet(1000);
        alice.getTS().getC().addAchvGoal(ASSyntax.parseLiteral("late"), null);
        alice.wakeUpSense();
        await("alice's send fails with bridge_error", () -> believes(alice, "failed(bridge_error)"));
        assertFalse(robot1.mqttChannel().send(new rason.messaging.WireMessage(ROBOT1, "alice", ROBOT2, "bob", "tell",
                "late", "mid_late", "")), "refused: the agent's intention fails");
        assertFalse(robot1.mqttChannel().announceNow());
    }

    @Test
    void whatAClientWithoutTheKeyPublishesChangesNothing() throws Exception {
        RosAgArch bob = twoRobotsAndAHello();
        Mqtt5BlockingClient mallory = keylessClient("mallory");
        long now = FleetAuth.wallNanos();
        byte[] badMac = new byte[FleetAuth.MAC_BYTES];
        FleetAuth.Signed forged = new FleetAuth.Signed(now, 1_000_000, now, "k1", badMac);
        // a hello "from alice" without a valid mac, a presence of a robot3, and a will of robot1
        mallory.publish(Mqtt5Publish.builder().topic("rason/inbox/robot2/rason_mas").qos(MqttQos.AT_LEAST_ONCE)
                .payload(TestPayloads.message(new rason.messaging.WireMessage(ROBOT1, "alice", ROBOT2, "bob", "tell",
                        "hello(2)", "mid_forged", ""), forged)).build());
        mallory.publish(Mqtt5Publish.builder().topic("rason/presence/robot3/rason_mas").qos(MqttQos.AT_LEAST_ONCE)
                .payload(TestPayloads.presence("/robot3/rason_mas", new String[] { "mallory" }, "x", forged)).build());
        mallory.publish(Mqtt5Publish.builder().topic("rason/presence/robot1/rason_mas").qos(MqttQos.AT_LEAST_ONCE)
                .payload(TestPayloads.will(ROBOT1, "x", forged)).build());
        mallory.publish(Mqtt5Publish.builder().topic("rason/broadcast").qos(MqttQos.AT_LEAST_ONCE)
                .payload(new byte[] { 1, 'M', 0, 0 }).build());
        await("the forged message dropped", () -> warningsWith("dropped message tell from alice") >= 1);
        await("the forged presence dropped", () -> warningsWith("dropped presence of /robot3/rason_mas") >= 1);
        await("the forged will dropped", () -> warningsWith("dropped last will of " + ROBOT1) >= 1);
        await("the unreadable payload dropped", () -> warningsWith("mqtt: dropped what arrived on rason/broadcast") >= 1);
        assertTrue(believes(bob, "heard(1)"));
        assertFalse(believes(bob, "present(mallory)"));
        assertTrue(robot2.fleet().fleet().reachable().contains("alice"), "alice is still present");
        assertFalse(robot2.fleet().fleet().reachable().contains("mallory"));
    }

    @Test
    void aRobotWhoseConnectionDiesIsNoticedGoneWithinTwoSeconds() throws Exception {
        RosAgArch bob = twoRobotsAndAHello();
        long t0 = System.nanoTime();
        robot1.mqttChannel().abandon(); // as if its process died: the broker sends its will
        await("robot2 notices alice gone", () -> !robot2.fleet().fleet().reachable().contains("alice"));
        long took = System.nanoTime() - t0;
        System.out.printf("departure noticed after %.0f ms (last will)%n", took / 1e6);
        assertTrue(took < DEPARTURE_LIMIT_NANOS, "noticed after " + took / 1e6 + " ms");
        await("bob's present(alice) goes", () -> !believes(bob, "present(alice)"));
    }

    @Test
    void aRobotWhoseConnectionIsCutIsNoticedGoneWithinTwoSeconds() throws Exception {
        robot1Link = new BlackHoleProxy(broker.port());
        RosAgArch bob = twoRobotsAndAHello();
        long t0 = System.nanoTime();
        robot1Link.cut(); // the broker sees the TCP connection close: it sends robot1's will
        await("robot2 notices alice gone", () -> !robot2.fleet().fleet().reachable().contains("alice"));
        long took = System.nanoTime() - t0;
        System.out.printf("departure noticed after %.0f ms (connection cut, last will)%n", took / 1e6);
        assertTrue(took < DEPARTURE_LIMIT_NANOS, "noticed after " + took / 1e6 + " ms");
        assertEquals(0, warningsWith("dropped last will"), "the will was taken");
    }

    @Test
    void aRobotWhoseLinkGoesQuietIsNoticedGoneBySilenceWithinTwoSeconds() throws Exception {
        presenceTimeoutNanos = 1_500_000_000L; // heartbeats every 0.2 s: seven may be lost before it counts
        robot1Link = new BlackHoleProxy(broker.port());
        twoRobotsAndAHello();
        long t0 = System.nanoTime();
        robot1Link.blackHole(); // no close reaches the broker: no will before its keep-alive runs out (3 s)
        await("robot2 notices alice gone", () -> !robot2.fleet().fleet().reachable().contains("alice"));
        long took = System.nanoTime() - t0;
        System.out.printf("departure noticed after %.0f ms (heartbeat silence)%n", took / 1e6);
        assertTrue(took < DEPARTURE_LIMIT_NANOS, "noticed after " + took / 1e6 + " ms");
        assertEquals(0, warningsWith("dropped last will"));
    }

    @Test
    void aStallOfTheMessageConnectionAloneMakesNoRobotLookGoneAndWhatWasSentArrivesOnce() throws Exception {
        robot1Link = new BlackHoleProxy(broker.port());
        join(robot1, ROBOT1);
        join(robot2, ROBOT2);
        RosAgArch bob = start(agents2, "bob", BOB);
        RosAgArch alice = start(agents1, "alice", ALICE + "\n+!again <- .send(bob, tell, hello(2)); .send(bob, tell, done2).");
        await("alice's messages at bob", () -> believes(bob, "finished(alice)"));
        // robot1's connection for messages and presence stalls as TCP does when a segment is lost
        // again and again; its pulse connection does not. The stall outlasts the presence timeout
        // (2 s) and the broker's keep-alive (3 s), whose end sends robot1's last will.
        robot1Link.stallAllBut(".pulse");
        alice.getTS().getC().addAchvGoal(ASSyntax.parseLiteral("again"), null);
        alice.wakeUpSense();
        long start = System.nanoTime(), deadline = start + 10_000_000_000L;
        while (System.nanoTime() - start < 2_500_000_000L || warningsWith("connection ended while its pulse is heard") == 0) {
            assertTrue(robot2.fleet().fleet().reachable().contains("alice"), "robot2 lost alice during the stall");
            assertTrue(robot1.fleet().fleet().reachable().contains("bob"), "robot1 lost bob during the stall");
            assertTrue(System.nanoTime() < deadline, "robot1's will did not come within 10 s of the stall");
            Thread.sleep(20);
        }
        System.out.printf("will held %.0f ms into the stall%n", (System.nanoTime() - start) / 1e6);
        assertFalse(believes(bob, "heard(2)"), "nothing passed the stall");
        robot1Link.heal();
        await("the hello sent during the stall", () -> believes(bob, "heard(2)") && believes(bob, "done2"));
        assertTrue(believes(bob, "present(alice)") && believes(alice, "present(bob)"));
    }

    @Test
    void robotsThatStartBeforeTheBrokerOrOutliveItFindEachOtherAgainAndMessagesGoOnce() throws Exception {
        int port = broker.port();
        broker.close(); // nobody listens: the robots keep trying
        join(robot1, ROBOT1);
        join(robot2, ROBOT2);
        RosAgArch bob = start(agents2, "bob", BOB);
        RosAgArch alice = start(agents1, "alice", ALICE + "\n+!again <- .send(bob, tell, hello(2)); .send(bob, tell, done2).");
        broker = MosquittoBroker.start(dir, port);
        long up = System.nanoTime();
        await("alice's messages at bob", () -> believes(bob, "finished(alice)"));
        System.out.printf("first hello %.0f ms after the broker came up%n", (System.nanoTime() - up) / 1e6);
        assertTrue(believes(bob, "heard(1)"));
        broker.close(); // the broker goes away and comes back: each robot's session is gone with it
        broker = MosquittoBroker.start(dir, port);
        up = System.nanoTime();
        await("both reconnected", () -> robot1.mqttChannel().isConnected() && robot2.mqttChannel().isConnected());
        await("robot1 sees bob again", () -> robot1.fleet().fleet().reachable().contains("bob"));
        System.out.printf("reconnected and present again %.0f ms after the broker came back%n",
                (System.nanoTime() - up) / 1e6);
        alice.getTS().getC().addAchvGoal(ASSyntax.parseLiteral("again"), null);
        alice.wakeUpSense();
        await("the second hello", () -> believes(bob, "heard(2)"));
        await("and the message after it", () -> believes(bob, "done2"));
        assertFalse(believes(bob, "heard(3)"), "each hello once");
    }

    @Test
    void overTlsWithAPasswordTheRobotsTalkAndAWrongPasswordGetsNoConnection() throws Exception {
        broker.close();
        Path tls = Files.createDirectories(dir.resolve("tls"));
        broker = MosquittoBroker.startTls(tls, "robots", "s3cret");
        Files.writeString(tls.resolve("password"), "s3cret\n");
        Files.writeString(tls.resolve("wrong"), "guess\n");
        String ssl = "ssl://127.0.0.1:" + broker.port();
        settingsOf = url -> new MqttSettings(ssl, "rason/", 60, PERIOD_NANOS, "robots",
                tls.resolve("password").toString(), tls.resolve("ca.pem").toString());
        twoRobotsAndAHello();
        Bridge intruder = new Bridge();
        intruder.fleet().setMasId("/robot3/rason_mas");
        intruder.fleet().requireKeyText(KEY, "test");
        var refused = intruder.useMqtt(new MqttSettings(ssl, "rason/", 60, PERIOD_NANOS, "robots",
                tls.resolve("wrong").toString(), tls.resolve("ca.pem").toString()));
        var untrusting = new Bridge();
        untrusting.fleet().setMasId("/robot4/rason_mas");
        untrusting.fleet().requireKeyText(KEY, "test");
        var noCa = untrusting.useMqtt(new MqttSettings(ssl, "rason/", 60, PERIOD_NANOS, "robots",
                tls.resolve("password").toString(), ""));
        try {
            await("the wrong password refused", () -> warningsWith("rason-robot3-rason_mas cannot connect") >= 1);
            await("the untrusted certificate refused", () -> warningsWith("rason-robot4-rason_mas cannot connect") >= 1);
            assertFalse(refused.isConnected());
            assertFalse(noCa.isConnected());
            assertFalse(robot2.fleet().fleet().reachable().contains("mallory"));
        } finally {
            refused.abandon();
            noCa.abandon();
        }
    }

    @Test
    void aRobotThatLeavesIsGoneAtOnce() throws Exception {
        twoRobotsAndAHello();
        long t0 = System.nanoTime();
        robot1.leaveFleet(1000);
        await("robot2 notices alice gone", () -> !robot2.fleet().fleet().reachable().contains("alice"));
        long took = System.nanoTime() - t0;
        System.out.printf("departure noticed after %.0f ms (leaving presence)%n", took / 1e6);
        assertTrue(took < DEPARTURE_LIMIT_NANOS, "noticed after " + took / 1e6 + " ms");
        assertEquals(0, warningsWith("dropped last will"), "no will was sent after a clean leave");
    }
}
