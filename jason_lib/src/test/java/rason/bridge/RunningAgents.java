package rason.bridge;

import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import java.util.function.BooleanSupplier;

import org.junit.jupiter.api.extension.AfterEachCallback;
import org.junit.jupiter.api.extension.ExtensionContext;

import jason.asSemantics.Unifier;
import jason.asSyntax.ASSyntax;
import rason.RosAgArch;
import rason.infra.RasonLocalMAS;

/**
 * Real Jason agents on the bridge for a test, with nobody draining the outbox
 * but the test itself: start one agent from its program, look into its
 * beliefs, wait for a condition, and stop everything so that nothing of one
 * test reaches the next: registered as an extension
 * ({@code @RegisterExtension final RunningAgents agents = new RunningAgents(bridge);}),
 * it stops them after each test, after the test class's own {@code @AfterEach}.
 */
public final class RunningAgents implements AfterEachCallback {

    public static final long SECOND = 1_000_000_000L;
    public static final long WAIT_MS = 10_000;

    private final Bridge bridge;
    private RasonLocalMAS mas;

    /** Agents of bridge (each test makes its own). */
    public RunningAgents(Bridge bridge) {
        this.bridge = bridge;
    }

    /** Starts agent with program (in dir) at ROS time 100 s with a 60 s action timeout. */
    public RosAgArch start(Path dir, String agent, String program) throws Exception {
        return start(dir, agent, program, "");
    }

    /** The same, with the agent's .mas2j options (e.g. {@code [mindinspector="web(cycle,html,no_history)"]}). */
    public RosAgArch start(Path dir, String agent, String program, String options) throws Exception {
        Files.writeString(dir.resolve(agent + ".asl"), program);
        Files.writeString(dir.resolve("test.mas2j"), "MAS test { agents: " + agent + " " + options + "; }");
        startMas(dir);
        RosAgArch arch = arch(agent);
        assertNotNull(arch, "agent " + agent + " registered");
        return arch;
    }

    /** Several agents in one MAS, each from its program (name to program, in .mas2j order). */
    public void startAll(Path dir, Map<String, String> programs) throws Exception {
        StringBuilder agents = new StringBuilder();
        for (Map.Entry<String, String> agent : programs.entrySet()) {
            Files.writeString(dir.resolve(agent.getKey() + ".asl"), agent.getValue());
            agents.append(agent.getKey()).append("; ");
        }
        Files.writeString(dir.resolve("test.mas2j"), "MAS test { agents: " + agents + "}");
        startMas(dir);
        for (String agent : programs.keySet())
            assertNotNull(arch(agent), "agent " + agent + " registered");
    }

    private void startMas(Path dir) throws Exception {
        bridge.attach();
        bridge.actions().setTimeoutNanos(60 * SECOND);
        bridge.tick(100 * SECOND);
        mas = bridge.newMas();
        mas.load(dir.resolve("test.mas2j").toString());
        mas.create();
        while (bridge.outbox().poll() != null) {
            // the announcement of the new agent: the tests look at what the agent queues
        }
        mas.start();
    }

    /** The RosAgArch of a running agent, null if there is none of that name. */
    public RosAgArch arch(String agent) {
        var la = mas == null ? null : mas.getAg(agent);
        return la == null ? null : RosAgArch.of(la.getTS());
    }

    /**
     * What source perceives now for this agent only (a robot of a fleet perceives its own
     * sensors); {@code bridge.perception().perceive} gives every hosted agent the same.
     */
    public void perceive(String agent, String source, long nowNanos, String... literals) {
        RosAgArch a = arch(agent);
        assertNotNull(a, "agent " + agent + " runs");
        rason.perception.OneAgentPerception.perceive(a.perception(), source, nowNanos, literals);
    }

    /** The MAS of the agents started last. */
    public RasonLocalMAS mas() {
        return mas;
    }

    @Override
    public void afterEach(ExtensionContext context) throws Exception {
        stop();
    }

    public void stop() throws Exception {
        bridge.shutdown(rason.core.Protocol.SHUTDOWN);
        if (mas != null)
            assertTrue(mas.stopAgents(5000), "agent threads end");
        bridge.detach();
        while (bridge.outbox().poll() != null) {
            // nothing of this test reaches the next one
        }
    }

    public static boolean believes(RosAgArch arch, String literal) {
        try {
            return arch.getTS().getAg().believes(ASSyntax.parseLiteral(literal), new Unifier());
        } catch (Exception e) {
            throw new IllegalStateException(e);
        }
    }

    public static void await(String what, BooleanSupplier condition) throws InterruptedException {
        long deadline = System.currentTimeMillis() + WAIT_MS;
        while (!condition.getAsBoolean()) {
            if (System.currentTimeMillis() > deadline)
                throw new AssertionError("timed out waiting for " + what);
            Thread.sleep(5);
        }
    }

    /**
     * Gives the agents nothing for ms of wall time: for tests of what an agent does when input
     * stops coming (its own timers run on), never to wait for something to happen.
     */
    public static void noInputFor(long ms, String why) throws InterruptedException {
        Thread.sleep(ms);
    }

    /** The next item the agents queued for ROS, of the given kind. */
    public <T extends Outbound> T next(Class<T> kind) throws InterruptedException {
        Outbound item = bridge.outbox().take(WAIT_MS);
        assertNotNull(item, "nothing was queued");
        return assertInstanceOf(kind, item);
    }
}
