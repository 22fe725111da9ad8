package rason.messaging;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.Consumer;
import java.util.function.Supplier;
import java.util.logging.Logger;

import jason.asSemantics.Message;
import jason.asSemantics.TransitionSystem;
import jason.infra.local.LocalAgArch;

import rason.core.Clock;
import rason.core.InputLimits;
import rason.core.RateLimitedLog;

/**
 * This process's agents among the other processes of the fleet (thesis §5.6), both
 * ways: presence and agent messages that arrive are checked ({@link Fleet},
 * {@link FleetAuth}), let through the {@link TrustPolicy} and put in the receivers'
 * mailboxes; what our agents send leaves through the {@link FleetChannel}; the
 * directory facilitator spans the fleet ({@link FleetDirectory}).
 */
public final class FleetPort implements FleetListener {

    /** Kind of the rate-limited lines of messages the trust policy refused. */
    public static final String REFUSED_MESSAGE = "refused message";

    private final Logger logger;
    private final RateLimitedLog limited;
    private final Clock wall;
    private final Clock rosClock;
    private volatile FleetChannel channel;
    private final Fleet fleet;
    private final TrustPolicy trust = new TrustPolicy();
    private final Map<String, AgentMessaging> agents = new ConcurrentHashMap<>();
    private final Supplier<Map<String, LocalAgArch>> jasonAgents;
    private final Consumer<List<String>> presence;
    private final Runnable mustStop;
    private final Object presencePushLock = new Object();
    private final DirectoryFacilitator df;
    private volatile boolean presenceBeliefs = true;
    private volatile long askTimeoutNanos;
    private volatile long messageTtlNanos = 60_000_000_000L;
    private final FleetNames names;

    /**
     * @param rosClock the time of asks' timeouts
     * @param jasonAgents every agent of this process as Jason's infrastructure knows them
     * @param presence gives every hosted agent the reachable agents (present/1)
     * @param mustStop stops this process (it duplicates an earlier one's agent)
     */
    public FleetPort(Logger logger, RateLimitedLog limited, InputLimits limits, Clock wall, Clock rosClock,
            FleetChannel channel, Supplier<Map<String, LocalAgArch>> jasonAgents, Consumer<List<String>> presence,
            Runnable mustStop, long askTimeoutNanos) {
        this.logger = logger;
        this.limited = limited;
        this.wall = wall;
        this.rosClock = rosClock;
        this.channel = channel;
        this.jasonAgents = jasonAgents;
        this.presence = presence;
        this.mustStop = mustStop;
        this.askTimeoutNanos = askTimeoutNanos;
        this.fleet = new Fleet(logger, this, limited, new FleetAuth(), limits, wall);
        this.names = new FleetNames(agents.keySet(), jasonAgents, fleet);
        this.df = new DirectoryFacilitator(fleet.directory(), jasonAgents, () -> this.channel);
    }

    public Fleet fleet() {
        return fleet;
    }

    /** Messages and presence go through channel from now on (set before the agents start). */
    public void useChannel(FleetChannel channel) {
        this.channel = channel;
    }

    public FleetAuth auth() {
        return fleet.auth();
    }

    public FleetDirectory directory() {
        return fleet.directory();
    }

    /** Which agents of other processes may send what to the hosted agents. */
    public TrustPolicy trust() {
        return trust;
    }

    // ---- the hosted agents ----------------------------------------------------------

    /** A hosted agent starts: the other robots hear of it at once. */
    public AgentMessaging join(String agent, TransitionSystem ts, AgentMessaging.Local local, Runnable wake) {
        AgentMessaging m = new AgentMessaging(agent, ts, this, local, wake);
        agents.put(agent, m);
        localAgentsChanged();
        return m;
    }

    /** A hosted agent stops (.kill_agent, or the node stops): the other robots hear of its departure at once. */
    public void leave(String agent, AgentMessaging m) {
        if (agents.remove(agent, m))
            localAgentsChanged();
    }

    private void localAgentsChanged() {
        fleet.localAgentsChanged(agents.keySet());
        reachableChanged();
        df.announceSoon();
    }

    /** The names of this process's agents, and of every agent it can reach. */
    public FleetNames names() {
        return names;
    }

    /** Every agent of this process, as Jason's infrastructure knows them. */
    Map<String, LocalAgArch> jasonAgents() {
        return jasonAgents.get();
    }

    // ---- configuration (from the node's ~params) ------------------------------------

    /** This process's id in agent messages and presence (the rason_mas node name). */
    public void setMasId(String id) {
        fleet.setMasId(id);
    }

    public String masId() {
        return fleet.getMasId();
    }

    /** This process's start time as its presence announces it. */
    public void setIncarnation(long t) {
        fleet.setIncarnation(t);
    }

    /** Silence after which another process counts as gone (wall clock). */
    public void setPresenceTimeoutNanos(long t) {
        fleet.setPresenceTimeoutNanos(t);
    }

    /** How far (wall clock) a message's stamp may be from ours; 0 or less turns the clock checks off. */
    public void setAuthWindowNanos(long t) {
        fleet.auth().setWindowNanos(t);
    }

    /** Whether agents get present(Name) percepts. */
    public void setPresenceBeliefs(boolean on) {
        presenceBeliefs = on;
        reachableChanged();
    }

    /** ROS time a synchronous ask to a remote agent may wait; 0 or less waits as long as the receiver is present. */
    public void setAskTimeoutNanos(long t) {
        askTimeoutNanos = t;
    }

    long askTimeoutNanos() {
        return askTimeoutNanos;
    }

    /** How long a remote message may take to be delivered before its send fails (wall clock). */
    public void setMessageTtlNanos(long t) {
        messageTtlNanos = t;
    }

    long messageTtlNanos() {
        return messageTtlNanos;
    }

    long rosNow() {
        return rosClock.nanos();
    }

    long wallNow() {
        return wall.nanos();
    }

    void log(java.util.logging.Level level, String line) {
        logger.log(level, line);
    }

    /**
     * Requires authentic messages and presence, with the keys of a key file (see
     * {@link FleetKeys}); warns if the file is open to other users.
     *
     * @throws IllegalArgumentException the file cannot be read or holds no usable key (the message says why)
     */
    public void requireKeyFile(String path) {
        Path file = Path.of(path);
        FleetKeys keys = FleetKeys.load(file);
        String open = FleetKeys.tooOpen(file);
        if (open != null)
            logger.warning(open);
        requireKeys(keys);
    }

    /** The same, with the keys in text (the ~fleet_key parameter). */
    public void requireKeyText(String text, String origin) {
        requireKeys(FleetKeys.parse(text, origin));
    }

    private void requireKeys(FleetKeys keys) {
        fleet.auth().require(keys);
        logger.info("fleet authentication: messages and presence signed with key " + keys.signing().id()
                + ", accepted when signed with any of " + keys.ids() + " (from " + keys.origin() + ")");
    }

    /** Signs nothing and checks nothing: any node that reaches the fleet's channel can command the agents. */
    public void authOff() {
        fleet.auth().off();
        logger.warning("fleet authentication is OFF (~fleet_auth: off): messages and presence go out unsigned and"
                + " are accepted from anyone; any node that reaches the ROS master can command these agents."
                + " Only for a trusted lab network");
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

    // ---- what arrives -----------------------------------------------------------------

    /**
     * A presence announcement arrived (see {@link Fleet#presenceAnnounced}), with the directory
     * registrations it announces (dfAgents[i] provides dfServices[i]), over the channel
     * connection named link ("" if the channel has none; see {@link Fleet#willArrived}).
     *
     * @param publisher who published it, as the channel knows it ("" if unknown)
     */
    public void presenceAnnounced(String mas, long incarnation, String[] names, String[] dfAgents, String[] dfServices,
            float period, boolean leaving, long sequence, long stamp, String keyId, byte[] mac, String publisher,
            String link) {
        fleet.presenceAnnounced(mas, names, dfAgents, dfServices, leaving, period,
                new FleetAuth.Signed(incarnation, sequence, stamp, keyId, mac), publisher, link);
    }

    /** The last will of process mas's channel connection named link (see {@link Fleet#willArrived}). */
    public void willArrived(String mas, String link, FleetAuth.Signed signed, String publisher) {
        fleet.willArrived(mas, link, signed, publisher);
    }

    /** Periodic presence check of a channel that reaches every process it hears (see {@link Fleet#presenceTickAllLinked}). */
    public void presenceTickAllLinked() {
        fleet.presenceTickAllLinked();
    }

    /** Periodic presence check with the processes the channel is linked to. */
    public void presenceTick(String[] linkedMas) {
        fleet.presenceTick(linkedMas);
    }

    /**
     * An agent message arrived. Messages for other processes and our own are ignored; those
     * that are not authentic and malformed ones are logged and dropped, and those the trust
     * policy refuses too.
     *
     * @param publisher who published it, as the channel knows it ("" if unknown)
     * @return how many hosted agents it was delivered to
     */
    public int deliver(WireMessage m, FleetAuth.Signed signed, String publisher) {
        Fleet.Incoming in = fleet.accept(m, signed, publisher, agents.containsKey(m.sender()));
        if (in == null)
            return 0;
        if (Receipts.isReceipt(m)) {
            Optional.ofNullable(agents.get(m.receiver())).ifPresent(sender -> sender.receiptArrived(m));
            return 0;
        }
        Map<String, LocalAgArch> hosted = jasonAgents();
        List<String> to = m.receiver().isEmpty() ? new ArrayList<>(hosted.keySet()) : List.of(m.receiver());
        int delivered = 0;
        for (String name : to) {
            LocalAgArch la = hosted.get(name);
            if (la == null) {
                fleet.noSuchReceiver(name, in.what());
                continue;
            }
            boolean trusted = trusted(name, m);
            if (trusted) {
                la.receiveMsg(Messages.toJason(m.performative(), m.sender(), name, in.content(), m.msgId(), m.inReplyTo()));
                delivered++;
            }
            if (Receipts.wanted(m))
                channel.send(Receipts.of(m, name, fleet.getMasId(), !trusted));
        }
        return delivered;
    }

    /** The trust policy lets receiver take this message of another process (answers to its own asks always). */
    private boolean trusted(String receiver, WireMessage m) {
        if (trust.allows(receiver, m.sender(), m.performative()))
            return true;
        AgentMessaging asker = agents.get(receiver);
        if (asker != null && asker.asked(m.sender(), m.inReplyTo()))
            return true;
        limited.warn(REFUSED_MESSAGE, trust.refusal(receiver, m.sender(), m.senderMas(), m.performative()), wall.nanos());
        return false;
    }

    // ---- what goes out -----------------------------------------------------------------

    /** Hands an agent message of ours to the channel (receiverMas "": every other process). */
    boolean send(String receiverMas, Message m) {
        return channel.send(new WireMessage(fleet.getMasId(), m.getSender(), receiverMas, m.getReceiver(),
                m.getIlForce(), Messages.contentText(m), m.getMsgId(), m.getInReplyTo() == null ? "" : m.getInReplyTo()));
    }

    /**
     * The authentication fields of our next presence announcement, over our channel connection
     * named link ("" if the channel has none); sign in the order of publishing.
     */
    public FleetAuth.Signed signPresence(String[] agents, String[] dfAgents, String[] dfServices, float period,
            boolean leaving, String link) {
        return fleet.auth().signPresence(fleet.getMasId(), List.of(agents), List.of(dfAgents), List.of(dfServices),
                period, leaving, link);
    }

    /** The last will of our channel connection named link (see {@link FleetAuth#signWill}). */
    public FleetAuth.Signed signWill(String link) {
        return fleet.auth().signWill(fleet.getMasId(), link);
    }

    /**
     * The authentication fields of our next agent message; sign in the order of publishing,
     * so that the sequence numbers arrive increasing.
     */
    public FleetAuth.Signed sign(WireMessage m) {
        return fleet.auth().sign(m);
    }

    /** Jason's directory facilitator over the fleet: our registrations and the fleet's. */
    public DirectoryFacilitator df() {
        return df;
    }

    /** Our registrations, for the presence about to be announced (a later change queues another). */
    public FleetDirectory.Announced announced() {
        return df.announced();
    }

    /** A node takes the channel again: an earlier node's queued announcement went with it. */
    public void reopen() {
        df.reopen();
    }

    @Override
    public void providersChanged(List<FleetDirectory.Notice> notices) {
        df.providersChanged(notices);
    }

    // ---- FleetListener ------------------------------------------------------------------

    /** Gives every agent the current present/1 list; the lock keeps a newer list from being overtaken by an older one. */
    @Override
    public void reachableChanged() {
        synchronized (presencePushLock) {
            presence.accept(presenceBeliefs ? names.allNames() : List.of());
        }
    }

    @Override
    public void mustStop(String why) {
        mustStop.run();
    }

    @Override
    public void receiversLost(Collection<String> names) {
        for (AgentMessaging m : agents.values())
            m.receiversLost(names);
    }

    /** Periodic, with the ROS time: asks that waited too long fail. */
    public void tick(long rosNanos) {
        for (AgentMessaging m : agents.values())
            m.tick(rosNanos);
    }

    /** The process is stopping: every pending remote ask fails with reason. */
    public void shutdown(String reason) {
        for (AgentMessaging m : agents.values())
            m.stop(reason);
    }
}
