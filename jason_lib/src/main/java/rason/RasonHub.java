package rason;

import rason.infra.RasonLocalMAS;
import rason.messaging.Messages;
import rason.messaging.PresenceTable;
import rason.perception.PerceptionManagers;
import rason.perception.Perceptions;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collection;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.logging.Level;
import java.util.logging.Logger;

import jason.JasonException;
import jason.asSemantics.Message;
import jason.asSyntax.ASSyntax;
import jason.asSyntax.Literal;
import jason.asSyntax.Term;
import jason.infra.local.BaseLocalMAS;
import jason.infra.local.LocalAgArch;

/**
 * The meeting point of one rospy process and the agents its JVM hosts: the ROS
 * callbacks push perceptions, feedback, agent messages, presence announcements
 * and clock ticks in here; each {@link RosAgArch} registers here and publishes
 * its actions and messages through the {@link RosConnector}. There is one hub
 * per JVM, and so one MAS id: the rason_mas node's name.
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
    private volatile long lastRosNanos = 0; // ROS time of the last tick

    // ---- between processes (thesis §5.6) ----
    /** Jason atoms: what an agent name must look like to become source(Name). */
    public static final String NAME_PATTERN = "[a-z][A-Za-z0-9_]*";
    private volatile String masId = "";
    private volatile String agentPrefix = "";
    private final PresenceTable presence = new PresenceTable(); // guarded by itself
    private final Object pushLock = new Object();
    private volatile long presenceTimeoutNanos = 2_000_000_000L;
    private volatile long askTimeoutNanos = 60_000_000_000L;
    private volatile boolean presenceBeliefs = true;
    private volatile String defaultPerceptionManager = PerceptionManagers.PER_SOURCE;
    private final Set<String> warnedOnce = ConcurrentHashMap.newKeySet();

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

    /** This process's id in agent messages and presence: the rason_mas node name. */
    public void setMasId(String id) {
        masId = id == null ? "" : id;
    }

    public String getMasId() {
        return masId;
    }

    /** Set by {@link RasonLocalMAS#setAgentPrefix} before the agents are created. */
    public void setAgentPrefix(String prefix) {
        agentPrefix = prefix == null ? "" : prefix;
    }

    public String getAgentPrefix() {
        return agentPrefix;
    }

    /** Silence after which another process counts as gone (wall clock). */
    public void setPresenceTimeoutNanos(long t) {
        presenceTimeoutNanos = t;
    }

    /** ROS time a synchronous ask to a remote agent may wait; 0 or less waits as long as the receiver is present. */
    public void setAskTimeoutNanos(long t) {
        askTimeoutNanos = t;
    }

    long getAskTimeoutNanos() {
        return askTimeoutNanos;
    }

    /** Whether agents get present(Name) percepts. */
    public void setPresenceBeliefs(boolean on) {
        presenceBeliefs = on;
        pushPresence();
    }

    boolean presenceBeliefs() {
        return presenceBeliefs;
    }

    /**
     * The strategy of agents whose .mas2j names none.
     *
     * @throws IllegalArgumentException if it names no strategy
     */
    public void setDefaultPerceptionManager(String spec) {
        PerceptionManagers.create(spec); // fail now, not at each agent
        defaultPerceptionManager = spec;
    }

    public String defaultPerceptionManager() {
        return defaultPerceptionManager;
    }

    long rosNow() {
        return lastRosNanos;
    }

    // ---- agents ------------------------------------------------------------------------

    void register(RosAgArch arch) {
        agents.put(arch.getAgName(), arch);
        localAgentsChanged();
    }

    void unregister(RosAgArch arch) {
        if (agents.remove(arch.getAgName(), arch))
            localAgentsChanged();
    }

    private void localAgentsChanged() {
        PresenceTable.Changes c;
        synchronized (presence) {
            c = presence.setLocal(agents.keySet());
        }
        apply(c);
        pushPresence();
    }

    /** The hosted agent called name, or prefix+name (so a program reaches its own robot's agents by their short names); null if neither. */
    String localNameFor(String name) {
        Map<String, LocalAgArch> jason = jasonAgents();
        if (jason.containsKey(name) || agents.containsKey(name))
            return name;
        String prefixed = agentPrefix + name;
        if (!agentPrefix.isEmpty() && (jason.containsKey(prefixed) || agents.containsKey(prefixed)))
            return prefixed;
        return null;
    }

    /** Every agent of this JVM, as Jason's local infrastructure knows them. */
    static Map<String, LocalAgArch> jasonAgents() {
        BaseLocalMAS runner = BaseLocalMAS.getRunner();
        return runner == null ? Map.of() : runner.getAgs();
    }

    /** What .all_names answers: the hosted agents and every reachable agent of other processes, sorted. */
    public List<String> allNames() {
        Set<String> all = new TreeSet<>(jasonAgents().keySet());
        all.addAll(agents.keySet());
        synchronized (presence) {
            all.addAll(presence.reachable());
        }
        return new ArrayList<>(all);
    }

    /** The process a message to agent goes to (see {@link PresenceTable#sendableMasOf}), or null. */
    String remoteMasOf(String agent) {
        synchronized (presence) {
            return presence.sendableMasOf(agent);
        }
    }

    String whyUnreachable(String agent) {
        synchronized (presence) {
            return presence.whyUnreachable(agent);
        }
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

    /** Called periodically with the ROS time: expires perceptions, timed-out actions and asks. */
    public void tick(long nowNanos) {
        lastRosNanos = nowNanos;
        for (RosAgArch arch : agents.values())
            arch.tick(nowNanos, actionTimeoutNanos, perceptionTtlNanos);
    }

    // ---- presence -------------------------------------------------------------------

    /** A rason_msgs/Presence arrived. Our own announcements and malformed ones are ignored (the latter with a log line). */
    public void presenceAnnounced(String mas, long incarnation, String[] names, boolean leaving) {
        if (mas == null || mas.isEmpty()) {
            warnOnce("presence:", "ignored a presence announcement without mas_id");
            return;
        }
        if (mas.equals(masId))
            return;
        List<String> valid = new ArrayList<>(names.length);
        for (String n : names) {
            if (n != null && n.matches(NAME_PATTERN))
                valid.add(n);
            else
                warnOnce("presence:" + mas + ":" + n, "ignored agent name '" + n + "' announced by " + mas
                        + ": not a Jason atom");
        }
        PresenceTable.Changes c;
        synchronized (presence) {
            c = presence.announced(mas, incarnation, valid, leaving, System.nanoTime());
        }
        apply(c);
    }

    /**
     * Called every few tens of milliseconds (wall clock) with the ids of the
     * processes our message publisher is connected to: silent ones leave.
     */
    public void presenceTick(String[] linkedMas) {
        PresenceTable.Changes c;
        synchronized (presence) {
            c = presence.tick(Arrays.asList(linkedMas), System.nanoTime(), presenceTimeoutNanos);
        }
        apply(c);
    }

    /** Reachable remote agents (for tests and diagnostics). */
    public String[] remoteAgents() {
        synchronized (presence) {
            return presence.reachable().toArray(new String[0]);
        }
    }

    private void apply(PresenceTable.Changes c) {
        if (c.isEmpty())
            return;
        for (String e : c.events)
            logger.info("presence: " + e);
        for (String e : c.clashes)
            logger.severe(e);
        for (String a : c.joined)
            logger.info("presence: agent " + a + " is reachable");
        for (String a : c.left)
            logger.info("presence: agent " + a + " is no longer reachable");
        if (!c.lost.isEmpty())
            for (RosAgArch arch : agents.values())
                arch.receiversLost(c.lost);
        if (c.reachabilityChanged())
            pushPresence();
    }

    /** Gives every agent the current present/1 list; the lock keeps a newer list from being overtaken by an older one. */
    private void pushPresence() {
        synchronized (pushLock) {
            List<String> names = presenceBeliefs ? allNames() : List.of();
            for (RosAgArch arch : agents.values())
                arch.presenceUpdate(names);
        }
    }

    // ---- agent messages --------------------------------------------------------------

    /**
     * A rason_msgs/AgentMessage arrived. Messages for other processes and our
     * own are ignored; malformed ones are logged and dropped.
     *
     * @return how many hosted agents it was delivered to
     */
    public int deliverMessage(String senderMas, String sender, String receiverMas, String receiver,
            String performative, String content, String msgId, String inReplyTo) {
        if (senderMas.equals(masId) || !(receiverMas.isEmpty() || receiverMas.equals(masId)))
            return 0;
        String what = performative + " from " + sender + " (" + senderMas + ") to "
                + (receiver.isEmpty() ? "everyone" : receiver);
        if (senderMas.isEmpty() || !sender.matches(NAME_PATTERN)) {
            logger.warning("dropped message " + what + ": sender and sender_mas must be set, and the sender a Jason atom");
            return 0;
        }
        if (!performative.matches(NAME_PATTERN)) {
            logger.warning("dropped message " + what + ": performative '" + performative + "' is not a Jason atom");
            return 0;
        }
        Term term;
        try {
            term = Messages.parseContent(content);
        } catch (IllegalArgumentException e) {
            logger.warning("dropped message " + what + ": " + e.getMessage());
            return 0;
        }
        PresenceTable.Changes c;
        synchronized (presence) {
            c = presence.messageFrom(senderMas, sender, System.nanoTime());
        }
        apply(c);
        if (agents.containsKey(sender))
            warnOnce("sender:" + sender, "message from " + sender + " of " + senderMas + ", a name this process also hosts:"
                    + " replies to it stay here; give one of the robots an ~agent_prefix");
        Map<String, LocalAgArch> hosted = jasonAgents();
        List<String> to = receiver.isEmpty() ? new ArrayList<>(hosted.keySet()) : List.of(receiver);
        int delivered = 0;
        for (String name : to) {
            LocalAgArch la = hosted.get(name);
            if (la == null) {
                warnOnce("receiver:" + name, "dropped message " + what + ": no agent '" + name
                        + "' here (logged once per name)");
                continue;
            }
            la.receiveMsg(Messages.toJason(performative, sender, name, term, msgId, inReplyTo));
            delivered++;
        }
        return delivered;
    }

    /**
     * Sends m to a remote process (receiverMas empty: to every other process).
     *
     * @throws JasonException if the bridge cannot publish (not running, stopping)
     */
    void publishMessage(String receiverMas, Message m) throws JasonException {
        RosConnector c = connector;
        boolean sent = false;
        if (c != null) {
            try {
                sent = c.publishMessage(receiverMas, m.getSender(), m.getReceiver(), m.getIlForce(),
                        Messages.contentText(m), m.getMsgId(), m.getInReplyTo() == null ? "" : m.getInReplyTo());
            } catch (RuntimeException e) {
                logger.warning("could not publish " + m + ": " + e);
            }
        }
        if (!sent)
            throw new JasonException("could not send " + m + ": the bridge is not running", ASSyntax.createAtom("bridge_error"));
    }

    private void warnOnce(String key, String message) {
        if (warnedOnce.add(key))
            logger.warning(message);
    }

    /** The process is stopping: every pending and future action, and every pending remote ask, fails with reason. */
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
    public Collection<String> hostedNames() {
        return agents.keySet();
    }
}
