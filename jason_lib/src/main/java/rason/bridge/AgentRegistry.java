package rason.bridge;

import java.util.Collection;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.concurrent.ConcurrentHashMap;

import jason.infra.local.BaseLocalMAS;
import jason.infra.local.LocalAgArch;

import rason.RosAgArch;

/** The agents this JVM hosts, by name, and how a receiver name resolves to one of them. */
public final class AgentRegistry {

    private final Map<String, RosAgArch> agents = new ConcurrentHashMap<>();
    private volatile String agentPrefix = "";

    void add(RosAgArch arch) {
        agents.put(arch.getAgName(), arch);
    }

    boolean remove(RosAgArch arch) {
        return agents.remove(arch.getAgName(), arch);
    }

    public RosAgArch get(String name) {
        return agents.get(name);
    }

    public boolean hosts(String name) {
        return agents.containsKey(name);
    }

    /** The hosted agents' architectures (live view). */
    public Collection<RosAgArch> all() {
        return agents.values();
    }

    /** Names of the hosted agents, live (the log handler tags lines with them). */
    public Set<String> names() {
        return agents.keySet();
    }

    public String[] sortedNames() {
        return new TreeSet<>(agents.keySet()).toArray(new String[0]);
    }

    /** Set before the agents are created: every agent of the project is named prefix+name. */
    public void setAgentPrefix(String prefix) {
        agentPrefix = prefix == null ? "" : prefix;
    }

    /** name as this robot names its agents (with its prefix): agents made by .create_agent too. */
    public String prefixed(String name) {
        return agentPrefix + name;
    }

    /** The hosted agent called name, or prefix+name (so a program reaches its own robot's agents by their short names); null if neither. */
    public String localNameFor(String name) {
        Map<String, LocalAgArch> jason = jasonAgents();
        if (jason.containsKey(name) || agents.containsKey(name))
            return name;
        String prefixed = agentPrefix + name;
        if (!agentPrefix.isEmpty() && (jason.containsKey(prefixed) || agents.containsKey(prefixed)))
            return prefixed;
        return null;
    }

    /** Every agent of this JVM, as Jason's local infrastructure knows them. */
    public static Map<String, LocalAgArch> jasonAgents() {
        BaseLocalMAS runner = BaseLocalMAS.getRunner();
        return runner == null ? Map.of() : runner.getAgs();
    }
}
