package rason.action;

import java.security.SecureRandom;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.logging.Level;
import java.util.logging.Logger;

import rason.core.Clock;
import rason.core.InputLimits;
import rason.core.RateLimitedLog;
import rason.core.WarnOnce;

/**
 * The actions of every hosted agent, as the node sees them: decomposers' events come in
 * here and reach the agent whose action they settle; the ROS time and the links to the
 * decomposers end what is overdue or lost; a stopping node fails everything pending.
 */
public final class ActionPort {

    /** Kind of the rate-limited lines of ignored events. */
    public static final String IGNORED_EVENT = "ignored event";

    private final Map<String, AgentActions> agents = new ConcurrentHashMap<>();
    private final ActionSink sink;
    private final InputLimits limits;
    private final Logger logger;
    private final RateLimitedLog limited;
    private final WarnOnce warned;
    private final Clock wall;
    // Ids start at a random point of each run, so a restarted process (or a second one for the
    // same agent name) does not reuse the ids a decomposer may still hold; 0 is never used
    // (a cancel for id 0 means every action of the agent).
    private int lastActionId = new SecureRandom().nextInt(1 << 30); // guarded by this
    private volatile long timeoutNanos;
    private volatile long decomposerGraceNanos;
    private volatile String shutdownReason = null;

    public ActionPort(ActionSink sink, InputLimits limits, Logger logger, RateLimitedLog limited, Clock wall,
            long timeoutNanos, long decomposerGraceNanos) {
        this.sink = sink;
        this.limits = limits;
        this.logger = logger;
        this.limited = limited;
        this.warned = new WarnOnce(logger);
        this.wall = wall;
        this.timeoutNanos = timeoutNanos;
        this.decomposerGraceNanos = decomposerGraceNanos;
    }

    /** A hosted agent starts acting; wake makes it settle what ended in its next cycle. */
    public AgentActions join(String agent, Runnable wake) {
        AgentActions a = new AgentActions(this::nextActionId, sink, agent, wake, this);
        agents.put(agent, a);
        return a;
    }

    /** The actions of a hosted agent, null if none is called so. */
    public AgentActions of(String agent) {
        return agents.get(agent);
    }

    public void leave(String agent, AgentActions actions) {
        agents.remove(agent, actions);
    }

    /** 0 or less disables the timeout (ROS time). */
    public void setTimeoutNanos(long t) {
        timeoutNanos = t;
    }

    /** How long the decomposer that took an action may be unreachable before the action fails (wall clock). */
    public void setDecomposerGraceNanos(long t) {
        decomposerGraceNanos = t;
    }

    /** The bounds within which an action's result is read as a Jason literal. */
    public InputLimits limits() {
        return limits;
    }

    synchronized int nextActionId() {
        lastActionId = lastActionId == Integer.MAX_VALUE ? 1 : lastActionId + 1;
        return lastActionId;
    }

    /**
     * A rason_msgs/Event arrived. Events for agents not hosted here, of unknown types or
     * malformed are ignored with a log line.
     *
     * @param publisher the node that published it ("" if unknown): for action_started, the decomposer to watch
     * @return true if it settled or started an action
     */
    public boolean event(String agent, String eventType, String[] parameters, String publisher) {
        AgentActions actions = agents.get(agent);
        if (actions == null) {
            if (warned.firstTime("event:" + agent))
                limited.log(IGNORED_EVENT, Level.INFO, "ignoring events for agent '" + InputLimits.abbreviate(agent, 100)
                        + "': not hosted here (logged once)", wall.nanos());
            return false;
        }
        ActionEvent ev;
        try {
            ev = ActionEvent.parse(eventType, parameters);
        } catch (IllegalArgumentException e) {
            limited.log(IGNORED_EVENT, Level.WARNING, "ignored event for " + agent + ": "
                    + InputLimits.abbreviate(e.getMessage(), 300), wall.nanos());
            return false;
        }
        if (ev.started())
            return publisher != null && !publisher.isEmpty() && actions.startedBy(ev.actionId(), publisher);
        return actions.feedback(ev.actionId(), ev.result());
    }

    /** An event whose publisher is unknown. */
    public boolean event(String agent, String eventType, String[] parameters) {
        return event(agent, eventType, parameters, "");
    }

    /** Ends an action with a result of the bridge's own (e.g. no_decomposer), from a thread of the node. */
    public boolean fail(String agent, int actionId, String reason) {
        AgentActions actions = agents.get(agent);
        return actions != null && actions.feedback(actionId, reason);
    }

    /**
     * Called every few tens of milliseconds with the nodes whose jason/event link is up:
     * actions taken by a node that has been gone for longer than the grace fail decomposer_lost.
     */
    public void decomposersTick(String[] connected) {
        Set<String> live = Set.of(connected);
        long now = wall.nanos();
        for (AgentActions a : agents.values())
            a.decomposersTick(live, now, decomposerGraceNanos);
    }

    /** Periodic, with the ROS time: actions older than the timeout fail, and their agents wake. */
    public void tick(long rosNanos) {
        for (AgentActions a : agents.values())
            a.expire(rosNanos, timeoutNanos);
    }

    /** The process is stopping: every pending and future action fails with reason. */
    public void shutdown(String reason) {
        shutdownReason = reason;
        for (AgentActions a : agents.values())
            a.failAll(reason);
    }

    /** Non-null once the process is stopping: new actions fail with this reason. */
    public String shutdownReason() {
        return shutdownReason;
    }

    /** A node takes actions again: the reason an earlier one stopped is forgotten. */
    public void reopen() {
        shutdownReason = null;
    }

    void ignoredFeedback(String agent, String result, int actionId) {
        limited.log(IGNORED_EVENT, Level.INFO, "[" + agent + "] ignored feedback '" + InputLimits.abbreviate(result, 200)
                + "' for action id " + actionId + ": no such action pending", wall.nanos());
    }

    void log(Level level, String agent, String text) {
        logger.log(level, "[" + agent + "] " + text);
    }
}
