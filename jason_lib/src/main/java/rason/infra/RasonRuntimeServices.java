package rason.infra;

import java.util.Collection;
import java.util.List;

import jason.JasonException;
import jason.asSemantics.Agent;
import jason.asSyntax.ASSyntax;
import jason.infra.local.BaseLocalMAS;
import jason.infra.local.LocalRuntimeServices;
import jason.mas2j.ClassParameters;
import jason.runtime.Settings;


/**
 * Jason's local runtime services, with agents of other rason_mas processes in
 * view: {@code .all_names} lists the reachable ones, {@code .create_agent}
 * never picks a name another robot uses (and names the agent as the robot's
 * project agents are named, with its ~agent_prefix), and {@code .kill_agent}
 * of an agent of another robot fails saying so instead of failing silently.
 */
public class RasonRuntimeServices extends LocalRuntimeServices implements rason.AgentHost.Provider {

    /** error(...) of a .kill_agent whose agent runs on another robot, or nowhere. */
    public static final String KILL_REMOTE = "remote_agent";
    public static final String KILL_UNKNOWN = "agent_not_found";

    private final MasHost host;

    public RasonRuntimeServices(BaseLocalMAS masRunner, MasHost host) {
        super(masRunner);
        this.host = host;
    }

    /** Where the agents these services serve find their ports. */
    @Override
    public MasHost agentHost() {
        return host;
    }

    @Override
    public Collection<String> getAgentsNames() {
        return host.fleet().names().allNames();
    }

    @Override
    public int getAgentsQty() {
        return getAgentsNames().size();
    }

    /**
     * .create_agent: the agent is named like the project's agents (prefix+name), its
     * source is found as an include is (the creator's directory, the project's, its
     * source paths; never the working directory), and it is announced to the other
     * robots at once.
     *
     * @throws JasonException if the source is found nowhere (the message lists the paths tried)
     */
    @Override
    public String createAgent(String agName, String agSource, String agClass, List<String> archClasses,
            ClassParameters bbPars, Settings stts, Agent father) throws Exception {
        String source = agSource;
        if (source != null && !source.isBlank() && RasonLocalMAS.hasProjectInclude()) {
            String creatorSource = father == null ? null : father.getASLSrc();
            String name = source.startsWith("file:") ? source.substring("file:".length()) : source;
            ProjectInclude.Resolution found = RasonLocalMAS.projectInclude().resolve(name, creatorSource);
            if (found.found() == null)
                throw new JasonException("cannot create agent " + agName + ": source '" + agSource
                        + "' not found; tried " + found.tried(), ASSyntax.createAtom("source_not_found"));
            source = found.found();
        }
        return super.createAgent(freeName(host.fleet().names().prefixed(agName)), source, agClass, archClasses,
                bbPars, stts, father);
    }

    /**
     * As Jason names a new agent (name, name_1, name_2, ...), but a name an agent of another robot
     * has is taken too. Only for .create_agent: the project's own agents keep their names (a clash
     * with another robot is logged, see the naming rule).
     */
    private String freeName(String baseName) {
        Collection<String> taken = host.fleet().names().allNames();
        String name = baseName;
        for (int n = 1; taken.contains(name) || masRunner.getAg(name) != null; n++)
            name = baseName + "_" + n;
        return name;
    }

    /**
     * .kill_agent: an agent of this process (by its name, or this robot's prefix and
     * its name, as .send finds it) stops, and the other robots hear of its departure at
     * once. Any other name fails the intention with error(remote_agent) or
     * error(agent_not_found) and an error_msg saying why: a robot only stops its own agents.
     */
    @Override
    public boolean killAgent(String agName, String byAg, int deadline) {
        String local = host.fleet().names().localNameFor(agName);
        if (local != null)
            return super.killAgent(local, byAg, deadline);
        String mas = host.fleet().fleet().sendableMasOf(agName);
        JasonException why = mas != null
                ? new JasonException("cannot kill agent " + agName + ": it runs on " + mas
                        + ", and .kill_agent stops agents of this robot only", ASSyntax.createAtom(KILL_REMOTE))
                : new JasonException("cannot kill agent " + agName + ": " + host.fleet().fleet().whyUnreachable(agName),
                        ASSyntax.createAtom(KILL_UNKNOWN));
        // RuntimeServices.killAgent declares no exception; Jason fails the intention with the
        // error annotations of a JasonException thrown from an internal action, so it goes through
        throw Unchecked.<RuntimeException>as(why);
    }

    /** Lets a checked exception pass a method that declares none (the caller catches it). */
    private static final class Unchecked {
        @SuppressWarnings("unchecked")
        static <E extends Throwable> E as(Throwable t) throws E {
            throw (E) t;
        }
    }
}
