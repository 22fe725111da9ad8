package rason.messaging;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collection;
import java.util.List;
import java.util.Set;
import java.util.logging.Logger;

import jason.asSyntax.Term;

import rason.bridge.InputLimits;

/**
 * This process among the other rason_mas processes of the fleet (thesis
 * §5.6): who is reachable, from their presence announcements and messages, and
 * which incoming agent messages are well-formed. Logs what changes; tells its
 * {@link Listener} when the reachable agents change or some leave.
 */
public final class Fleet {

    /** What the agents need to hear of the fleet. */
    public interface Listener {
        /** The set of reachable agents changed (present/1 beliefs). */
        void reachableChanged();

        /** These agents' processes ended: answers they owe will never come. */
        void receiversLost(Collection<String> names);

        /** This process must not go on (it duplicates an earlier one's agent in the same namespace). */
        void mustStop(String why);
    }

    /** An incoming agent message that passed the checks. */
    public record Incoming(String what, Term content) {
    }

    /** Jason atoms: what an agent name must look like to become source(Name). */
    public static final String NAME_PATTERN = "[a-z][A-Za-z0-9_]*";

    private final Logger logger;
    private final Listener listener;
    private final PresenceTable presence = new PresenceTable(); // guarded by itself
    private final WarnOnce warned;
    private final RateLimitedLog limited;
    private volatile String masId = "";
    private volatile long presenceTimeoutNanos = 2_000_000_000L;
    private volatile long incarnation = 0;
    private volatile boolean stopping = false;

    public Fleet(Logger logger, Listener listener) {
        this(logger, listener, new RateLimitedLog(logger));
    }

    /** @param limited where dropped messages are logged (kind "dropped message"), at most a few lines per period */
    public Fleet(Logger logger, Listener listener, RateLimitedLog limited) {
        this.logger = logger;
        this.listener = listener;
        this.warned = new WarnOnce(logger);
        this.limited = limited;
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
    }

    /** Silence after which another process counts as gone (wall clock). */
    public void setPresenceTimeoutNanos(long t) {
        presenceTimeoutNanos = t;
    }

    /** The agents this process hosts changed. */
    public void localAgentsChanged(Collection<String> local) {
        PresenceTable.Changes c;
        synchronized (presence) {
            c = presence.setLocal(local);
        }
        apply(c);
    }

    /** A rason_msgs/Presence arrived. Our own announcements and malformed ones are ignored (the latter with a log line). */
    public void presenceAnnounced(String mas, long incarnation, String[] names, boolean leaving) {
        if (mas == null || mas.isEmpty()) {
            warned.warn("presence:", "ignored a presence announcement without mas_id");
            return;
        }
        if (mas.equals(masId))
            return;
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

    /** Names of the reachable agents of other processes, sorted. */
    public Set<String> reachable() {
        synchronized (presence) {
            return presence.reachable();
        }
    }

    /** The process a message to agent goes to (see {@link PresenceTable#sendableMasOf}), or null. */
    public String sendableMasOf(String agent) {
        synchronized (presence) {
            return presence.sendableMasOf(agent);
        }
    }

    public String whyUnreachable(String agent) {
        synchronized (presence) {
            return presence.whyUnreachable(agent);
        }
    }

    /**
     * Checks a rason_msgs/AgentMessage for this process and counts it as
     * hearing from its sender's process.
     *
     * @param hostsSender whether this process hosts an agent of the sender's name
     * @return the parsed message, or null if it is not for us (ignored) or malformed (logged)
     */
    public Incoming accept(String senderMas, String sender, String receiverMas, String receiver, String performative,
            String content, boolean hostsSender) {
        if (senderMas.equals(masId) || !(receiverMas.isEmpty() || receiverMas.equals(masId)))
            return null;
        String what = InputLimits.abbreviate(performative, 100) + " from " + InputLimits.abbreviate(sender, 100) + " ("
                + InputLimits.abbreviate(senderMas, 100) + ") to "
                + (receiver.isEmpty() ? "everyone" : InputLimits.abbreviate(receiver, 100));
        if (senderMas.isEmpty() || !sender.matches(NAME_PATTERN)) {
            dropped("dropped message " + what + ": sender and sender_mas must be set, and the sender a Jason atom");
            return null;
        }
        if (!performative.matches(NAME_PATTERN)) {
            dropped("dropped message " + what + ": performative '" + InputLimits.abbreviate(performative, 100)
                    + "' is not a Jason atom");
            return null;
        }
        Term term;
        try {
            term = Messages.parseContent(content);
        } catch (IllegalArgumentException e) {
            dropped("dropped message " + what + ": " + e.getMessage());
            return null;
        }
        PresenceTable.Changes c;
        synchronized (presence) {
            c = presence.messageFrom(senderMas, sender, System.nanoTime());
        }
        apply(c);
        if (hostsSender)
            warned.warn("sender:" + sender, "message from " + sender + " of " + senderMas + ", a name this process also hosts:"
                    + " replies to it stay here; give one of the robots an ~agent_prefix");
        return new Incoming(what, term);
    }

    /** Logs a message for an agent this process does not host, once per name. */
    public void noSuchReceiver(String name, String what) {
        if (warned.firstTime("receiver:" + name))
            dropped("dropped message " + what + ": no agent '" + InputLimits.abbreviate(name, 100)
                    + "' here (logged once per name)");
    }

    /** Kind of the rate-limited lines of dropped messages. */
    public static final String DROPPED_MESSAGE = "dropped message";

    private void dropped(String line) {
        limited.warn(DROPPED_MESSAGE, line, System.nanoTime());
    }

    /** "/robot1" for "/robot1/rason_mas", "" for "/rason_mas". */
    static String namespaceOf(String masId) {
        int slash = masId.lastIndexOf('/');
        return slash <= 0 ? "" : masId.substring(0, slash);
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
