package rason.infra;

import jason.asSyntax.Structure;
import jason.asSyntax.VarTerm;
import jason.util.Config;

/**
 * Jason's configuration, with Rason's web mind inspector in place of Jason's: the
 * {@code .mas2j} option {@code mindinspector="web(...)"} then serves on loopback, on a
 * free port of its own ({@link LoopbackMindInspector}).
 *
 * {@link #install} makes it Jason's configuration and completes it as Jason's runner
 * does: the user's {@code jason.properties} or {@code ~/.jason/user.properties}, then
 * Jason's defaults for what they leave unset ({@code jasonJar}, the jar Jason runs from,
 * so {@code $jasonJar/...} paths resolve; {@code shortUnnamedVars}; ...), and no web
 * mind inspector unless the {@code .mas2j} asks for one.
 */
public class RasonConfig extends Config {

    @Override
    public String getMindInspectorWebServerClassName() {
        return LoopbackMindInspector.class.getName();
    }

    /**
     * Jason's configuration from now on, completed with Jason's defaults. Call it
     * before any Jason term is made: Jason reads some settings (shortUnnamedVars)
     * once, when its term classes are first used.
     *
     * @return the configuration in use
     */
    public static synchronized Config install() {
        if (!(Config.get() instanceof RasonConfig))
            Config.setClassFactory(RasonConfig.class.getName()); // loads the user's files again, in this class
        Config config = Config.get();
        if (config.getJasonJar() == null) { // as RunLocalMAS.init: defaults only if the files did not say
            config.setShowFixMsgs(false);
            config.fix();
        }
        config.put(Config.START_WEB_MI, "false"); // as RunLocalMAS --no-mindinspector: only on the .mas2j's request
        return config;
    }

    /**
     * Whether variables Jason renames print short ({@code _44}), as the configuration
     * asks; false when Jason's terms were first used before {@link #install}.
     */
    public static boolean shortUnnamedVarsApplied() {
        Structure probe = new Structure("probe");
        probe.addTerm(new VarTerm("Named"));
        probe.makeVarsAnnon();
        return probe.getTerm(0).toString().matches("_[0-9]+");
    }

    /** Whether the configuration asks for short unnamed variables. */
    public static boolean shortUnnamedVarsWanted() {
        return Config.get().getBoolean(Config.SHORT_UNNAMED_VARS);
    }
}
