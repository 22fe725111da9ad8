package rason.perception;

import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import java.util.Set;

import jason.asSyntax.ASSyntax;
import jason.asSyntax.Atom;
import jason.asSyntax.Literal;

/**
 * One agent's perception from ROS: each source's literals kept by the agent's
 * {@link PerceptionManager} (behind its selection, thesis §5.5), and the present/1
 * literals of the agents it can reach. ROS threads update it and wake the agent;
 * the agent's thread reads it in {@code perceive()}.
 */
public final class AgentPerception {

    private final Runnable wake;
    private volatile PerceptionManager manager;
    private volatile List<Literal> presence = List.of();
    private volatile boolean presenceChanged = false;

    AgentPerception(PerceptionManager manager, Runnable wake) {
        this.manager = manager;
        this.wake = wake;
    }

    /** A source's current literals (from a ROS thread). */
    void update(String source, List<Literal> literals, long nowNanos) {
        if (manager.update(source, literals, nowNanos))
            wake.run();
    }

    /** Periodic, with the ROS time: sources silent for longer than ttl are dropped. */
    void expire(long nowNanos, long ttlNanos) {
        if (manager.expire(nowNanos, ttlNanos))
            wake.run();
    }

    /** The reachable agents changed: they become present(Name) percepts. */
    public void presenceUpdate(List<String> names) {
        List<Literal> literals = new ArrayList<>(names.size());
        for (String n : names)
            literals.add(ASSyntax.createLiteral("present", new Atom(n)));
        presence = literals;
        presenceChanged = true;
        wake.run();
    }

    /** Selective perception from now on (null: everything); see {@code rason.perceive_only}. */
    public void perceiveOnly(Set<String> selection) {
        PerceptionManager m = manager;
        if (m instanceof SelectivePerception sel)
            sel.select(selection);
        else
            manager = new SelectivePerception(m, selection);
        wake.run();
    }

    /**
     * What the agent perceives this cycle, on its thread: null when neither the
     * environment's percepts nor ROS's nor presence changed (Jason then skips its
     * belief update), else the whole list.
     */
    public Collection<Literal> perceive(Collection<Literal> fromEnvironment) {
        PerceptionManager m = manager;
        Collection<Literal> fromRos = m.perceive();
        boolean presenceNews = presenceChanged;
        presenceChanged = false;
        if (fromEnvironment == null && fromRos == null && !presenceNews)
            return null;
        List<Literal> all = new ArrayList<>();
        if (fromEnvironment != null)
            all.addAll(fromEnvironment);
        all.addAll(fromRos != null ? fromRos : m.current());
        for (Literal l : presence)
            if (m.wants(l))
                all.add(l);
        return all;
    }

    @Override
    public String toString() {
        return manager.toString();
    }
}
