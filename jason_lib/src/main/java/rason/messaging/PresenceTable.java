package rason.messaging;

import java.util.ArrayList;
import java.util.Collection;
import java.util.HashMap;
import java.util.HashSet;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;

/**
 * Which agents of other rason_mas processes ("peers") can be reached, from
 * their presence announcements and the messages they send. Pure bookkeeping:
 * time is passed in and nothing is logged here; {@link Fleet} owns the one
 * instance and calls it under its lock.
 * <p>
 * An agent is <em>reachable</em> when its peer was heard within the timeout,
 * our message publisher is linked to that peer (heard is not connected), and
 * no earlier claimer holds its name. Name clashes are reported once each.
 */
public final class PresenceTable {

    /** What one call changed. */
    public static final class Changes {
        /** agents that became reachable */
        public final List<String> joined = new ArrayList<>();
        /** agents that are no longer reachable */
        public final List<String> left = new ArrayList<>();
        /** agents whose process ended (left, or restarted): their pending answers will never come */
        public final Set<String> lost = new TreeSet<>();
        /** one line per peer that joined, left or restarted */
        public final List<String> events = new ArrayList<>();
        /** one line per name clash, the first time it is seen */
        public final List<String> clashes = new ArrayList<>();
        /** agents hosted here that another process announces too, with that process's incarnation */
        public final List<LocalClash> localClashes = new ArrayList<>();
        /** processes that left (or were declared gone) */
        public final List<String> departed = new ArrayList<>();
        /** the announcement was of an earlier run of its process, and ignored */
        public boolean stale = false;

        public boolean reachabilityChanged() {
            return !joined.isEmpty() || !left.isEmpty();
        }

        public boolean isEmpty() {
            return joined.isEmpty() && left.isEmpty() && lost.isEmpty() && events.isEmpty() && clashes.isEmpty()
                    && localClashes.isEmpty() && departed.isEmpty();
        }
    }

    /** An agent hosted here that another process (of incarnation, 0 if unknown) announces too. */
    public record LocalClash(String agent, String masId, long incarnation) {
    }

    private static final class Peer {
        final String masId;
        final long order; // first heard: the earlier claimer of a name keeps it
        long incarnation; // 0 = not announced yet (known from a message only)
        final Set<String> agents = new LinkedHashSet<>();
        long heardNanos;
        long pulseNanos;
        boolean pulsing; // heard over a second connection (see pulse)
        boolean ended; // its other connection ended while its pulse was heard: it goes when the pulse stops
        boolean linked;
        boolean everLinked; // a link that went down means the process is gone or cut off

        Peer(String masId, long order) {
            this.masId = masId;
            this.order = order;
        }
    }

    private final Map<String, Peer> peers = new LinkedHashMap<>();
    // peers gone silent (or whose connection ended) that may come back with what was sent to them meanwhile
    private final Map<String, Peer> away = new LinkedHashMap<>();
    private long awayHoldNanos = 0;
    private long pulseGraceNanos = 0;
    private Map<String, String> owners = new HashMap<>(); // agent -> masId
    private final Map<String, String> departed = new HashMap<>(); // agent -> why it is gone
    private final Set<String> reportedClashes = new HashSet<>();
    private Set<String> local = Set.of();
    private long nextOrder = 0;

    /** The agents this process hosts: a peer claiming one of them is a clash. */
    public Changes setLocal(Collection<String> names) {
        Set<String> before = reachable();
        local = Set.copyOf(names);
        Changes c = new Changes();
        recompute(before, c);
        return c;
    }

    /**
     * How long a peer that went silent (or whose connection ended) stays a place to send
     * to: its messages wait (in its broker session, or on the link) and their receipts say
     * whether they got there. 0: not at all (the peer is gone when it is silent).
     */
    public void setAwayHoldNanos(long t) {
        awayHoldNanos = Math.max(0, t);
    }

    /**
     * How recent a peer's pulse must be for the end of its other connection not to count at once
     * (see {@link #connectionEnded}): the peer stays while pulses come at most this far apart.
     */
    public void setPulseGraceNanos(long t) {
        pulseGraceNanos = Math.max(0, t);
    }

    /**
     * A presence announcement.
     *
     * @param incarnation the peer's start time; an older one than known is stale and ignored
     */
    public Changes announced(String masId, long incarnation, Collection<String> agents, boolean leaving, long nowNanos) {
        Set<String> before = reachable();
        Changes c = new Changes();
        Peer p = peers.get(masId);
        if (p != null && p.incarnation != 0 && incarnation != 0 && incarnation < p.incarnation) {
            c.stale = true; // a late announcement of an earlier run
            return c;
        }
        Peer wasAway = away.remove(masId);
        if (wasAway != null && (leaving || wasAway.incarnation != incarnation))
            c.lost.addAll(wasAway.agents); // it left for good, or restarted: nothing sent meanwhile will arrive
        if (leaving) {
            if (p != null && (p.incarnation == 0 || p.incarnation == incarnation)) {
                drop(p, "announced it is leaving", c);
                recompute(before, c);
            }
            return c;
        }
        if (p != null && p.incarnation != 0 && incarnation != p.incarnation) {
            // restarted faster than the timeout: whatever the old run owed is lost
            c.lost.addAll(p.agents);
            c.events.add(masId + " restarted");
            p.agents.clear();
            p.pulsing = false;
        }
        if (p == null) {
            p = new Peer(masId, nextOrder++);
            peers.put(masId, p);
            c.events.add(masId + " joined with " + agents);
        }
        p.incarnation = incarnation;
        p.heardNanos = nowNanos;
        p.ended = false; // announced over a new connection
        p.agents.clear();
        p.agents.addAll(agents);
        recompute(before, c);
        return c;
    }

    /** A message from agent of masId arrived: that proves the peer is there, announced or not. */
    public Changes messageFrom(String masId, String agent, long nowNanos) {
        Changes c = new Changes();
        Peer p = peers.get(masId);
        if (p != null && p.agents.contains(agent)) { // the usual case: nothing changes but the time
            p.heardNanos = nowNanos;
            return c;
        }
        Set<String> before = reachable();
        if (p == null && away.containsKey(masId)) {
            // back before its announcement (a broker's queue flushed first after a cut): the
            // peer that went away, with its run's incarnation, so that what was sent to it
            // stays owed if it goes silent again
            p = away.remove(masId);
            peers.put(masId, p);
            c.events.add(masId + " is back (a message from " + agent + " is heard)");
        } else if (p == null) {
            p = new Peer(masId, nextOrder++);
            peers.put(masId, p);
            c.events.add(masId + " heard from (message from " + agent + ") before its announcement");
        }
        p.heardNanos = nowNanos;
        p.agents.add(agent);
        recompute(before, c);
        return c;
    }

    /**
     * A pulse of masId's run incarnation arrived, over a connection apart from the one carrying its
     * messages and presence: a present peer is heard; one that went away (silent, or its other
     * connection ended) is back with what it announced, since its process is alive.
     */
    public Changes pulse(String masId, long incarnation, long nowNanos) {
        Changes c = new Changes();
        Peer p = peers.get(masId);
        if (p == null) {
            p = away.get(masId);
            if (p == null || p.incarnation != incarnation)
                return c; // unknown (its presence will introduce it), or an earlier run's pulse
            Set<String> before = reachable();
            away.remove(masId);
            peers.put(masId, p);
            c.events.add(masId + " is back (its pulse is heard)");
            recompute(before, c);
        } else if (p.incarnation != incarnation)
            return c;
        p.heardNanos = nowNanos;
        p.pulseNanos = nowNanos;
        p.pulsing = true;
        return c;
    }

    /**
     * Periodic update: which peers our message publisher is linked to, and
     * which peers have been silent for longer than timeoutNanos.
     */
    public Changes tick(Collection<String> linkedMas, long nowNanos, long timeoutNanos) {
        Set<String> before = reachable();
        Changes c = new Changes();
        Set<String> links = new HashSet<>(linkedMas);
        for (Peer p : new ArrayList<>(peers.values())) {
            if (p.ended && nowNanos - p.pulseNanos > pulseGraceNanos)
                goAway(p, "its connection ended and its pulse stopped", nowNanos, c);
            else if (nowNanos - p.heardNanos > timeoutNanos)
                goAway(p, String.format(java.util.Locale.ROOT, "not heard for %.1f s", (nowNanos - p.heardNanos) / 1e9),
                        nowNanos, c);
            else {
                p.linked = links.contains(p.masId);
                p.everLinked |= p.linked;
            }
        }
        for (Iterator<Peer> it = away.values().iterator(); it.hasNext();) {
            Peer a = it.next();
            if (nowNanos - a.heardNanos > awayHoldNanos) {
                it.remove();
                c.lost.addAll(a.agents);
            }
        }
        recompute(before, c);
        return c;
    }

    /** The connection of peer masId (of incarnation) ended without its leaving: it is gone, and may come back. */
    public Changes connectionEnded(String masId, long incarnation, long nowNanos) {
        Set<String> before = reachable();
        Changes c = new Changes();
        Peer p = peers.get(masId);
        if (p != null && p.pulsing && p.incarnation == incarnation && nowNanos - p.pulseNanos <= pulseGraceNanos) {
            p.ended = true; // a stall, if its pulse goes on; its death, if not (see tick)
            c.events.add(masId + "'s connection ended while its pulse is heard: it stays while the pulse goes on");
            return c;
        }
        if (p != null && (p.incarnation == 0 || p.incarnation == incarnation)) {
            goAway(p, "its connection ended", nowNanos, c);
            recompute(before, c);
        }
        return c;
    }

    /** The process of a reachable remote agent, else null. */
    public String masOf(String agent) {
        String mas = owners.get(agent);
        if (mas == null)
            return null;
        Peer p = peers.get(mas);
        return p != null && p.linked ? mas : null;
    }

    /**
     * Where a message to agent can go: its process if reachable, or if just
     * heard of and not linked yet (the message then waits for the link);
     * null if unknown, gone, or its link went down.
     */
    public String sendableMasOf(String agent) {
        String mas = owners.get(agent);
        if (mas == null) {
            for (Peer a : away.values())
                if (a.agents.contains(agent) && !local.contains(agent))
                    return a.masId;
            return null;
        }
        Peer p = peers.get(mas);
        return p != null && (p.linked || !p.everLinked) ? mas : null;
    }

    /** Names of the reachable remote agents, sorted. */
    public Set<String> reachable() {
        Set<String> out = new TreeSet<>();
        for (Map.Entry<String, String> e : owners.entrySet()) {
            Peer p = peers.get(e.getValue());
            if (p != null && p.linked)
                out.add(e.getKey());
        }
        return out;
    }

    /** Why agent cannot be reached, for the failure of a send. */
    public String whyUnreachable(String agent) {
        String mas = owners.get(agent);
        if (mas != null)
            return "agent '" + agent + "' of " + mas + " is known but the connection to its process is down";
        String gone = departed.get(agent);
        if (gone != null)
            return "agent '" + agent + "' has left (" + gone + ")";
        return "no agent '" + agent + "' is present (neither in this process nor announced by another)";
    }

    /** The incarnation peer masId last announced; 0 if it has not announced itself (unknown, or known from messages only). */
    public long announcedIncarnation(String masId) {
        Peer p = peers.get(masId);
        return p == null ? 0 : p.incarnation;
    }

    /** Whether masId's current announcement lists agent. */
    public boolean announces(String masId, String agent) {
        Peer p = peers.get(masId);
        return p != null && p.incarnation != 0 && p.agents.contains(agent);
    }

    /** The agents peer masId is known to host (empty if unknown). */
    public List<String> agentsOf(String masId) {
        Peer p = peers.get(masId);
        return p == null ? List.of() : new ArrayList<>(p.agents);
    }

    /** How many other processes can be reached now. */
    public int linkedPeers() {
        int n = 0;
        for (Peer p : peers.values())
            if (p.linked)
                n++;
        return n;
    }

    /** Ids of the peers currently known (for tests and diagnostics). */
    public List<String> peerIds() {
        return new ArrayList<>(peers.keySet());
    }

    /** Like {@link #drop}, but what was sent to p stays owed for awayHoldNanos: p may come back. */
    private void goAway(Peer p, String why, long nowNanos, Changes c) {
        if (awayHoldNanos <= 0 || p.incarnation == 0) {
            drop(p, why, c);
            return;
        }
        gone(p, why, c);
        p.heardNanos = nowNanos;
        away.put(p.masId, p);
    }

    private void drop(Peer p, String why, Changes c) {
        gone(p, why, c);
        c.lost.addAll(p.agents);
    }

    /** p leaves the table and present/1: what its agents owe is the caller's to decide. */
    private void gone(Peer p, String why, Changes c) {
        peers.remove(p.masId);
        c.departed.add(p.masId);
        c.events.add(p.masId + " left: " + why);
        for (String a : p.agents)
            departed.put(a, p.masId + " " + why);
    }

    /** Re-assigns names to claimers (earliest first) and reports what became (un)reachable. */
    private void recompute(Set<String> before, Changes c) {
        Map<String, String> next = new HashMap<>();
        List<Peer> byOrder = new ArrayList<>(peers.values());
        byOrder.sort((a, b) -> Long.compare(a.order, b.order));
        for (Peer p : byOrder) {
            for (String a : p.agents) {
                if (local.contains(a)) {
                    c.localClashes.add(new LocalClash(a, p.masId, p.incarnation));
                    clash(a, "agent name '" + a + "' is hosted here and also announced by " + p.masId
                            + ": messages to '" + a + "' from this process stay here; give one of the robots an ~agent_prefix", c);
                } else if (next.containsKey(a)) {
                    clash(a, "agent name '" + a + "' is announced by both " + next.get(a) + " and " + p.masId
                            + ": messages to '" + a + "' go to " + next.get(a) + "; give one of the robots an ~agent_prefix", c);
                } else {
                    next.put(a, p.masId);
                    departed.remove(a);
                }
            }
        }
        owners = next;
        Set<String> after = reachable();
        for (String a : after)
            if (!before.contains(a))
                c.joined.add(a);
        for (String a : before)
            if (!after.contains(a))
                c.left.add(a);
    }

    private void clash(String agent, String text, Changes c) {
        if (reportedClashes.add(agent + "\n" + text))
            c.clashes.add(text);
    }
}
