package rason.infra;

import java.io.File;
import java.io.FileInputStream;
import java.io.InputStream;
import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.logging.Handler;
import java.util.logging.Level;
import java.util.logging.Logger;

import jason.JasonException;
import jason.asSemantics.Agent;
import jason.asSyntax.NumberTermImpl;
import jason.asSyntax.PlanLibrary;
import jason.asSyntax.Trigger;
import jason.asSyntax.directives.DirectiveProcessor;
import jason.asSyntax.directives.Include;
import jason.infra.local.LocalAgArch;
import jason.infra.local.RunLocalMAS;
import jason.mas2j.AgentParameters;
import jason.runtime.RuntimeServicesFactory;

import rason.MindAgArch;
import rason.RosAgArch;
import rason.core.Clock;
import rason.messaging.Fleet;
import rason.messaging.TrustPolicy;
import rason.perception.PerceptionManagers;

/**
 * Jason's local infrastructure, headless and embedded: loads a .mas2j without
 * GUI, RMI or System.exit, gives every agent a {@link RosAgArch} (also when the
 * project names no architecture), prefixes the agents' names when the robot
 * has an agent prefix, makes {@code .all_names} see the agents of other
 * processes, and routes Jason's log to rosout.
 */
public class RasonLocalMAS extends RunLocalMAS {

    public static final String ARCH_CLASS = RosAgArch.class.getName();
    /** jason/mind's architecture, just before {@link #ARCH_CLASS} in every agent's chain. */
    public static final String MIND_ARCH_CLASS = MindAgArch.class.getName();

    private final MasHost host;
    private String agentPrefix = "";
    private final AtomicBoolean finishing = new AtomicBoolean(false); // a .stopMAS was made

    /** A MAS whose agents run in host (the one RuntimeServices of the process is this MAS's). */
    public RasonLocalMAS(MasHost host) {
        super();
        this.host = host;
        RasonRuntimeServices services = new RasonRuntimeServices(this, host);
        // agents made later with .create_agent too, in this order
        services.registerDefaultAgArch(MIND_ARCH_CLASS);
        services.registerDefaultAgArch(ARCH_CLASS);
        RuntimeServicesFactory.set(services);
    }

    /**
     * Names every agent of the project prefix+name (two robots running the same
     * program then host distinct names). Call before {@link #load}.
     *
     * @throws JasonException if the prefix cannot start a Jason atom
     */
    public void setAgentPrefix(String prefix) throws JasonException {
        String p = prefix == null ? "" : prefix.strip();
        if (!p.isEmpty() && !p.matches(Fleet.NAME_PATTERN))
            throw new JasonException("agent prefix '" + prefix + "' must start with a lower-case letter and hold only"
                    + " letters, digits and _ (agent names are Jason atoms), e.g. robot1_");
        agentPrefix = p;
        host.fleet().names().setAgentPrefix(p);
    }

    /**
     * Parses the project file and fixes its agents' sources relative to it.
     *
     * @throws Exception with a message saying what is wrong with the file
     */
    public void load(String mas2jPath) throws Exception {
        addInitArg("no-rmi", true);
        addInitArg("no-mbean", true);
        addInitArg("no-mindinspector", true);
        RasonConfig.install(); // before the parser: aslSourcePath's $jasonJar/... entries are resolved there
        setupLogger();
        if (RasonConfig.shortUnnamedVarsWanted() && !RasonConfig.shortUnnamedVarsApplied())
            Logger.getLogger(RasonLocalMAS.class.getName()).warning("Jason's terms were used before its configuration"
                    + " was installed (rason.infra.RasonConfig.install): unnamed variables print in the long form");

        File file = new File(mas2jPath).getCanonicalFile();
        if (!file.isFile())
            throw new JasonException("project file not found: " + mas2jPath);
        try (InputStream in = new FileInputStream(file)) {
            project = new jason.mas2j.parser.mas2j(in).mas();
        } catch (jason.mas2j.parser.ParseException | jason.mas2j.parser.TokenMgrError e) {
            throw new JasonException("cannot parse " + file + ": " + e.getMessage());
        }
        project.setProjectFile(file);
        project.setDirectory(file.getParent());
        project.setupDefault();
        ProjectCheck.checkProject(project);
        project.getSourcePaths().setRoot(file.getParent());
        project.registerDirectives();
        Include include = (Include) DirectiveProcessor.getDirective("include");
        include.setSourcePath(project.getSourcePaths());
        projectInclude().setProject(file.getParentFile(), projectSourcePaths());

        for (AgentParameters ap : project.getAgents()) {
            // .asl paths in a .mas2j are relative to the project file, not to the working directory
            String src = ap.getSource() == null ? ap.name + ".asl" : ap.getSource().toString();
            if (src.startsWith("file:"))
                src = src.substring("file:".length());
            // the project's directory, then its aslSourcePath (as Jason does, but never the working directory)
            ProjectInclude.Resolution asl = projectInclude().resolve(src, null);
            if (asl.found() == null)
                throw new JasonException("agent '" + ap.name + "': source file not found: "
                        + (asl.tried().size() == 1 ? asl.tried().get(0) : "tried " + asl.tried()));
            ap.setSource(asl.found());
            if (!ap.getAgArchClasses().contains(MIND_ARCH_CLASS))
                ap.addArchClass(MIND_ARCH_CLASS);
            if (!ap.getAgArchClasses().contains(ARCH_CLASS))
                ap.addArchClass(ARCH_CLASS);
            ProjectCheck.checkAgent(ap);
            try {
                // the same check RosAgArch.init makes, but fatal here: a typo must not go unnoticed
                PerceptionManagers.forAgent(ProjectCheck.unquote(ap.getOption(PerceptionManagers.MANAGER_OPTION)),
                        ProjectCheck.unquote(ap.getOption(PerceptionManagers.RATE_OPTION)),
                        ProjectCheck.unquote(ap.getOption(PerceptionManagers.PERCEIVE_OPTION)),
                        host.perception().defaultManager());
            } catch (IllegalArgumentException e) {
                throw new JasonException("agent '" + ap.name + "': " + e.getMessage());
            }
            ap.name = agentPrefix + ap.name;
            readTrustOptions(ap);
        }
        project.fixAgentsSrc();
    }

    /**
     * Creates the agents; Jason logs an agent it cannot create (say its .asl
     * does not parse) and goes on without it, but a robot missing one of its
     * agents must not start.
     *
     * @throws JasonException naming the agents that were not created
     */
    @Override
    public void create() throws JasonException {
        super.create();
        List<String> missing = new ArrayList<>();
        for (AgentParameters ap : project.getAgents())
            for (String name : instanceNames(ap))
                if (getAg(name) == null)
                    missing.add(name);
        if (!missing.isEmpty())
            throw new JasonException("agent" + (missing.size() > 1 ? "s " : " ") + String.join(", ", missing)
                    + " could not be created (Jason's error is above)");
        for (LocalAgArch ag : getAgs().values())
            ProjectCheck.checkInternalActions(ag.getAgName(), ag.getTS().getAg());
        // Jason runs an agent without a file it could not include: here the project does not start
        List<String> includes = projectInclude().failures();
        projectInclude().loaded();
        if (!includes.isEmpty())
            throw new JasonException(String.join("; ", includes));
    }

    static {
        // before any Jason term is made (Jason reads some of its settings once, then)
        RasonConfig.install();
        // before Jason makes its own include directive: the parser and .include then use this one
        DirectiveProcessor.registerDirective("include", ProjectInclude.class);
    }

    /**
     * The include directive every agent's parser and {@code .include} use.
     *
     * @throws JasonException if Jason made its own before this class was loaded
     */
    static ProjectInclude projectInclude() throws JasonException {
        if (DirectiveProcessor.getDirective("include") instanceof ProjectInclude p)
            return p;
        throw new JasonException("Jason's include directive was created before rason.infra.RasonLocalMAS was loaded:"
                + " includes would be resolved from the working directory");
    }

    /** Whether includes (and .create_agent's sources) are resolved from the project. */
    static boolean hasProjectInclude() {
        return DirectiveProcessor.getDirective("include") instanceof ProjectInclude;
    }

    /** The project's aslSourcePath entries as Jason keeps them (without the variants it adds under its root). */
    private static List<String> projectSourcePaths() {
        List<String> all = project.getSourcePaths().getPaths();
        String root = project.getSourcePaths().getRoot() + "/";
        List<String> out = new ArrayList<>();
        for (String p : all)
            if (!(p.startsWith(root) && all.contains(p.substring(root.length()))))
                out.add(p);
        return out;
    }

    /**
     * The agent's trust_&lt;group&gt; options: which agents of other robots it takes
     * which performatives from (see {@link TrustPolicy}).
     *
     * @throws JasonException for an unknown group or a rule that does not parse
     */
    private void readTrustOptions(AgentParameters ap) throws JasonException {
        Map<String, String> options = ap.getOptions();
        if (options == null)
            return;
        for (Map.Entry<String, String> o : options.entrySet()) {
            if (!o.getKey().startsWith(TrustPolicy.OPTION_PREFIX))
                continue;
            try {
                TrustPolicy.Group group = TrustPolicy.Group.byKey(o.getKey().substring(TrustPolicy.OPTION_PREFIX.length()));
                TrustPolicy.Rule rule = TrustPolicy.Rule.parse(o.getValue());
                for (String name : instanceNames(ap))
                    host.fleet().trust().setProgramRule(name, group, rule);
            } catch (IllegalArgumentException e) {
                throw new JasonException("agent '" + ap.name + "', option " + o.getKey() + ": " + e.getMessage());
            }
        }
    }

    /** The names Jason gives an agent's instances: bob, or bob1, bob2, ... for {@code bob #n}. */
    private static List<String> instanceNames(AgentParameters ap) {
        if (ap.getNbInstances() <= 1)
            return List.of(ap.name);
        List<String> names = new ArrayList<>();
        for (int i = 1; i <= ap.getNbInstances(); i++)
            names.add(ap.name + i);
        return names;
    }

    // ---- the directory facilitator: the fleet's (see rason.messaging.FleetDirectory), without a df agent ----
    // Jason's local DF is an agent called df, created on first use: it would be announced as
    // one of this robot's agents and clash with every other robot's df.

    @Override
    public void dfRegister(String agName, String service) {
        host.fleet().df().register(agName, service);
    }

    @Override
    public void dfDeRegister(String agName, String service) {
        host.fleet().df().deregister(agName, service);
    }

    @Override
    public Collection<String> dfSearch(String service) {
        return host.fleet().directory().search(service);
    }

    @Override
    public void dfSubscribe(String agName, String service) {
        host.fleet().directory().subscribe(agName, service);
    }

    @Override
    public Map<String, Set<String>> getDF() {
        return host.fleet().directory().byAgent();
    }

    @Override
    public LocalAgArch delAg(String agName) {
        host.fleet().df().agentGone(agName);
        return super.delAg(agName);
    }

    @Override
    public synchronized void setupLogger(String confFile) {
        Logger root = Logger.getLogger("");
        for (Handler h : root.getHandlers())
            root.removeHandler(h);
        root.addHandler(new RosLogHandler(host.log(), host.fleet().names()::hosts));
        root.setLevel(Level.INFO);
    }

    /**
     * .stopMAS: asks the rospy node to shut down (which stops the agents) instead of
     * System.exit. .stopMAS(T) first gives the agents T ms of their clock (ROS time,
     * as {@code .wait}), telling each {@code +jag_shutting_down(T)}, as Jason does.
     * As in Jason, the first .stopMAS decides: a later one is ignored.
     */
    @Override
    public void finish(int deadline, boolean stopJVM, int exitValue) {
        if (finishing.getAndSet(true))
            return;
        if (deadline <= 0) {
            requestStop(exitValue);
            return;
        }
        for (LocalAgArch ag : new ArrayList<>(getAgs().values())) {
            Trigger shuttingDown = PlanLibrary.TE_JAG_SHUTTING_DOWN.clone();
            shuttingDown.getLiteral().addTerm(new NumberTermImpl(deadline));
            ag.getTS().getC().addExternalEv(shuttingDown);
            ag.wakeUpSense();
        }
        Agent.getScheduler().schedule(() -> requestStop(exitValue), deadline, TimeUnit.MILLISECONDS);
    }

    private void requestStop(int exitValue) {
        if (!host.requestStop(exitValue))
            Logger.getLogger("rason.infra").warning(".stopMAS ignored: no rason_mas node runs this MAS");
    }

    /** The project's environment's stop(), as Jason's runner calls it when the MAS ends. */
    private void stopEnvironment() {
        if (env == null)
            return;
        try {
            env.stop();
        } catch (RuntimeException e) {
            Logger.getLogger("rason.infra").log(Level.WARNING, "the environment's stop() failed", e);
        }
    }

    /**
     * Stops every agent and waits for their threads.
     *
     * @return true if all agent threads ended within timeoutMillis
     */
    public boolean stopAgents(long timeoutMillis) throws InterruptedException {
        isRunning = false;
        List<LocalAgArch> all = new ArrayList<>(getAgs().values());
        for (LocalAgArch ag : all) {
            try {
                ag.stopAg();
            } catch (Exception e) {
                // keep stopping the others
            }
            delAg(ag.getAgName());
        }
        long deadline = Clock.WALL.nanos() / 1_000_000 + timeoutMillis;
        boolean allEnded = true;
        for (LocalAgArch ag : all) {
            Thread t = ag.getThread();
            if (t == null)
                continue;
            t.join(Math.max(1, deadline - Clock.WALL.nanos() / 1_000_000));
            allEnded &= !t.isAlive();
        }
        stopEnvironment();
        jason.architecture.MindInspectorWeb.stop(); // its port closes with the agents
        return allEnded;
    }
}
