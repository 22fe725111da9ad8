package rason.messaging;

import java.util.Arrays;
import java.util.Collections;
import java.util.EnumMap;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.concurrent.ConcurrentHashMap;

import rason.core.InputLimits;

/**
 * Which agents of other processes may send what to the agents hosted here.
 * Messages between agents of one process are Jason's own business and are not
 * checked; a message from another robot is delivered only if the receiver's
 * rule for its performative names the sender (or is {@code all}).
 *
 * <p>Rules come from three places; for each agent and group the first that is
 * set wins: the {@code ~trust} parameter for that agent, the agent's
 * {@code trust_<group>} option in the .mas2j, the {@code ~trust} parameter for
 * every agent ({@code '*'}), the default. By default other robots may tell,
 * ask, have goals achieved and use performatives of the program's own, but not
 * change an agent's plans ({@code tellHow}, {@code untellHow}) or read them
 * ({@code askHow}). Thread-safe.
 */
public final class TrustPolicy {

    /** Performatives that share a rule. */
    public enum Group {
        TELL("tell", true, "tell", "untell", "signal"),
        ACHIEVE("achieve", true, "achieve", "unachieve"),
        ASK("ask", true, "askOne", "askAll"),
        ASK_HOW("askHow", false, "askHow"),
        TELL_HOW("tellHow", false, "tellHow", "untellHow"),
        /** Performatives Jason does not define, handled by the program's own +!kqml_received plans. */
        OTHER("other", true);

        /** Name in rules: trust_&lt;name&gt; in the .mas2j, the key under ~trust. */
        public final String key;
        final boolean allByDefault;
        final Set<String> performatives;

        Group(String key, boolean allByDefault, String... performatives) {
            this.key = key;
            this.allByDefault = allByDefault;
            this.performatives = Set.of(performatives);
        }

        /** The .mas2j option that sets this group's rule. */
        public String option() {
            return OPTION_PREFIX + key;
        }

        public static Group of(String performative) {
            for (Group g : values())
                if (g.performatives.contains(performative))
                    return g;
            return OTHER;
        }

        /** @throws IllegalArgumentException naming the groups there are */
        public static Group byKey(String key) {
            for (Group g : values())
                if (g.key.equals(key))
                    return g;
            throw new IllegalArgumentException("no performative group '" + key + "' (there are "
                    + Arrays.stream(values()).map(g -> g.key).toList() + ")");
        }
    }

    /** Prefix of the .mas2j agent options, e.g. {@code [trust_tellHow="faulty"]}. */
    public static final String OPTION_PREFIX = "trust_";
    /** The ~trust key of rules for every agent of the process. */
    public static final String EVERY_AGENT = "*";

    /** Who may: everybody, or the listed agent names (none when empty). */
    public record Rule(boolean all, Set<String> names) {

        public static final Rule ALL = new Rule(true, Set.of());
        public static final Rule NONE = new Rule(false, Set.of());

        public boolean allows(String sender) {
            return all || names.contains(sender);
        }

        /**
         * {@code all}, {@code none}, or agent names separated by commas or
         * spaces, optionally in brackets: {@code "[faulty, helper]"}.
         *
         * @throws IllegalArgumentException saying what is wrong
         */
        public static Rule parse(String spec) {
            String s = spec == null ? "" : spec.strip();
            if (s.length() >= 2 && s.startsWith("\"") && s.endsWith("\""))
                s = s.substring(1, s.length() - 1).strip();
            if (s.startsWith("[") && s.endsWith("]"))
                s = s.substring(1, s.length() - 1).strip();
            String word = s.toLowerCase(Locale.ROOT);
            if (word.equals("all"))
                return ALL;
            if (word.equals("none") || s.isEmpty())
                return NONE;
            Set<String> names = new TreeSet<>();
            for (String n : s.split("[,\\s]+")) {
                if (!n.matches(Fleet.NAME_PATTERN))
                    throw new IllegalArgumentException("'" + InputLimits.abbreviate(n, 60) + "' in trust rule '"
                            + InputLimits.abbreviate(spec, 60) + "' is not an agent name (use all, none or agent names)");
                names.add(n);
            }
            return new Rule(false, Set.copyOf(names));
        }

        @Override
        public String toString() {
            return all ? "all" : names.isEmpty() ? "none" : String.join(", ", new TreeSet<>(names));
        }
    }

    private final Map<String, Map<Group, Rule>> byParameter = new ConcurrentHashMap<>();
    private final Map<String, Map<Group, Rule>> byProgram = new ConcurrentHashMap<>();

    /** A rule of the ~trust parameter, for one agent or {@link #EVERY_AGENT}. */
    public void setParameterRule(String agent, Group group, Rule rule) {
        set(byParameter, agent, group, rule);
    }

    /** A rule of the .mas2j (agent option trust_&lt;group&gt;). */
    public void setProgramRule(String agent, Group group, Rule rule) {
        set(byProgram, agent, group, rule);
    }

    /** Forgets what the .mas2j set for agent (it stopped; a new agent of its name starts from the parameters). */
    public void forgetProgram(String agent) {
        byProgram.remove(agent);
    }

    private static void set(Map<String, Map<Group, Rule>> rules, String agent, Group group, Rule rule) {
        rules.computeIfAbsent(agent, a -> Collections.synchronizedMap(new EnumMap<>(Group.class)))
                .put(group, rule);
    }

    /** The rule that decides what agent accepts from other processes for this group. */
    public Rule rule(String agent, Group group) {
        Rule r = lookup(byParameter, agent, group);
        if (r == null)
            r = lookup(byProgram, agent, group);
        if (r == null)
            r = lookup(byParameter, EVERY_AGENT, group);
        if (r == null)
            r = group.allByDefault ? Rule.ALL : Rule.NONE;
        return r;
    }

    private static Rule lookup(Map<String, Map<Group, Rule>> rules, String agent, Group group) {
        Map<Group, Rule> m = rules.get(agent);
        return m == null ? null : m.get(group);
    }

    /** Whether receiver accepts a message with this performative from sender, an agent of another process. */
    public boolean allows(String receiver, String sender, String performative) {
        return rule(receiver, Group.of(performative)).allows(sender);
    }

    /** The log line of a refused message. */
    public String refusal(String receiver, String sender, String senderMas, String performative) {
        Group g = Group.of(performative);
        Rule rule = rule(receiver, g);
        return "refused " + InputLimits.abbreviate(performative, 100) + " from " + sender + " ("
                + InputLimits.abbreviate(senderMas, 100) + ") to " + receiver + ": " + receiver + " takes " + g.key
                + " from " + (rule.names().isEmpty() ? "no agent of another robot" : "other robots' " + rule + " only")
                + " (" + g.option() + " in the .mas2j, or ~trust)";
    }
}
