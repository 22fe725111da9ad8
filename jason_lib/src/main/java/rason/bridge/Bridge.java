package rason.bridge;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collection;
import java.util.Comparator;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.logging.Level;
import java.util.logging.Logger;

import jason.asSemantics.Message;
import jason.asSyntax.ASSyntax;
import jason.asSyntax.Atom;
import jason.asSyntax.Literal;
import jason.asSyntax.StringTermImpl;
import jason.infra.local.LocalAgArch;

import rason.RosAgArch;
import rason.action.ActionEvent;
import rason.messaging.Fleet;
import rason.messaging.FleetAuth;
import rason.messaging.FleetDirectory;
import rason.messaging.FleetKeys;
import rason.messaging.Messages;
import rason.messaging.RateLimitedLog;
import rason.messaging.TrustPolicy;
import rason.messaging.WarnOnce;
import rason.messaging.WireMessage;
import rason.mind.AgentMind;
import rason.mind.MindReader;
import rason.perception.PerceptionManagers;
import rason.perception.PerceptionSources;

/**
 * Where one rospy process meets the agents its JVM hosts (one per JVM, since
 * Jason creates the architectures by reflection). The node's ROS threads push
 * perceptions, events, agent messages, presence and the ROS time in through
 * the methods here; the agents hand what goes out to the {@link Outbox}, which
 * a thread of the node drains. Configuration comes from the node's ~params.
 */
public final class Bridge implements Fleet.Listener {

    // before INSTANCE: the constructor uses it
    private static final Logger logger = Logger.getLogger("rason.bridge");
    private static final Bridge INSTANCE = new Bridge();

    private final AgentRegistry registry = new AgentRegistry();
    private final RosClock clock = new RosClock();
    private final RosTimeScheduler scheduler = new RosTimeScheduler(clock);
    private boolean schedulerInstalled = false; // guarded by scheduler
    private final Outbox outbox = new Outbox();
    // at most a few lines per period of each kind of dropped input (wall clock)
    private final RateLimitedLog limited = new RateLimitedLog(logger);
    private final Fleet fleet = new Fleet(logger, this, limited);
    private final WarnOnce warned = new WarnOnce(logger);
    private final TrustPolicy trust = new TrustPolicy();
    private final PerceptionSources sources = new PerceptionSources();
    private final Object presencePushLock = new Object();
    // Ids start at a random point of each run, so a restarted process (or a second one for the
    // same agent name) does not reuse the ids a decomposer may still hold; 0 is never used
    // (a cancel for id 0 means every action of the agent).
    private int lastActionId = new java.security.SecureRandom().nextInt(1 << 30); // guarded by this

    private volatile long actionTimeoutNanos = 60_000_000_000L;
    private volatile long perceptionTtlNanos = 2_000_000_000L;
    private volatile long askTimeoutNanos = 60_000_000_000L;
    private volatile long decomposerGraceNanos = 500_000_000L;
    private volatile boolean presenceBeliefs = true;
    private volatile String defaultPerceptionManager = PerceptionManagers.PER_SOURCE;
    private volatile String shutdownReason = null;
    private volatile boolean attached = false;
    // jason/mind (rason.mind): off (0) until the node has a subscriber for it
    private volatile long mindPeriodNanos = 0;
    private volatile MindReader mindReader = new MindReader(MIND_MAX_ITEMS, MIND_MAX_CHARS);
    private final Map<String, Long> mindPublished = new HashMap<>(); // guarded by itself

    private Bridge() {
    }

    public static Bridge get() {
        return INSTANCE;
    }

    public AgentRegistry registry() {
        return registry;
    }

    public RosClock clock() {
        return clock;
    }

    public RosTimeScheduler scheduler() {
        return scheduler;
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

    public Outbox outbox() {
        return outbox;
    }

    public Fleet fleet() {
        return fleet;
    }

    // ---- configuration (from the node's ~params) -------------------------------------

    /** 0 or less disables the timeout. */
    public void setActionTimeoutNanos(long t) {
        actionTimeoutNanos = t;
    }

    /** 0 or less: perceptions never expire. */
    public void setPerceptionTtlNanos(long t) {
        perceptionTtlNanos = t;
    }

    /** ROS time a synchronous ask to a remote agent may wait; 0 or less waits as long as the receiver is present. */
    public void setAskTimeoutNanos(long t) {
        askTimeoutNanos = t;
    }

    public long askTimeoutNanos() {
        return askTimeoutNanos;
    }

    /** Whether agents get present(Name) percepts. */
    public void setPresenceBeliefs(boolean on) {
        presenceBeliefs = on;
        reachableChanged();
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

    /** The bounds on perceptions and agent messages (see {@link InputLimits}); the node sets them. */
    public InputLimits limits() {
        return InputLimits.current();
    }

    // ---- life cycle --------------------------------------------------------------------

    /**
     * A rospy node takes the outbox and the log from now on: the sources an earlier one
     * heard are forgotten and its rate-limited warnings summarised.
     */
    public void attach() {
        shutdownReason = null;
        sources.clear();
        limited.endAll(System.nanoTime());
        announceQueued.set(false); // an earlier node's queued announcement went with its outbox
        outbox.open();
        attached = true;
    }

    /** The node is gone: nothing more is published, Java logs to stderr. */
    public void detach() {
        attached = false;
        outbox.close();
    }

    public boolean isAttached() {
        return attached;
    }

    /** The process is stopping: every pending and future action, and every pending remote ask, fails with reason. */
    public void shutdown(String reason) {
        shutdownReason = reason;
        for (RosAgArch arch : registry.all())
            arch.failPending(reason);
    }

    /** Non-null once the process is stopping: new actions fail with this reason. */
    public String shutdownReason() {
        return shutdownReason;
    }

    public synchronized int nextActionId() {
        lastActionId = lastActionId == Integer.MAX_VALUE ? 1 : lastActionId + 1;
        return lastActionId;
    }

    // ---- jason/mind -----------------------------------------------------------------------

    /** Default bounds of a snapshot: entries a list, characters an entry. */
    public static final int MIND_MAX_ITEMS = 200;
    public static final int MIND_MAX_CHARS = 500;

    /**
     * How often at most (wall clock) a running agent's state is read for jason/mind; 0
     * stops reading. Turning it on has every agent read its state in its next cycle,
     * and the next {@link #mindChanges()} returns them all.
     */
    public void setMindPeriodNanos(long t) {
        if (t < 0)
            throw new IllegalArgumentException("the mind period must be 0 (off) or more, not " + t + " ns");
        boolean turnedOn = mindPeriodNanos <= 0 && t > 0;
        mindPeriodNanos = t;
        if (turnedOn) {
            synchronized (mindPublished) {
                mindPublished.clear();
            }
            for (RosAgArch arch : registry.all())
                arch.requestMind();
        }
    }

    public long mindPeriodNanos() {
        return mindPeriodNanos;
    }

    /** Bounds of each snapshot: at most maxItems entries a list, maxChars characters an entry. */
    public void setMindLimits(int maxItems, int maxChars) {
        mindReader = new MindReader(maxItems, maxChars);
    }

    /** Where Jason's web mind inspector of this process is served (loopback), "" if no agent asked for it. */
    public String mindInspectorUrl() {
        return rason.infra.LoopbackMindInspector.url();
    }

    public MindReader mindReader() {
        return mindReader;
    }

    /**
     * Every hosted agent's newest snapshot, sorted by name, when one of them changed or an
     * agent came or went since the last call; null when nothing did (the node's thread).
     */
    public AgentMind[] mindChanges() {
        List<AgentMind> minds = new ArrayList<>();
        Map<String, Long> versions = new HashMap<>();
        for (RosAgArch arch : registry.all()) {
            AgentMind m = arch.mind().latest();
            if (m != null) {
                minds.add(m);
                versions.put(m.name(), arch.mind().version());
            }
        }
        synchronized (mindPublished) {
            if (versions.equals(mindPublished))
                return null;
            mindPublished.clear();
            mindPublished.putAll(versions);
        }
        minds.sort(Comparator.comparing(AgentMind::name));
        return minds.toArray(new AgentMind[0]);
    }

    // ---- agents ------------------------------------------------------------------------

    /** An agent starts (from the project or .create_agent): the other robots hear of it at once. */
    public void register(RosAgArch arch) {
        registry.add(arch);
        fleet.localAgentsChanged(registry.names());
        reachableChanged();
        announceSoon();
    }

    /** An agent stops (.kill_agent, or the node stops): the other robots hear of its departure at once. */
    public void unregister(RosAgArch arch) {
        if (registry.remove(arch)) {
            fleet.localAgentsChanged(registry.names());
            reachableChanged();
            announceSoon();
        }
    }

    /** What .all_names answers: the hosted agents and every reachable agent of other processes, sorted. */
    public List<String> allNames() {
        Set<String> all = new TreeSet<>(AgentRegistry.jasonAgents().keySet());
        all.addAll(registry.names());
        all.addAll(fleet.reachable());
        return new ArrayList<>(all);
    }

    /** Names of the hosted agents, sorted (the node announces them). */
    public String[] agentNames() {
        return registry.sortedNames();
    }

    public boolean hosts(String agent) {
        return registry.hosts(agent);
    }

    // ---- input from ROS ---------------------------------------------------------------

    /**
     * A rason_msgs/Perception arrived: parse it once and hand it to every agent.
     * Unparsable literals are logged with their source and dropped; the rest is kept.
     * Called by one thread of the node, with the newest message of a source (see the
     * node's coalescing); a literal the source's previous message had is not parsed again.
     *
     * @return how many literals were accepted
     */
    public int perceive(String source, String[] texts, long nowNanos) {
        InputLimits limits = InputLimits.current();
        String shownSource = InputLimits.abbreviate(source, 100);
        if (source.length() > InputLimits.MAX_SOURCE_LENGTH) {
            limited.warn(DROPPED_PERCEPTION, "dropped perception message from source '" + shownSource
                    + "': source name longer than " + InputLimits.MAX_SOURCE_LENGTH + " characters", System.nanoTime());
            return 0;
        }
        if (texts.length > limits.maxLiterals()) {
            limited.warn(DROPPED_PERCEPTION, "dropped perception message from source '" + shownSource + "': "
                    + texts.length + " literals, more than " + limits.maxLiterals() + " (the source's percepts are unchanged)",
                    System.nanoTime());
            return 0;
        }
        List<Literal> literals = sources.parse(source, texts, nowNanos, limits,
                (text, why) -> limited.warn(DROPPED_PERCEPTION, "dropped perception '" + InputLimits.abbreviate(text, 200)
                        + "' from source '" + shownSource + "': " + why, System.nanoTime()));
        if (literals == null) {
            limited.warn(DROPPED_PERCEPTION, "dropped perception message from source '" + shownSource + "': more than "
                    + limits.maxSources() + " sources heard within ~perception_ttl and this one is new"
                    + " (the others' percepts are unchanged)", System.nanoTime());
            return 0;
        }
        List<Literal> shared = List.copyOf(literals);
        for (RosAgArch arch : registry.all())
            arch.perceptionUpdate(source, shared, nowNanos);
        return shared.size();
    }

    /**
     * A burst of input is over (the node saw a perception flood end): a garbage collection now
     * lets the JVM shrink the heap the burst grew (concurrent with the node's JVM options).
     */
    public void releaseMemory() {
        System.gc();
    }

    /** The perception sources remembered now (bounded by {@link InputLimits#maxSources()}). */
    public int perceptionSources() {
        return sources.size();
    }

    /**
     * A rason_msgs/Event arrived. Events for agents not hosted here, of
     * unknown types or malformed are ignored with a log line.
     *
     * @param publisher the node that published it ("" if unknown): for action_started, the decomposer to watch
     * @return true if it settled or started an action
     */
    public boolean event(String agent, String eventType, String[] parameters, String publisher) {
        RosAgArch arch = registry.get(agent);
        if (arch == null) {
            if (warned.firstTime("event:" + agent))
                logLimited(IGNORED_EVENT, Level.INFO, "ignoring events for agent '" + InputLimits.abbreviate(agent, 100)
                        + "': not hosted here (logged once)");
            return false;
        }
        ActionEvent ev;
        try {
            ev = ActionEvent.parse(eventType, parameters);
        } catch (IllegalArgumentException e) {
            logLimited(IGNORED_EVENT, Level.WARNING, "ignored event for " + agent + ": "
                    + InputLimits.abbreviate(e.getMessage(), 300));
            return false;
        }
        if (ev.started())
            return publisher != null && !publisher.isEmpty() && arch.startedBy(ev.actionId(), publisher);
        return arch.feedback(ev.actionId(), ev.result());
    }

    /** An event whose publisher is unknown. */
    public boolean event(String agent, String eventType, String[] parameters) {
        return event(agent, eventType, parameters, "");
    }

    /**
     * Called every few tens of milliseconds with the nodes whose jason/event
     * link is up: actions taken by a node that has been gone for longer than
     * the grace fail decomposer_lost.
     */
    public void decomposersTick(String[] connected) {
        java.util.Set<String> live = java.util.Set.of(connected);
        long now = System.nanoTime();
        for (RosAgArch arch : registry.all())
            arch.decomposersTick(live, now, decomposerGraceNanos);
    }

    /** How long the decomposer that took an action may be unreachable before the action fails (wall clock). */
    public void setDecomposerGraceNanos(long t) {
        decomposerGraceNanos = t;
    }

    /** Ends an action with a result of the bridge's own (e.g. no_decomposer), from a thread of the node. */
    public boolean actionFailed(String agent, int actionId, String reason) {
        RosAgArch arch = registry.get(agent);
        return arch != null && arch.feedback(actionId, reason);
    }

    /** Called periodically with the ROS time: the one clock of timeouts and expiry. */
    public void tick(long nowNanos) {
        scheduler.advance(nowNanos);
        limited.tick(System.nanoTime());
        sources.expire(nowNanos, perceptionTtlNanos);
        for (RosAgArch arch : registry.all())
            arch.tick(nowNanos, actionTimeoutNanos, perceptionTtlNanos);
    }

    /**
     * A rason_msgs/Presence arrived (see {@link Fleet#presenceAnnounced}): its fields as published, the
     * uint64 ones as their bits.
     *
     * @param publisher the node that published it (from the connection; "" if unknown)
     */
    public void presenceAnnounced(String mas, long incarnation, String[] names, float period, boolean leaving,
            long sequence, long stamp, String keyId, byte[] mac, String publisher) {
        presenceAnnounced(mas, incarnation, names, new String[0], new String[0], period, leaving, sequence, stamp, keyId,
                mac, publisher);
    }

    /** The same, with the directory registrations it announces (dfAgents[i] provides dfServices[i]). */
    public void presenceAnnounced(String mas, long incarnation, String[] names, String[] dfAgents, String[] dfServices,
            float period, boolean leaving, long sequence, long stamp, String keyId, byte[] mac, String publisher) {
        fleet.presenceAnnounced(mas, names, dfAgents, dfServices, leaving, period,
                new FleetAuth.Signed(incarnation, sequence, stamp, keyId, mac), publisher);
    }

    /** The authentication fields of our next presence announcement; sign in the order of publishing. */
    public FleetAuth.Signed signPresence(String[] agents, float period, boolean leaving) {
        return signPresence(agents, new String[0], new String[0], period, leaving);
    }

    /** The same, for an announcement with our directory registrations (see {@link #dfAnnounced}). */
    public FleetAuth.Signed signPresence(String[] agents, String[] dfAgents, String[] dfServices, float period,
            boolean leaving) {
        return fleet.auth().signPresence(fleet.getMasId(), List.of(agents), List.of(dfAgents), List.of(dfServices),
                period, leaving);
    }

    /**
     * The authentication fields of our next agent message (from our process, the sender_mas);
     * sign in the order of publishing, so that the sequence numbers arrive increasing.
     */
    public FleetAuth.Signed signMessage(String receiverMas, String sender, String receiver, String performative,
            String content, String msgId, String inReplyTo) {
        return fleet.auth().sign(new WireMessage(fleet.getMasId(), sender, receiverMas, receiver, performative, content,
                msgId, inReplyTo));
    }

    // ---- fleet authentication (the node's ~fleet_auth, ~fleet_key_file, ~fleet_key, ~auth_window) ----

    /**
     * Requires authentic messages and presence, with the keys of a key file
     * (see {@link FleetKeys}); warns if the file is open to other users.
     *
     * @throws IllegalArgumentException the file cannot be read or holds no usable key (the message says why)
     */
    public void requireFleetKeyFile(String path) {
        Path file = Path.of(path);
        FleetKeys keys = FleetKeys.load(file);
        String open = FleetKeys.tooOpen(file);
        if (open != null)
            logger.warning(open);
        requireFleetKeys(keys);
    }

    /**
     * Requires authentic messages and presence, with the keys in text (the ~fleet_key parameter).
     *
     * @throws IllegalArgumentException no usable key in text
     */
    public void requireFleetKeyText(String text, String origin) {
        requireFleetKeys(FleetKeys.parse(text, origin));
    }

    private void requireFleetKeys(FleetKeys keys) {
        fleet.auth().require(keys);
        logger.info("fleet authentication: messages and presence signed with key " + keys.signing().id()
                + ", accepted when signed with any of " + keys.ids() + " (from " + keys.origin() + ")");
    }

    /** Signs nothing and checks nothing: any node that reaches the ROS master can command the agents. */
    public void fleetAuthOff() {
        fleet.auth().off();
        logger.warning("fleet authentication is OFF (~fleet_auth: off): messages and presence go out unsigned and"
                + " are accepted from anyone; any node that reaches the ROS master can command these agents."
                + " Only for a trusted lab network");
    }

    /** How far (wall clock) a message's stamp may be from ours; 0 or less turns the clock checks off. */
    public void setAuthWindowNanos(long t) {
        fleet.auth().setWindowNanos(t);
    }

    /** Periodic presence check with the processes our message publisher is connected to. */
    public void presenceTick(String[] linkedMas) {
        fleet.presenceTick(linkedMas);
    }

    /** This process's id in agent messages and presence: the rason_mas node name. */
    public void setMasId(String id) {
        fleet.setMasId(id);
    }

    public void setPresenceTimeoutNanos(long t) {
        fleet.setPresenceTimeoutNanos(t);
    }

    /** This process's start time as its presence announces it. */
    public void setIncarnation(long t) {
        fleet.setIncarnation(t);
    }

    /**
     * A rason_msgs/AgentMessage arrived: its fields as published, the uint64 ones as their bits.
     * Messages for other processes and our own are ignored; those that are not
     * authentic and malformed ones are logged and dropped.
     *
     * @param publisher the node that published it (from the connection; "" if unknown)
     * @return how many hosted agents it was delivered to
     */
    public int deliverMessage(String senderMas, String sender, String receiverMas, String receiver,
            String performative, String content, String msgId, String inReplyTo, long incarnation, long sequence,
            long stamp, String keyId, byte[] mac, String publisher) {
        Fleet.Incoming in = fleet.accept(
                new WireMessage(senderMas, sender, receiverMas, receiver, performative, content, msgId, inReplyTo),
                new FleetAuth.Signed(incarnation, sequence, stamp, keyId, mac), publisher, registry.hosts(sender));
        if (in == null)
            return 0;
        var hosted = AgentRegistry.jasonAgents();
        List<String> to = receiver.isEmpty() ? new ArrayList<>(hosted.keySet()) : List.of(receiver);
        int delivered = 0;
        for (String name : to) {
            LocalAgArch la = hosted.get(name);
            if (la == null) {
                fleet.noSuchReceiver(name, in.what());
                continue;
            }
            if (!trusted(name, sender, senderMas, performative, inReplyTo))
                continue;
            la.receiveMsg(Messages.toJason(performative, sender, name, in.content(), msgId, inReplyTo));
            delivered++;
        }
        return delivered;
    }

    /** Kind of the rate-limited lines of messages the trust policy refused. */
    public static final String REFUSED_MESSAGE = "refused message";

    /** The trust policy lets receiver take this message of another process (answers to its own asks always). */
    private boolean trusted(String receiver, String sender, String senderMas, String performative, String inReplyTo) {
        if (trust.allows(receiver, sender, performative))
            return true;
        RosAgArch arch = registry.get(receiver);
        if (arch != null && arch.asked(sender, inReplyTo))
            return true;
        TrustPolicy.Group g = TrustPolicy.Group.of(performative);
        TrustPolicy.Rule rule = trust.rule(receiver, g);
        limited.warn(REFUSED_MESSAGE, "refused " + InputLimits.abbreviate(performative, 100) + " from " + sender + " ("
                + InputLimits.abbreviate(senderMas, 100) + ") to " + receiver + ": " + receiver + " takes " + g.key + " from "
                + (rule.names().isEmpty() ? "no agent of another robot" : "other robots' " + rule + " only") + " ("
                + g.option() + " in the .mas2j, or ~trust)", System.nanoTime());
        return false;
    }

    /** Which agents of other processes may send what to the hosted agents. */
    public TrustPolicy trust() {
        return trust;
    }

    /**
     * A rule of the ~trust parameter.
     *
     * @param agent a hosted agent's name, or {@link TrustPolicy#EVERY_AGENT}
     * @param group a performative group ({@link TrustPolicy.Group#key})
     * @param spec all, none or agent names
     * @throws IllegalArgumentException saying what is wrong
     */
    public void setTrust(String agent, String group, String spec) {
        if (!agent.equals(TrustPolicy.EVERY_AGENT) && !agent.matches(Fleet.NAME_PATTERN))
            throw new IllegalArgumentException("'" + InputLimits.abbreviate(agent, 60) + "' is not an agent name or '*'");
        trust.setParameterRule(agent, TrustPolicy.Group.byKey(group), TrustPolicy.Rule.parse(spec));
    }

    // ---- the directory facilitator (Jason's .df_* through RasonLocalMAS) ------------------

    /** Jason's name for the directory facilitator: subscribers hear from it, as in one MAS. */
    public static final String DF_NAME = "df";

    private final AtomicBoolean announceQueued = new AtomicBoolean();

    public void dfRegister(String agent, String service) {
        if (fleet.directory().register(agent, service))
            announceSoon();
    }

    public void dfDeregister(String agent, String service) {
        if (fleet.directory().deregister(agent, service))
            announceSoon();
    }

    public void dfSubscribe(String agent, String service) {
        fleet.directory().subscribe(agent, service);
    }

    /** The providers of service in the whole fleet, sorted. */
    public List<String> dfSearch(String service) {
        return fleet.directory().search(service);
    }

    /** A hosted agent stopped: its registrations and subscriptions go. */
    public void dfAgentGone(String agent) {
        if (fleet.directory().agentGone(agent))
            announceSoon();
    }

    /** Our registrations, for the presence the node is about to announce (a later change queues another). */
    public FleetDirectory.Announced dfAnnounced() {
        announceQueued.set(false);
        return fleet.directory().announced();
    }

    /**
     * Other processes hear of a change of our agents or their registrations at once, not at our
     * next periodic announcement (one announcement for changes queued before the node takes it).
     */
    private void announceSoon() {
        if (announceQueued.compareAndSet(false, true) && !outbox.offer(new Outbound.Announce()))
            announceQueued.set(false); // no node yet: its first announcement will have them
    }

    /**
     * Tells subscribers what the directory says changed, as Jason's DF does: tell
     * provider(Agent, "service") from df when one comes, untell when one goes. Only queues
     * the messages in their mailboxes: each agent takes them on its own thread.
     */
    @Override
    public void providersChanged(List<FleetDirectory.Notice> notices) {
        var hosted = AgentRegistry.jasonAgents();
        for (FleetDirectory.Notice n : notices) {
            LocalAgArch la = hosted.get(n.subscriber());
            if (la == null)
                continue;
            Literal provider = ASSyntax.createLiteral("provider", new Atom(n.provider()), new StringTermImpl(n.service()));
            la.receiveMsg(new Message(n.added() ? "tell" : "untell", DF_NAME, n.subscriber(), provider));
        }
    }

    // ---- Fleet.Listener ----------------------------------------------------------------

    /** Gives every agent the current present/1 list; the lock keeps a newer list from being overtaken by an older one. */
    @Override
    public void reachableChanged() {
        synchronized (presencePushLock) {
            List<String> names = presenceBeliefs ? allNames() : List.of();
            for (RosAgArch arch : registry.all())
                arch.presenceUpdate(names);
        }
    }

    @Override
    public void mustStop(String why) {
        outbox.offer(new Outbound.Stop(1));
    }

    @Override
    public void receiversLost(Collection<String> names) {
        for (RosAgArch arch : registry.all())
            arch.receiversLost(names);
    }

    public static void log(Level level, String message) {
        logger.log(level, message);
    }

    /** Kinds of the rate-limited log lines (see {@link RateLimitedLog}). */
    public static final String DROPPED_PERCEPTION = "dropped perception";
    public static final String IGNORED_EVENT = "ignored event";

    /** Logs a line of kind, at most a few per period of that kind (wall clock); the rest are counted and summarised. */
    public void logLimited(String kind, Level level, String message) {
        limited.log(kind, level, message, System.nanoTime());
    }
}
