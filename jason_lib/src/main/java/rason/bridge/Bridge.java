package rason.bridge;

import java.util.Map;
import java.util.logging.Logger;

import jason.infra.local.LocalAgArch;

import rason.action.ActionPort;
import rason.core.Clock;
import rason.core.InputLimits;
import rason.core.LogQueue;
import rason.core.RateLimitedLog;
import rason.core.RosClock;
import rason.infra.LoopbackMindInspector;
import rason.infra.MasHost;
import rason.infra.RasonLocalMAS;
import rason.messaging.FleetPort;
import rason.messaging.mqtt.MqttChannel;
import rason.messaging.mqtt.MqttSettings;
import rason.mind.MindPort;
import rason.perception.AgentPerception;
import rason.perception.PerceptionPort;

/**
 * Where one rospy process meets the agents its JVM hosts: the composition root that
 * makes the ports (actions, perception, fleet, mind) and the Jason infrastructure
 * and wires them. The node makes one, configures the ports from its ~params, pushes
 * ROS input and the ROS time into them, and drains the {@link Outbox} and the
 * {@link LogQueue} on threads of its own, so an agent's thread never calls Python.
 */
public final class Bridge implements MasHost {

    private static final Logger logger = Logger.getLogger("rason.bridge");

    private final Clock wall;
    private final RosClock rosClock = new RosClock();
    private final RosTimeScheduler scheduler = new RosTimeScheduler(rosClock);
    private boolean schedulerInstalled = false; // guarded by scheduler
    private final Outbox outbox = new Outbox();
    private final LogQueue log = new LogQueue();
    private final InputLimits limits = new InputLimits();
    // at most a few lines per period of each kind of dropped input (wall clock)
    private final RateLimitedLog limited = new RateLimitedLog(logger);
    private final ActionPort actions;
    private final PerceptionPort perception;
    private final RosTopicChannel rosChannel = new RosTopicChannel(outbox);
    private final FleetPort fleet;
    private final MindPort mind;
    private volatile MqttChannel mqtt; // the fleet channel instead of rosChannel, if chosen
    private volatile RasonLocalMAS mas;

    /** The ports start with every duration off (no action timeout, perception expiry, ask timeout) until the node sets its ~params. */
    public Bridge() {
        this(Clock.WALL);
    }

    /** @param wall the clock of durations (tests move it by hand) */
    public Bridge(Clock wall) {
        this.wall = wall;
        actions = new ActionPort(outbox, limits, logger, limited, wall, 0, 0);
        perception = new PerceptionPort(limits, logger, limited, wall, 0, rason.perception.PerceptionManagers.PER_SOURCE);
        fleet = new FleetPort(logger, limited, limits, wall, rosClock, rosChannel, this::jasonAgents,
                this::presenceChanged, () -> requestStop(1), 0);
        rosChannel.connect(fleet);
        mind = new MindPort(200, 500, LoopbackMindInspector::url);
    }

    @Override
    public ActionPort actions() {
        return actions;
    }

    @Override
    public PerceptionPort perception() {
        return perception;
    }

    @Override
    public FleetPort fleet() {
        return fleet;
    }

    /**
     * The fleet goes through an MQTT broker instead of the ROS topics (the node then neither
     * publishes nor subscribes /rason/messages and /rason/presence): call after the fleet's mas id,
     * incarnation and authentication are set, before the agents start. Connects in the background.
     *
     * @throws IllegalArgumentException settings that cannot be used (the text says why)
     */
    public MqttChannel useMqtt(MqttSettings settings) {
        if (mqtt != null)
            throw new IllegalStateException("the MQTT fleet channel is already in use");
        MqttChannel channel = new MqttChannel(fleet, settings, logger, wall);
        mqtt = channel;
        fleet.useChannel(channel);
        // the broker keeps a silent robot's session: what is sent to it meanwhile may still arrive
        fleet.fleet().setAwayHoldNanos(settings.messageTtlSeconds() * 1_000_000_000L);
        channel.start();
        return channel;
    }

    /** The MQTT fleet channel if in use, else null. */
    public MqttChannel mqttChannel() {
        return mqtt;
    }

    /** The fleet channel of one ROS master: what the node publishes and receives on /rason/*. */
    public RosTopicChannel rosChannel() {
        return rosChannel;
    }

    @Override
    public MindPort mind() {
        return mind;
    }

    @Override
    public Clock rosClock() {
        return rosClock;
    }

    @Override
    public Clock wallClock() {
        return wall;
    }

    @Override
    public LogQueue log() {
        return log;
    }

    /** What the agents hand to the node: actions, cancels, messages, announcements, stop. */
    public Outbox outbox() {
        return outbox;
    }

    /** The rate limit of the warnings about dropped input, refused messages and ignored events; the node sets its period. */
    public RateLimitedLog warnings() {
        return limited;
    }

    /** The bounds on perceptions and agent messages; the node sets them. */
    public InputLimits limits() {
        return limits;
    }

    @Override
    public boolean requestStop(int exitValue) {
        return outbox.offer(new Outbound.Stop(exitValue));
    }

    /** The Jason MAS of this process (one at a time: Jason's runtime services are one per process). */
    public RasonLocalMAS newMas() {
        RasonLocalMAS m = new RasonLocalMAS(this);
        mas = m;
        return m;
    }

    private Map<String, LocalAgArch> jasonAgents() {
        RasonLocalMAS m = mas;
        return m == null ? Map.of() : m.getAgs();
    }

    private void presenceChanged(java.util.List<String> present) {
        for (AgentPerception p : perception.agents())
            p.presenceUpdate(present);
    }

    // ---- life cycle --------------------------------------------------------------------

    /**
     * A rospy node takes the outbox and the log from now on: the sources an earlier one
     * heard are forgotten and its rate-limited warnings summarised.
     */
    public void attach() {
        actions.reopen();
        perception.clearSources();
        limited.endAll(wall.nanos());
        fleet.reopen();
        outbox.open();
        log.setAttached(true);
    }

    /** The node is gone: nothing more is published, Java logs to stderr. */
    public void detach() {
        log.setAttached(false);
        outbox.close();
    }

    public boolean isAttached() {
        return log.isAttached();
    }

    /** The process is stopping: every pending and future action, and every pending remote ask, fails with reason. */
    public void shutdown(String reason) {
        actions.shutdown(reason);
        fleet.shutdown(reason);
    }

    /** Our agents leave the fleet: over MQTT a leaving presence, then the connection closes (at most timeoutMillis). */
    public void leaveFleet(long timeoutMillis) {
        MqttChannel m = mqtt;
        if (m != null)
            m.leave(timeoutMillis);
    }

    /**
     * Jason's timing ({@code .wait}, {@code .at}, plan deadlines, {@code .send}
     * timeouts) follows ROS time (true: /use_sim_time, the clock pushed by
     * {@link #clockAdvanced}) or the wall clock (false). The first call puts
     * this bridge's scheduler in Jason, for the whole process.
     */
    public void agentsOnRosTime(boolean rosTime) {
        synchronized (scheduler) {
            if (!schedulerInstalled) {
                RosTimeScheduler.installInJason(scheduler);
                schedulerInstalled = true;
            }
        }
        scheduler.useRosTime(rosTime);
    }

    /** A /clock message: the ROS time is nowNanos; what Jason scheduled for then is due. */
    public void clockAdvanced(long nowNanos) {
        scheduler.advance(nowNanos);
    }

    public RosTimeScheduler scheduler() {
        return scheduler;
    }

    /** Called periodically with the ROS time: the one clock of timeouts and expiry. */
    public void tick(long nowNanos) {
        scheduler.advance(nowNanos);
        limited.tick(wall.nanos());
        perception.tick(nowNanos);
        actions.tick(nowNanos);
        fleet.tick(nowNanos);
    }

    /** Names of the hosted agents, sorted (the node announces them). */
    public String[] agentNames() {
        return fleet.names().localAgents();
    }

    /** A perception flood ended: a (concurrent) garbage collection lets the JVM shrink the heap the burst grew. */
    public void releaseMemory() {
        System.gc();
    }
}
