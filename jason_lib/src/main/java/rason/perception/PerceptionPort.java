package rason.perception;

import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.logging.Level;
import java.util.logging.Logger;

import jason.asSyntax.Literal;
import jason.runtime.Settings;

import rason.core.Clock;
import rason.core.InputLimits;
import rason.core.RateLimitedLog;

/**
 * Perceptions from ROS into every hosted agent: each rason_msgs/Perception is
 * parsed once, within the input limits, and handed to each agent's
 * {@link AgentPerception}; sources not heard for the TTL (ROS time) are dropped.
 */
public final class PerceptionPort {

    /** Kind of the rate-limited lines of dropped perceptions. */
    public static final String DROPPED_PERCEPTION = "dropped perception";
    /** Kind of the rate-limited lines of perceptions read with U+FFFD for bytes that are not UTF-8. */
    public static final String NOT_UTF8 = "perception not UTF-8";

    private final Map<String, AgentPerception> agents = new ConcurrentHashMap<>();
    private final PerceptionSources sources = new PerceptionSources();
    private final InputLimits limits;
    private final Logger logger;
    private final RateLimitedLog limited;
    private final Clock wall;
    private volatile long ttlNanos;
    private volatile String defaultManager;

    /** @throws IllegalArgumentException if defaultManager names no strategy */
    public PerceptionPort(InputLimits limits, Logger logger, RateLimitedLog limited, Clock wall, long ttlNanos,
            String defaultManager) {
        this.limits = limits;
        this.logger = logger;
        this.limited = limited;
        this.wall = wall;
        this.ttlNanos = ttlNanos;
        setDefaultManager(defaultManager);
    }

    /**
     * A hosted agent starts perceiving, with the strategy its .mas2j options name (else the
     * default); a bad option is logged and the agent perceives per source.
     */
    public AgentPerception join(String agent, Settings options, Runnable wake) {
        SelectivePerception manager;
        try {
            manager = PerceptionManagers.forAgent(options, defaultManager);
        } catch (IllegalArgumentException e) {
            // RasonLocalMAS checks the options before creating agents; this is for agents created later
            logger.severe("[" + agent + "] " + e.getMessage() + "; using " + PerceptionManagers.PER_SOURCE);
            manager = new SelectivePerception(new PerSourcePerception(), null);
        }
        if (!PerceptionManagers.PER_SOURCE.equals(manager.toString()))
            logger.info("[" + agent + "] perception: " + manager);
        AgentPerception p = new AgentPerception(manager, wake);
        agents.put(agent, p);
        return p;
    }

    public void leave(String agent, AgentPerception perception) {
        agents.remove(agent, perception);
    }

    /** 0 or less: perceptions never expire. */
    public void setTtlNanos(long t) {
        ttlNanos = t;
    }

    /**
     * The strategy of agents whose .mas2j names none.
     *
     * @throws IllegalArgumentException if it names no strategy
     */
    public void setDefaultManager(String spec) {
        PerceptionManagers.create(spec); // fail now, not at each agent
        defaultManager = spec;
    }

    public String defaultManager() {
        return defaultManager;
    }

    /**
     * A rason_msgs/Perception arrived: parse it once and hand it to every agent.
     * Unparsable literals are logged with their source and dropped; the rest is kept.
     * Called by one thread of the node, with the newest message of a source (see the
     * node's coalescing); a literal the source's previous message had is not parsed again.
     *
     * @return how many literals were accepted
     */
    public int perceive(String source, String[] texts, long nowNanos) {
        String shownSource = InputLimits.abbreviate(source, 100);
        if (source.length() > InputLimits.MAX_SOURCE_LENGTH)
            return droppedMessage(shownSource, "source name longer than " + InputLimits.MAX_SOURCE_LENGTH + " characters");
        if (texts.length > limits.maxLiterals())
            return droppedMessage(shownSource, PerceptionWire.tooManyLiterals(texts.length, limits.maxLiterals()));
        List<Literal> literals = sources.parse(source, texts, nowNanos, limits,
                (text, why) -> droppedLiteral(text, shownSource, why));
        if (literals == null)
            return droppedMessage(shownSource, "more than " + limits.maxSources()
                    + " sources heard within ~perception_ttl and this one is new (the others' percepts are unchanged)");
        List<Literal> shared = List.copyOf(literals);
        for (AgentPerception a : agents.values())
            a.update(source, shared, nowNanos);
        return shared.size();
    }

    /**
     * As {@link #perceive(String, String[], long)}, with the message as rospy received it (its
     * serialization, read by {@link PerceptionWire}; source is the one it holds, read by the
     * node to coalesce messages): one call and no Python strings per message. A message that
     * cannot be read is dropped whole, with its reason.
     *
     * @return how many literals were accepted
     */
    public int perceiveSerialized(String source, byte[] message, long nowNanos) {
        String shownSource = InputLimits.abbreviate(source, 100);
        if (source.length() > InputLimits.MAX_SOURCE_LENGTH)
            return droppedMessage(shownSource, "source name longer than " + InputLimits.MAX_SOURCE_LENGTH + " characters");
        PerceptionWire.Literals read;
        try {
            read = PerceptionWire.literals(message, limits, (text, why) -> droppedLiteral(text, shownSource, why));
        } catch (IllegalArgumentException e) {
            return droppedMessage(shownSource, e.getMessage());
        }
        if (read.notUtf8() > 0)
            limited.log(NOT_UTF8, Level.WARNING, "perception message from source '" + shownSource + "': "
                    + read.notUtf8() + " literals not valid UTF-8, read with U+FFFD for the invalid bytes", wall.nanos());
        return perceive(source, read.texts(), nowNanos);
    }

    private int droppedMessage(String shownSource, String why) {
        return dropped("dropped perception message from source '" + shownSource + "': " + why);
    }

    private int droppedLiteral(String text, String shownSource, String why) {
        return dropped("dropped perception '" + InputLimits.abbreviate(text, 200) + "' from source '" + shownSource
                + "': " + why);
    }

    private int dropped(String line) {
        limited.log(DROPPED_PERCEPTION, Level.WARNING, line, wall.nanos());
        return 0;
    }

    /** Periodic, with the ROS time: silent sources are forgotten and their percepts dropped. */
    public void tick(long rosNanos) {
        sources.expire(rosNanos, ttlNanos);
        for (AgentPerception a : agents.values())
            a.expire(rosNanos, ttlNanos);
    }

    /** The sources an earlier node heard are forgotten. */
    public void clearSources() {
        sources.clear();
    }

    /** The perception sources remembered now (bounded by {@link InputLimits#maxSources()}). */
    public int sources() {
        return sources.size();
    }

    /** Every hosted agent's perception (present/1 goes to each). */
    public Iterable<AgentPerception> agents() {
        return agents.values();
    }
}
