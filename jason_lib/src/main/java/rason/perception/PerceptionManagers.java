package rason.perception;

import java.util.Set;

import jason.runtime.Settings;

/**
 * Builds each agent's perception manager from its .mas2j options:
 * <pre>
 *   agents: helper [perception_manager=accumulate, perceive="robot/4, battery/1", perception_rate=5];
 * </pre>
 * <ul>
 * <li>{@code perception_manager}: {@code per_source} (default, thesis §5.2),
 * {@code accumulate} (thesis Table 5.1), or the quoted name of a class
 * implementing {@link PerceptionManager};</li>
 * <li>{@code perception_rate}: at most this many updates per second per source;</li>
 * <li>{@code perceive}: only these functor/arity pairs reach the agent.</li>
 * </ul>
 * The node's {@code ~perception_manager} sets the default strategy.
 */
public final class PerceptionManagers {

    public static final String MANAGER_OPTION = "perception_manager";
    public static final String RATE_OPTION = "perception_rate";
    public static final String PERCEIVE_OPTION = "perceive";

    public static final String PER_SOURCE = "per_source";
    public static final String ACCUMULATE = "accumulate";

    private PerceptionManagers() {
    }

    /**
     * A base strategy by name or class name.
     *
     * @throws IllegalArgumentException saying what is wrong with the name
     */
    public static PerceptionManager create(String spec) {
        String name = spec == null || spec.isBlank() ? PER_SOURCE : spec.strip();
        switch (name) {
        case PER_SOURCE:
            return new PerSourcePerception();
        case ACCUMULATE:
            return new AccumulatePerception();
        default:
            break;
        }
        Class<?> c;
        try {
            c = Class.forName(name);
        } catch (ClassNotFoundException | LinkageError e) {
            throw new IllegalArgumentException("perception manager '" + name + "' is neither " + PER_SOURCE + ", "
                    + ACCUMULATE + " nor a class on the class path");
        }
        if (!PerceptionManager.class.isAssignableFrom(c))
            throw new IllegalArgumentException("class " + name + " does not implement " + PerceptionManager.class.getName());
        try {
            return (PerceptionManager) c.getConstructor().newInstance();
        } catch (ReflectiveOperationException e) {
            throw new IllegalArgumentException("cannot create perception manager " + name
                    + " (it needs a public constructor without arguments): " + e);
        }
    }

    /**
     * The whole chain for one agent: selection, then rate limit, then the base strategy.
     * The selection layer is always there so {@code rason.perceive_only} can be used later.
     *
     * @param defaultManager used when the agent names no perception_manager
     * @throws IllegalArgumentException saying which option is wrong and why
     */
    public static SelectivePerception forAgent(String manager, String rate, String perceive, String defaultManager) {
        PerceptionManager m;
        try {
            m = create(manager != null ? manager : defaultManager);
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException(MANAGER_OPTION + ": " + e.getMessage());
        }
        if (rate != null) {
            double perSecond;
            try {
                perSecond = Double.parseDouble(rate.strip());
            } catch (NumberFormatException e) {
                throw new IllegalArgumentException(RATE_OPTION + ": '" + rate + "' is not a number of updates per second");
            }
            try {
                m = new RateLimitedPerception(m, perSecond);
            } catch (IllegalArgumentException e) {
                throw new IllegalArgumentException(RATE_OPTION + ": " + e.getMessage());
            }
        }
        Set<String> selection = null;
        if (perceive != null) {
            try {
                selection = SelectivePerception.parseSelection(perceive);
            } catch (IllegalArgumentException e) {
                throw new IllegalArgumentException(PERCEIVE_OPTION + ": " + e.getMessage());
            }
        }
        return new SelectivePerception(m, selection);
    }

    /** The chain for an agent from its settings (the .mas2j options). */
    public static SelectivePerception forAgent(Settings settings, String defaultManager) {
        return forAgent(settings.getUserParameter(MANAGER_OPTION), settings.getUserParameter(RATE_OPTION),
                settings.getUserParameter(PERCEIVE_OPTION), defaultManager);
    }
}
