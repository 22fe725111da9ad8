package rason;

import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import java.util.Map;
import java.util.TreeSet;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.logging.Level;
import java.util.logging.Logger;

import jason.asSyntax.Literal;

/**
 * The meeting point of one rospy process and the agents its JVM hosts: the ROS
 * callbacks push perceptions, feedback and clock ticks in here; each
 * {@link RosAgArch} registers here and publishes its actions through the
 * {@link RosConnector}. There is one hub per JVM.
 */
public final class RasonHub {

    private static final RasonHub INSTANCE = new RasonHub();
    private static final Logger logger = Logger.getLogger("rason.bridge");

    private final Map<String, RosAgArch> agents = new ConcurrentHashMap<>();
    private final AtomicInteger lastActionId = new AtomicInteger();
    private volatile RosConnector connector;
    private volatile long actionTimeoutNanos = 60_000_000_000L;
    private volatile long perceptionTtlNanos = 2_000_000_000L;
    private volatile String shutdownReason = null;

    private RasonHub() {
    }

    public static RasonHub get() {
        return INSTANCE;
    }

    // ---- configuration (from the node's ~params) -------------------------------------

    public void setConnector(RosConnector c) {
        connector = c;
    }

    public RosConnector getConnector() {
        return connector;
    }

    /** 0 or less disables the timeout. */
    public void setActionTimeoutNanos(long t) {
        actionTimeoutNanos = t;
    }

    public long getActionTimeoutNanos() {
        return actionTimeoutNanos;
    }

    /** 0 or less: perceptions never expire. */
    public void setPerceptionTtlNanos(long t) {
        perceptionTtlNanos = t;
    }

    // ---- agents ------------------------------------------------------------------------

    void register(RosAgArch arch) {
        agents.put(arch.getAgName(), arch);
    }

    void unregister(RosAgArch arch) {
        agents.remove(arch.getAgName(), arch);
    }

    public boolean hosts(String agent) {
        return agents.containsKey(agent);
    }

    public String[] agentNames() {
        return new TreeSet<>(agents.keySet()).toArray(new String[0]);
    }

    public RosAgArch agent(String name) {
        return agents.get(name);
    }

    int nextActionId() {
        return lastActionId.incrementAndGet();
    }

    /** Non-null once the process is stopping: new actions fail with this reason. */
    String shutdownReason() {
        return shutdownReason;
    }

    // ---- input from ROS ---------------------------------------------------------------

    /**
     * A rason_msgs/Perception arrived: parse it once and hand it to every agent.
     * Unparsable literals are logged with their source and dropped; the rest is kept.
     *
     * @return how many literals were accepted
     */
    public int perceive(String source, String[] texts, long nowNanos) {
        List<Literal> literals = new ArrayList<>(texts.length);
        for (String text : texts) {
            try {
                literals.add(Perceptions.parse(text));
            } catch (IllegalArgumentException e) {
                logger.warning("dropped perception '" + text + "' from source '" + source + "': " + e.getMessage());
            }
        }
        List<Literal> shared = List.copyOf(literals);
        for (RosAgArch arch : agents.values())
            arch.perceptionUpdate(source, shared, nowNanos);
        return shared.size();
    }

    /**
     * An action_feedback event for one agent.
     *
     * @return false if this process does not host the agent
     */
    public boolean actionFeedback(String agent, int actionId, String result) {
        RosAgArch arch = agents.get(agent);
        if (arch == null)
            return false;
        arch.feedback(actionId, result);
        return true;
    }

    /** Called periodically with the ROS time: expires perceptions and timed-out actions. */
    public void tick(long nowNanos) {
        for (RosAgArch arch : agents.values())
            arch.tick(nowNanos, actionTimeoutNanos, perceptionTtlNanos);
    }

    /** The process is stopping: every pending and future action fails with reason. */
    public void shutdown(String reason) {
        shutdownReason = reason;
        for (RosAgArch arch : agents.values())
            arch.failPending(reason);
    }

    /** Total of actions still waiting for feedback (for tests and diagnostics). */
    public int pendingActions() {
        int n = 0;
        for (RosAgArch arch : agents.values())
            n += arch.pendingCount();
        return n;
    }

    // ---- output to ROS ----------------------------------------------------------------

    long publishAction(String agent, int id, String action, String[] parameters) {
        RosConnector c = connector;
        if (c == null)
            throw new IllegalStateException("no ROS connector: the bridge is not running");
        return c.publishAction(agent, id, action, parameters);
    }

    static void log(Level level, String message) {
        logger.log(level, message);
    }

    /** Names of the hosted agents, live (the log handler tags lines with them). */
    Collection<String> hostedNames() {
        return agents.keySet();
    }
}
