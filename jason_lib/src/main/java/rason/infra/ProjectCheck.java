package rason.infra;

import java.util.Set;
import java.util.TreeSet;

import jason.JasonException;
import jason.architecture.AgArch;
import jason.asSemantics.Agent;
import jason.asSyntax.Literal;
import jason.asSyntax.LiteralImpl;
import jason.asSyntax.Plan;
import jason.asSyntax.Rule;
import jason.asSyntax.Structure;
import jason.asSyntax.Term;
import jason.asSyntax.VarTerm;
import jason.bb.BeliefBase;
import jason.control.ExecutionControl;
import jason.control.ExecutionControlGUI;
import jason.environment.Environment;
import jason.mas2j.AgentParameters;
import jason.mas2j.ClassParameters;
import jason.mas2j.MAS2JProject;
import jason.runtime.Settings;

/**
 * What a project asks of Jason that rason_mas cannot give, found before any agent
 * runs: Jason logs a class it cannot load (or a GUI it cannot open) and runs on
 * without it, a robot must not. Every class the project names (agent, architecture,
 * belief base, environment, execution control) must load from the JVM's class path,
 * where the project's own classes are (rason_mas's {@code ~classpath}).
 */
public final class ProjectCheck {

    /** Where the message for a class not found sends the user. */
    static final String CLASS_PATH_HINT = "a typo, or its class is not on the class path: see rason_mas's ~classpath";

    private ProjectCheck() {
    }

    /**
     * The parts of the project that are not about one agent: its infrastructure, environment and execution control.
     *
     * @throws JasonException saying what is not supported, or which class is missing, and why
     */
    public static void checkProject(MAS2JProject project) throws JasonException {
        String infra = project.getInfrastructure().getClassName();
        if (!"Local".equals(infra))
            throw new JasonException("infrastructure " + infra + " is not supported: rason_mas runs Jason's Local"
                    + " infrastructure and reaches the agents of other processes through its fleet (remove the"
                    + " infrastructure line)");
        ClassParameters env = project.getEnvClass();
        if (env != null)
            checkClass("environment", env.getClassName(), Environment.class);
        ClassParameters control = project.getControlClass();
        if (control != null) {
            Class<?> c = checkClass("executionControl", control.getClassName(), ExecutionControl.class);
            if (ExecutionControlGUI.class.isAssignableFrom(c))
                throw new JasonException("executionControl " + control.getClassName() + " is a window, and rason_mas"
                        + " runs headless (no display on a robot)");
        }
    }

    /**
     * One agent's classes and options.
     *
     * @throws JasonException naming the agent and what is missing or not supported
     */
    public static void checkAgent(AgentParameters ap) throws JasonException {
        try {
            for (String arch : ap.getAgArchClasses())
                checkClass("agentArchClass", arch, AgArch.class);
            if (ap.agClass != null)
                checkClass("agentClass", ap.agClass.getClassName(), Agent.class);
            if (ap.getBBClass() != null)
                checkClass("beliefBaseClass", ap.getBBClass().getClassName(), BeliefBase.class);
        } catch (JasonException e) {
            throw new JasonException("agent '" + ap.name + "': " + e.getMessage());
        }
        String inspector = unquote(ap.getOption(Settings.MIND_INSPECTOR));
        if (inspector != null && (inspector.strip().equals("gui") || inspector.strip().startsWith("gui(")))
            throw new JasonException("agent '" + ap.name + "': " + Settings.MIND_INSPECTOR + "=\"" + inspector.strip()
                    + "\" is a window, and rason_mas runs headless (no display on a robot): use web(...), served on"
                    + " loopback, or file(...)");
    }

    /**
     * Jason parses an internal action whose class it cannot load ({@code mylib.twice(X, Y)}) as
     * an action, with a warning: the agent would send it to ROS. Found in its plans and rules,
     * such a step stops the node.
     *
     * @throws JasonException naming the agent and the internal actions not found
     */
    public static void checkInternalActions(String agName, Agent ag) throws JasonException {
        Set<String> missing = new TreeSet<>();
        for (Plan p : ag.getPL()) {
            if (p.getContext() != null)
                collectUnloaded(p.getContext(), ag, missing);
            if (p.getBody() != null)
                collectUnloaded(p.getBody(), ag, missing);
        }
        for (Literal b : ag.getBB())
            if (b.isRule())
                collectUnloaded(((Rule) b).getBody(), ag, missing);
        if (!missing.isEmpty())
            throw new JasonException("agent '" + agName + "': internal action" + (missing.size() > 1 ? "s " : " ")
                    + String.join(", ", missing) + " not found (" + CLASS_PATH_HINT + ")");
    }

    /** The dotted literals of t that are neither internal actions nor arithmetic functions. */
    private static void collectUnloaded(Term t, Agent ag, Set<String> missing) {
        if (t instanceof LiteralImpl l && !(t instanceof VarTerm) && l.getFunctor().contains(".")
                && ag.getFunction(l.getFunctor(), l.getArity()) == null)
            missing.add(l.getFunctor());
        if (t instanceof Structure s && !(t instanceof VarTerm))
            for (int i = 0; i < s.getArity(); i++) // by index: lists and plans (as terms) keep no term list
                if (s.getTerm(i) != null)
                    collectUnloaded(s.getTerm(i), ag, missing);
    }

    /**
     * The class, loaded as Jason loads it (from Jason's own class loader, the class path).
     *
     * @throws JasonException when it cannot be loaded or is not a base
     */
    static Class<?> checkClass(String what, String name, Class<?> base) throws JasonException {
        Class<?> c;
        try {
            c = Class.forName(name, false, Agent.class.getClassLoader());
        } catch (ClassNotFoundException | LinkageError e) {
            throw new JasonException(what + " " + name + " not found (" + CLASS_PATH_HINT + ")");
        }
        if (!base.isAssignableFrom(c))
            throw new JasonException(what + " " + name + " is not a " + base.getName());
        return c;
    }

    static String unquote(String s) {
        return s != null && s.length() >= 2 && s.startsWith("\"") && s.endsWith("\"") ? s.substring(1, s.length() - 1) : s;
    }
}
