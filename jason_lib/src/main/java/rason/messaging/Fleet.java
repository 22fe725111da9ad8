package rason.messaging;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collection;
import java.util.List;
import java.util.Set;
import java.util.logging.Logger;

import jason.asSyntax.Term;

import rason.core.Clock;
import rason.core.InputLimits;
import rason.core.RateLimitedLog;
import rason.core.WarnOnce;

/**
 * This process among the other rason_mas processes of the fleet (thesis
 * §5.6): who is reachable, from their presence announcements and messages, and
 * which incoming agent messages are well-formed. Logs what changes; tells its
 * {@link FleetListener} when the reachable agents change or some leave.
 */
public final class Fleet {

    /** An incoming agent message that passed the checks. */
    public record Incoming(String what, Term content) {
    }

    /** Jason atoms: what an agent name must look like to become source(Name). */
    public static final String NAME_PATTERN = "[a-z][A-Za-z0-9_]*";

    private final Logger logger;
    private final FleetListener listener;
    private final PresenceTable presence = new PresenceTable(); // guarded by itself
    private final WarnOnce warned;
    private final RateLimitedLog limited;
    private final FleetAuth auth;
    private final InputLimits limits;
    private final Clock wall;
    private final FleetDirectory directory;
    private volatile String masId = "";
    private volatile long presenceTimeoutNanos = 2_000_000_000L;
    private volatile long incarnation = 0;
    private volatile boolean stopping = false;

    /** With the default input limits, on the wall clock. */
    public Fleet(Logger logger, FleetListener listener) {
        this(logger, listener, new RateLimitedLog(logger), new FleetAuth(), new InputLimits(), Clock.WALL);
    }

    /**
     * @param limited where dropped messages are logged (kind "dropped message"), at most a few lines per period
     * @param auth signs our messages and presence and checks others' (required by default: set keys, or turn it off)
     * @param limits the bounds on incoming content; wall measures silences and stamps log periods
     */
    public Fleet(Logger logger, FleetListener listener, RateLimitedLog limited, FleetAuth auth, InputLimits limits,
            Clock wall) {
        this.logger = logger;
        this.listener = listener;
        this.warned = new WarnOnce(logger);
        this.limited = limited;
        this.auth = auth;
        this.limits = limits;
        this.wall = wall;
        // never called under the presence lock: the directory asks the table who owns a name
        this.directory = new FleetDirectory(this::sendableMasOf, listener::providersChanged);
        presence.setPulseGraceNanos(presenceTimeoutNanos / 2);
    }

    /** The directory facilitator of the whole fleet (our registrations and those others announce). */
    public FleetDirectory directory() {
        return directory;
    }

    /** The authentication of our traffic and others' (keys, window, off). */
    public FleetAuth auth() {
        return auth;
    }

    /** This process's id in agent messages and presence: the rason_mas node name. */
    public void setMasId(String id) {
        masId = id == null ? "" : id;
    }

    public String getMasId() {
        return masId;
    }

    /** This process's start time, as its presence announces it: the later of two duplicates stops. */
    public void setIncarnation(long t) {
        incarnation = t;
        auth.setIncarnation(t);
    }

    /** Silence after which another process counts as gone (wall clock); a pulse this half as old outweighs a will. */
    public void setPresenceTimeoutNanos(long t) {
        presenceTimeoutNanos = t;
        synchronized (presence) { presence.setPulseGraceNanos(t / 2); }
    }

    /** How long a process gone silent may come back to what was sent to it (see {@link PresenceTable#setAwayHoldNanos}). */
    public void setAwayHoldNanos(long t) {
        synchronized (presence) { presence.setAwayHoldNanos(t); }
    }

    /** The agents this process hosts changed. */
    public void localAgentsChanged(Collection<String> local) {
        PresenceTable.Changes c;
        synchronized (presence) {
            c = presence.setLocal(local);
        }
        apply(c);
    }

    /**
     * A presence announcement arrived (signed: its authentication fields; publisher: who published it, "" if
     * unknown), with its directory registrations (dfAgents[i] provides dfServices[i]), which replace the earlier
     * ones, over the channel connection named link ("" if the channel has none): the last will of that
     * connection, and only of that one, counts as mas leaving ({@link #willArrived}). Ours, malformed ones
     * (logged) and, with authentication on, unauthentic ones (rate-limited) change nothing.
     */
    public void presenceAnnounced(String mas, String[] names, String[] dfAgents, String[] dfServices, boolean leaving,
            float period, FleetAuth.Signed signed, String publisher, String link) {
        if (mas == null || mas.isEmpty()) {
            warned.warn("presence:", "ignored a presence announcement without mas_id");
            return;
        }
        if (mas.equals(masId))
            return;
        FleetAuth.Refusal refused = auth.verifyPresence(mas, Arrays.asList(names), Arrays.asList(dfAgents),
                Arrays.asList(dfServices), period, leaving, link, signed);
        if (refused == null)
            refused = auth.admit(FleetAuth.Kind.PRESENCE, mas, signed, wall.nanos(),
                    () -> publishedBy(mas, publisher));
        if (refused != null) {
            limited.warn(DROPPED_PRESENCE + " (" + refused.problem().word + ")", "dropped presence of "
                    + InputLimits.abbreviate(mas, 100) + (leaving ? " (leaving)" : " announcing "
                    + InputLimits.abbreviate(Arrays.toString(names), 200)) + ": " + refused.text(), wall.nanos());
            return;
        }
        List<String> valid = new ArrayList<>(names.length);
        for (String n : names) {
            if (n != null && n.matches(NAME_PATTERN))
                valid.add(n);
            else
                warned.warn("presence:" + mas + ":" + n, "ignored agent name '" + n + "' announced by " + mas
                        + ": not a Jason atom");
        }
        PresenceTable.Changes c;
        synchronized (presence) {
            c = presence.announced(mas, signed.incarnation(), valid, leaving, wall.nanos());
            if (leaving)
                links.remove(mas);
            else if (!c.stale)
                links.put(mas, new Link(signed.incarnation(), link == null ? "" : link));
        }
        apply(c);
        if (!leaving && !c.stale)
            directory.remote(mas, FleetDirectory.valid(valid, dfAgents, dfServices, (entry, why) -> limited.warn(
                    IGNORED_REGISTRATION, "ignored directory registration '" + InputLimits.abbreviate(entry, 200)
                            + "' announced by " + InputLimits.abbreviate(mas, 100) + ": " + why, wall.nanos())));
    }

    /** The channel connection a process last announced itself over. */
    private record Link(long incarnation, String id) {
    }

    private final java.util.Map<String, Link> links = new java.util.HashMap<>(); // guarded by presence

    /**
     * The last will of process mas's channel connection named link arrived: mas leaves if that is
     * the connection of its current run it last announced itself over. A will of any other
     * connection (an earlier one, a copy played again after mas reconnected) changes nothing.
     *
     * @param signed its authentication fields (see {@link FleetAuth#signWill})
     * @param publisher who published it, as the channel knows it ("" if unknown)
     */
    public void willArrived(String mas, String link, FleetAuth.Signed signed, String publisher) {
        if (mas == null || mas.isEmpty() || mas.equals(masId))
            return;
        FleetAuth.Refusal refused = auth.verifyWill(mas, link, signed);
        if (refused == null)
            refused = publishedBy(mas, publisher);
        PresenceTable.Changes c = null;
        synchronized (presence) {
            Link current = links.get(mas);
            if (refused == null && current == null)
                return; // gone already (it left, or a retained will of an earlier run): nothing to say
            if (refused == null && (link.isEmpty() || !current.id().equals(link)
                    || current.incarnation() != signed.incarnation()))
                refused = new FleetAuth.Refusal(FleetAuth.Problem.REPLAYED, "the will of connection "
                        + InputLimits.abbreviate(link, 40) + ", which is not the one " + InputLimits.abbreviate(mas, 100)
                        + " last announced itself over");
            if (refused == null) {
                links.remove(mas);
                c = presence.connectionEnded(mas, signed.incarnation(), wall.nanos());
            }
        }
        if (refused != null) {
            limited.warn(DROPPED_PRESENCE + " (" + refused.problem().word + ")", "dropped last will of "
                    + InputLimits.abbreviate(mas, 100) + ": " + refused.text(), wall.nanos());
            return;
        }
        logger.info("presence: the connection of " + mas + " ended without leaving (its last will)");
        apply(c);
    }

    /** A pulse of mas arrived (see {@link FleetAuth#signPulse}); publisher as for {@link #willArrived}. */
    public void pulseArrived(String mas, FleetAuth.Signed signed, String publisher) {
        if (mas == null || mas.isEmpty() || mas.equals(masId))
            return;
        FleetAuth.Refusal refused = auth.verifyPulse(mas, signed);
        if (refused == null)
            refused = auth.admit(FleetAuth.Kind.PULSE, mas, signed, wall.nanos(), () -> publishedBy(mas, publisher));
        if (refused != null) {
            limited.warn(DROPPED_PRESENCE + " (" + refused.problem().word + ")", "dropped pulse of "
                    + InputLimits.abbreviate(mas, 100) + ": " + refused.text(), wall.nanos());
            return;
        }
        PresenceTable.Changes c;
        synchronized (presence) {
            c = presence.pulse(mas, signed.incarnation(), wall.nanos());
        }
        apply(c);
    }

    /** Periodic check for a channel without links of its own (a broker): only silence or a will makes a process leave. */
    public void presenceTickAllLinked() {
        PresenceTable.Changes c;
        synchronized (presence) {
            c = presence.tick(presence.peerIds(), wall.nanos(), presenceTimeoutNanos);
            links.keySet().retainAll(presence.peerIds());
        }
        apply(c);
    }

    /** Kind of the rate-limited lines of directory registrations in a presence that are ignored. */
    public static final String IGNORED_REGISTRATION = "ignored directory registration";

    /** Periodic check (every few tens of ms) with the processes our message publisher is connected to: silent ones leave. */
    public void presenceTick(String[] linkedMas) {
        PresenceTable.Changes c;
        synchronized (presence) {
            c = presence.tick(Arrays.asList(linkedMas), wall.nanos(), presenceTimeoutNanos);
        }
        apply(c);
    }

    /** How many other processes (robots) can be reached now. */
    public int reachableProcesses() {
        synchronized (presence) { return presence.linkedPeers(); }
    }

    /** Names of the reachable agents of other processes, sorted. */
    public Set<String> reachable() {
        synchronized (presence) { return presence.reachable(); }
    }

    /** The process a message to agent goes to (see {@link PresenceTable#sendableMasOf}), or null. */
    public String sendableMasOf(String agent) {
        synchronized (presence) { return presence.sendableMasOf(agent); }
    }

    public String whyUnreachable(String agent) {
        synchronized (presence) { return presence.whyUnreachable(agent); }
    }

    /**
     * Checks a rason_msgs/AgentMessage for this process and counts it as
     * hearing from its sender's process. With authentication on, it must be
     * authentic (see {@link FleetAuth}), published by its sender process, and
     * its sender among that process's announced agents when the announcement
     * of that run is known (a message may overtake the first announcement).
     *
     * @param signed its authentication fields
     * @param publisher the node that published it (from the connection; "" if unknown)
     * @param hostsSender whether this process hosts an agent of the sender's name
     * @return the parsed message, or null if it is not for us (ignored), not authentic or malformed (logged)
     */
    public Incoming accept(WireMessage m, FleetAuth.Signed signed, String publisher, boolean hostsSender) {
        String senderMas = m.senderMas(), sender = m.sender(), receiver = m.receiver();
        if (senderMas.equals(masId) || !(m.receiverMas().isEmpty() || m.receiverMas().equals(masId)))
            return null;
        String what = InputLimits.abbreviate(m.performative(), 100) + " from " + InputLimits.abbreviate(sender, 100)
                + " (" + InputLimits.abbreviate(senderMas, 100) + ") to "
                + (receiver.isEmpty() ? "everyone" : InputLimits.abbreviate(receiver, 100));
        FleetAuth.Refusal refused = auth.verify(m, signed);
        if (refused == null)
            refused = auth.admit(FleetAuth.Kind.MESSAGE, senderMas, signed, wall.nanos(),
                    () -> forgedMessage(m, signed, publisher));
        if (refused != null) {
            limited.warn(DROPPED_MESSAGE + " (" + refused.problem().word + ")",
                    "dropped message " + what + ": " + refused.text(), wall.nanos());
            return null;
        }
        if (senderMas.isEmpty() || !sender.matches(NAME_PATTERN)) {
            dropped("dropped message " + what + ": sender and sender_mas must be set, and the sender a Jason atom");
            return null;
        }
        if (!m.performative().matches(NAME_PATTERN)) {
            dropped("dropped message " + what + ": performative '" + InputLimits.abbreviate(m.performative(), 100)
                    + "' is not a Jason atom");
            return null;
        }
        Term term;
        try {
            term = Messages.parseContent(m.content(), limits);
        } catch (IllegalArgumentException e) {
            dropped("dropped message " + what + ": " + e.getMessage());
            return null;
        }
        PresenceTable.Changes c;
        synchronized (presence) {
            c = presence.messageFrom(senderMas, sender, wall.nanos());
        }
        apply(c);
        if (hostsSender)
            warned.warn("sender:" + sender, "message from " + sender + " of " + senderMas + ", a name this process also hosts:"
                    + " replies to it stay here; give one of the robots an ~agent_prefix");
        return new Incoming(what, term);
    }

    /** Checks of an authentic message against what its process announced (under the replay lock of {@link FleetAuth#admit}). */
    private FleetAuth.Refusal forgedMessage(WireMessage m, FleetAuth.Signed signed, String publisher) {
        FleetAuth.Refusal r = publishedBy(m.senderMas(), publisher);
        if (r != null)
            return r;
        synchronized (presence) {
            long announced = presence.announcedIncarnation(m.senderMas());
            if (announced == 0 || signed.incarnation() > announced)
                return null; // not announced yet (or restarted since): its presence may come on another connection
            if (signed.incarnation() < announced)
                return new FleetAuth.Refusal(FleetAuth.Problem.REPLAYED, "from an earlier run of " + m.senderMas()
                        + " (incarnation " + signed.incarnation() + "; it now runs " + announced + ")");
            if (!presence.announces(m.senderMas(), m.sender()))
                return new FleetAuth.Refusal(FleetAuth.Problem.FORGED, InputLimits.abbreviate(m.senderMas(), 100)
                        + " does not host " + InputLimits.abbreviate(m.sender(), 100) + " (it announces "
                        + presence.agentsOf(m.senderMas()) + ")");
            return null;
        }
    }

    /** A signed message or presence must come from the node it names: a copy published by another node is forged. */
    private static FleetAuth.Refusal publishedBy(String mas, String publisher) {
        if (publisher == null || publisher.isEmpty() || publisher.equals(mas))
            return null;
        return new FleetAuth.Refusal(FleetAuth.Problem.FORGED, "published by node "
                + InputLimits.abbreviate(publisher, 100) + ", not by " + InputLimits.abbreviate(mas, 100));
    }

    /** Logs a message for an agent this process does not host, once per name. */
    public void noSuchReceiver(String name, String what) {
        if (warned.firstTime("receiver:" + name))
            dropped("dropped message " + what + ": no agent '" + InputLimits.abbreviate(name, 100)
                    + "' here (logged once per name)");
    }

    /** Kind of the rate-limited lines of dropped messages (those not authentic: "dropped message (reason)"). */
    public static final String DROPPED_MESSAGE = "dropped message";
    /** Kind of the rate-limited lines of presence that is not authentic: "dropped presence (reason)". */
    public static final String DROPPED_PRESENCE = "dropped presence";

    private void dropped(String line) {
        limited.warn(DROPPED_MESSAGE, line, wall.nanos());
    }

    /** "/robot1" for "/robot1/rason_mas", "" for "/rason_mas". */
    static String namespaceOf(String masId) {
        int slash = masId.lastIndexOf('/');
        return slash <= 0 ? "" : masId.substring(0, slash);
    }

    private void apply(PresenceTable.Changes c) {
        if (c.isEmpty())
            return;
        directory.fleetChanged(c.departed); // who owns which name may have changed too
        for (String e : c.events)
            logger.info("presence: " + e);
        for (String e : c.clashes)
            logger.severe(e);
        for (String a : c.joined)
            logger.info("presence: agent " + a + " is reachable");
        for (String a : c.left)
            logger.info("presence: agent " + a + " is no longer reachable");
        if (!c.lost.isEmpty())
            listener.receiversLost(c.lost);
        for (PresenceTable.LocalClash d : c.localClashes)
            if (!stopping && namespaceOf(d.masId()).equals(namespaceOf(masId)) && d.incarnation() != 0
                    && d.incarnation() < incarnation) {
                stopping = true;
                String why = "agent '" + d.agent() + "' is already hosted by " + d.masId() + " in the same namespace: two"
                        + " processes would both take its feedback on jason/event, so this later one stops";
                logger.severe(why);
                listener.mustStop(why);
            }
        if (c.reachabilityChanged())
            listener.reachableChanged();
    }
}
