package rason.messaging;

import java.util.ArrayList;
import java.util.Collection;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;
import java.util.function.BiConsumer;
import java.util.function.Consumer;
import java.util.function.Function;

/**
 * Jason's directory facilitator (.df_register, .df_deregister, .df_search,
 * .df_subscribe) over the whole fleet: the registrations of the agents hosted
 * here, and those every other process announces with its presence. A remote
 * registration counts while a message to its agent would go to the process
 * that announced it (so a process that left, timed out or lost a name clash
 * takes its registrations with it). Subscribers are told of every provider
 * of their service that appears or goes, as {@link Notice}s handed to the sink
 * in order, under this object's lock (the sink only queues them for the agents).
 * <p>
 * Services are compared by name only, as Jason's local DF does (the type of
 * .df_register/2 is not kept).
 */
public final class FleetDirectory {

    /** Agent provides service. */
    public record Entry(String agent, String service) implements Comparable<Entry> {
        @Override
        public int compareTo(Entry o) {
            int c = service.compareTo(o.service);
            return c != 0 ? c : agent.compareTo(o.agent);
        }
    }

    /** Subscriber must hear that provider now provides service (added) or no longer does. */
    public record Notice(String subscriber, boolean added, String provider, String service) {
    }

    /** Our registrations as a presence announces them: two parallel arrays. */
    public record Announced(String[] agents, String[] services) {
    }

    /** At most this many registrations are taken from one process's announcement. */
    public static final int MAX_REMOTE_ENTRIES = 1000;
    /** A longer service name in an announcement is ignored. */
    public static final int MAX_SERVICE_LENGTH = 256;

    private final Function<String, String> ownerOf;
    private final Consumer<List<Notice>> sink;
    private final Set<Entry> local = new TreeSet<>();
    private final Map<String, Set<Entry>> remote = new HashMap<>(); // process -> what it announces
    private final Set<Entry> subscriptions = new TreeSet<>(); // agent = the subscriber
    private Set<Entry> view = new TreeSet<>(); // what counts now, and what subscribers were told

    /**
     * @param ownerOf the process a message to a remote agent would go to (null if none)
     * @param sink    receives the notices of each change, in order
     */
    public FleetDirectory(Function<String, String> ownerOf, Consumer<List<Notice>> sink) {
        this.ownerOf = ownerOf;
        this.sink = sink;
    }

    // ---- the agents hosted here ----------------------------------------------------------

    /** @return whether our registrations changed (then the process announces them at once) */
    public synchronized boolean register(String agent, String service) {
        boolean changed = local.add(new Entry(agent, service));
        refresh();
        return changed;
    }

    /** @return whether our registrations changed */
    public synchronized boolean deregister(String agent, String service) {
        boolean changed = local.remove(new Entry(agent, service));
        refresh();
        return changed;
    }

    /** A hosted agent stopped: its registrations and subscriptions go. @return whether our registrations changed */
    public synchronized boolean agentGone(String agent) {
        boolean changed = local.removeIf(e -> e.agent().equals(agent));
        subscriptions.removeIf(e -> e.agent().equals(agent));
        refresh();
        return changed;
    }

    /** Agent hears of every provider of service from now on, starting with the present ones (as in Jason). */
    public synchronized void subscribe(String agent, String service) {
        subscriptions.add(new Entry(agent, service));
        List<Notice> notices = new ArrayList<>();
        for (Entry e : view)
            if (e.service().equals(service))
                notices.add(new Notice(agent, true, e.agent(), service));
        if (!notices.isEmpty())
            sink.accept(notices);
    }

    /** Our registrations, sorted, for our presence announcement. */
    public synchronized Announced announced() {
        List<String> agents = new ArrayList<>(local.size()), services = new ArrayList<>(local.size());
        for (Entry e : local) {
            agents.add(e.agent());
            services.add(e.service());
        }
        return new Announced(agents.toArray(new String[0]), services.toArray(new String[0]));
    }

    // ---- other processes -------------------------------------------------------------------

    /** Process mas announced these registrations (they replace what it announced before). */
    public synchronized void remote(String mas, Collection<Entry> entries) {
        if (entries.isEmpty() && !remote.containsKey(mas))
            return;
        if (entries.isEmpty())
            remote.remove(mas);
        else
            remote.put(mas, Set.copyOf(entries));
        refresh();
    }

    /** These processes left, and who owns which name may have changed. */
    public synchronized void fleetChanged(Collection<String> departed) {
        for (String mas : departed)
            remote.remove(mas);
        refresh();
    }

    /**
     * The registrations of an announcement that can be taken: for an agent the announcement
     * lists, a service of 1 to {@link #MAX_SERVICE_LENGTH} characters, at most
     * {@link #MAX_REMOTE_ENTRIES}; each one left out is reported (entry text, why).
     */
    public static List<Entry> valid(Collection<String> announcedAgents, String[] agents, String[] services,
            BiConsumer<String, String> ignored) {
        List<Entry> out = new ArrayList<>();
        if (agents.length != services.length) {
            ignored.accept(agents.length + " agents and " + services.length + " services",
                    "df_agents and df_services must be as long as each other");
            return out;
        }
        for (int i = 0; i < agents.length; i++) {
            String a = agents[i], s = services[i];
            if (out.size() >= MAX_REMOTE_ENTRIES) {
                ignored.accept((agents.length - i) + " more", "more than " + MAX_REMOTE_ENTRIES + " registrations");
                break;
            }
            if (a == null || !announcedAgents.contains(a))
                ignored.accept(a + " provides " + s, "the announcement does not list agent " + a);
            else if (s == null || s.isEmpty() || s.length() > MAX_SERVICE_LENGTH)
                ignored.accept(a + " provides a service", "a service name must have 1 to " + MAX_SERVICE_LENGTH
                        + " characters");
            else
                out.add(new Entry(a, s));
        }
        return out;
    }

    // ---- what the agents ask -----------------------------------------------------------------

    /** The providers of service, here and at every process that counts, sorted. */
    public synchronized List<String> search(String service) {
        List<String> out = new ArrayList<>();
        for (Entry e : view)
            if (e.service().equals(service))
                out.add(e.agent());
        return out;
    }

    /** Every provider and its services (Jason's getDF). */
    public synchronized Map<String, Set<String>> byAgent() {
        Map<String, Set<String>> out = new TreeMap<>();
        for (Entry e : view)
            out.computeIfAbsent(e.agent(), k -> new TreeSet<>()).add(e.service());
        return out;
    }

    /** Recomputes what counts and tells subscribers what appeared and what went. */
    private void refresh() {
        Set<Entry> next = new TreeSet<>(local);
        for (Map.Entry<String, Set<Entry>> r : remote.entrySet())
            for (Entry e : r.getValue())
                if (r.getKey().equals(ownerOf.apply(e.agent())))
                    next.add(e);
        List<Notice> notices = new ArrayList<>();
        for (Entry s : subscriptions) {
            for (Entry e : next)
                if (e.service().equals(s.service()) && !view.contains(e))
                    notices.add(new Notice(s.agent(), true, e.agent(), e.service()));
            for (Entry e : view)
                if (e.service().equals(s.service()) && !next.contains(e))
                    notices.add(new Notice(s.agent(), false, e.agent(), e.service()));
        }
        view = next;
        if (!notices.isEmpty())
            sink.accept(notices);
    }
}
