package rason.bridge;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static rason.bridge.RunningAgents.await;
import static rason.bridge.RunningAgents.believes;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.Executors;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;

import rason.RosAgArch;
import rason.messaging.FleetAuth;
import rason.messaging.FleetKeys;
import rason.messaging.WireMessage;
import rason.messaging.mqtt.MosquittoBroker;
import rason.messaging.mqtt.MqttSettings;
import rason.messaging.mqtt.SimulatedRobot;

/**
 * The benchmark's simulated robots pass for robots: a real robot (a Bridge) over mosquitto
 * takes their signed presence, delivers their signed messages to its agent and sends the
 * answers back, and notices them gone by their wills when their connections end.
 */
class SimulatedRobotTest {

    /** A test key (never used outside tests). */
    private static final String KEY = "test-sim-key-0123456789abcdef0123456789abcdef";
    private static final String OBSERVER = "/robot1/rason_mas";
    private static final String ECHO = "+!echo(R, I)[source(S)] <- .send(S, achieve, echoed(R, I)).";

    private final Bridge robot = new Bridge();
    @RegisterExtension
    final RunningAgents agents = new RunningAgents(robot);
    @TempDir
    Path dir;
    private final ScheduledExecutorService ticker = Executors.newSingleThreadScheduledExecutor();
    private MosquittoBroker broker;
    private final List<SimulatedRobot> sims = new java.util.ArrayList<>();

    @AfterEach
    void stop() throws Exception {
        for (SimulatedRobot s : sims)
            s.leave().get(5, TimeUnit.SECONDS);
        robot.leaveFleet(1000);
        ticker.shutdownNow();
        if (broker != null)
            broker.close();
    }

    private RosAgArch observer(String program) throws Exception {
        broker = MosquittoBroker.start(dir);
        robot.fleet().setMasId(OBSERVER);
        robot.fleet().setIncarnation(FleetAuth.wallNanos());
        robot.fleet().requireKeyText(KEY, "test");
        robot.useMqtt(MqttSettings.of(broker.url()));
        return agents.start(Files.createDirectories(dir.resolve("watcher")), "watcher", program);
    }

    private SimulatedRobot sim(int i, BlockingQueue<WireMessage> inbox) throws Exception {
        SimulatedRobot s = new SimulatedRobot("/sim/robot" + i + "/rason_mas", "sim" + i,
                FleetKeys.parse(KEY, "test"), MqttSettings.of(broker.url()), ticker, inbox::add);
        sims.add(s);
        s.start().get(10, TimeUnit.SECONDS);
        return s;
    }

    @Test
    void aSimulatedRobotIsPresentItsMessageIsAnsweredAndItsEndedConnectionIsNoticed() throws Exception {
        RosAgArch watcher = observer(ECHO);
        BlockingQueue<WireMessage> inbox = new LinkedBlockingQueue<>();
        SimulatedRobot s3 = sim(3, inbox);
        SimulatedRobot s4 = sim(4, new LinkedBlockingQueue<>());
        await("the observer believes sim3 and sim4 present",
                () -> believes(watcher, "present(sim3)") && believes(watcher, "present(sim4)"));

        s3.send(OBSERVER, "watcher", "achieve", "echo(1,7)", "").get(5, TimeUnit.SECONDS);
        WireMessage answer = inbox.poll(10, TimeUnit.SECONDS);
        assertEquals("echoed(1,7)", answer == null ? null : answer.content().replace(" ", ""));
        assertEquals("watcher", answer.sender());

        s4.abandon().get(5, TimeUnit.SECONDS);
        sims.remove(s4);
        await("the observer notices sim4 gone", () -> !believes(watcher, "present(sim4)"));
        assertEquals(true, believes(watcher, "present(sim3)"), "sim3 is still there");
    }
}
