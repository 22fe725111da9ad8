package rason.messaging;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.function.Supplier;

import jason.infra.local.LocalAgArch;

/**
 * How this process names agents: its hosted agents (with the robot's ~agent_prefix), the
 * other agents Jason's infrastructure runs here, and the reachable agents of other
 * processes; and how a receiver's name resolves to one of ours.
 */
public final class FleetNames {

    private final Set<String> hosted;
    private final Supplier<Map<String, LocalAgArch>> jasonAgents;
    private final Fleet fleet;
    private volatile String agentPrefix = "";

    /** @param hosted the hosted agents' names (a live view) */
    FleetNames(Set<String> hosted, Supplier<Map<String, LocalAgArch>> jasonAgents, Fleet fleet) {
        this.hosted = hosted;
        this.jasonAgents = jasonAgents;
        this.fleet = fleet;
    }

    /** Names of the hosted agents, sorted (presence announces them). */
    public String[] localAgents() {
        return new TreeSet<>(hosted).toArray(new String[0]);
    }

    public boolean hosts(String agent) {
        return hosted.contains(agent);
    }

    /** What .all_names answers: the hosted agents and every reachable agent of other processes, sorted. */
    public List<String> allNames() {
        Set<String> all = new TreeSet<>(hosted);
        // an agent being killed is still in Jason's table while its architecture leaves: it is gone
        for (Map.Entry<String, LocalAgArch> agent : jasonAgents.get().entrySet())
            if (agent.getValue().isRunning())
                all.add(agent.getKey());
        all.addAll(fleet.reachable());
        return new ArrayList<>(all);
    }

    /** Set before the agents are created: every agent of the project is named prefix+name. */
    public void setAgentPrefix(String prefix) {
        agentPrefix = prefix == null ? "" : prefix;
    }

    /** name as this robot names its agents (with its prefix): agents made by .create_agent too. */
    public String prefixed(String name) {
        return agentPrefix + name;
    }

    /**
     * The hosted agent called name, or prefix+name (so a program reaches its own robot's
     * agents by their short names); null if neither.
     */
    public String localNameFor(String name) {
        Map<String, LocalAgArch> jason = jasonAgents.get();
        if (jason.containsKey(name) || hosted.contains(name))
            return name;
        String p = agentPrefix + name;
        if (!agentPrefix.isEmpty() && (jason.containsKey(p) || hosted.contains(p)))
            return p;
        return null;
    }
}
