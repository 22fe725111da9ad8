package rason.mind;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.Iterator;
import java.util.List;
import java.util.Set;

import jason.asSemantics.Circumstance;
import jason.asSemantics.IntendedMeans;
import jason.asSemantics.Intention;
import jason.asSemantics.TransitionSystem;
import jason.asSyntax.ASSyntax;
import jason.asSyntax.Atom;
import jason.asSyntax.Literal;
import jason.asSyntax.PlanBody;
import jason.asSyntax.Trigger;

/**
 * Reads an agent's mental state out of Jason into an {@link AgentMind}, bounded:
 * at most {@code maxItems} entries a list and {@code maxChars} characters an
 * entry, the rest counted as omitted. Only on the agent's own thread, the one
 * that changes that state.
 */
public final class MindReader {

    /** The annotation Jason's mind inspector hides beliefs by (its kqml rules carry it). */
    static final Atom HIDDEN = ASSyntax.createAtom("hide_in_mind_inspector");

    /** Written before an achievement goal, as in Jason's source ({@code !g}), to tell it from a belief. */
    static final String GOAL_MARK = "!";

    private final int maxItems;
    private final int maxChars;

    public MindReader(int maxItems, int maxChars) {
        if (maxItems < 1 || maxChars < 16)
            throw new IllegalArgumentException("maxItems must be positive and maxChars at least 16");
        this.maxItems = maxItems;
        this.maxChars = maxChars;
    }

    public AgentMind read(TransitionSystem ts, long cycle, long stampNanos, List<AgentMind.ActionView> actions,
            List<String> events, List<String> messages) {
        int[] omitted = { 0 };
        List<String> beliefs = new ArrayList<>();
        List<String> rules = new ArrayList<>();
        for (Literal b : ts.getAg().getBB()) {
            if (b.hasAnnot(HIDDEN))
                continue; // Jason's own rules (kqml::...), hidden by its mind inspector too
            List<String> into = b.isRule() ? rules : beliefs;
            if (into.size() == maxItems) {
                omitted[0]++;
                continue;
            }
            into.add(cut(b.toString(), maxChars));
        }
        List<String> goals = new ArrayList<>();
        List<AgentMind.IntentionView> intentions = new ArrayList<>();
        Circumstance c = ts.getC();
        Set<Integer> seen = new HashSet<>();
        for (Iterator<Intention> it = c.getAllIntentions(); it.hasNext();) {
            Intention i = it.next();
            if (!seen.add(i.getId()))
                continue; // Jason's iterator can meet one intention in two places (waiting for an action)
            if (intentions.size() == maxItems) {
                omitted[0]++;
                continue;
            }
            List<String> plans = new ArrayList<>();
            List<String> itsGoals = new ArrayList<>();
            for (IntendedMeans im : i) { // innermost first
                if (plans.size() == maxItems) {
                    omitted[0]++;
                    continue;
                }
                plans.add(frame(im));
                Trigger t = im.getTrigger();
                if (t.isAchvGoal() && t.isAddition())
                    itsGoals.add(0, cut(GOAL_MARK + t.getLiteral(), maxChars)); // outermost first
            }
            for (String g : itsGoals) {
                if (goals.size() == maxItems)
                    omitted[0]++;
                else
                    goals.add(g);
            }
            intentions.add(new AgentMind.IntentionView(i.getId(), i.getStateBasedOnPlace().toString(),
                    List.copyOf(plans)));
        }
        return new AgentMind(ts.getAgArch().getAgName(), cycle, stampNanos, List.copyOf(beliefs), List.copyOf(rules),
                List.copyOf(goals),
                List.copyOf(intentions), bounded(actions, omitted), bounded(events, omitted),
                bounded(messages, omitted), omitted[0]);
    }

    /** "label: trigger <- next step" of one intended means, its variables as bound so far. */
    private String frame(IntendedMeans im) {
        String label;
        String step;
        try {
            label = im.getPlan().getLabel() == null ? "" : im.getPlan().getLabel().getFunctor() + ": ";
            PlanBody next = im.getCurrentStep();
            step = next == null || next.getBodyTerm() == null ? "."
                    : next.getBodyTerm().capply(im.getUnif()).toString();
        } catch (RuntimeException e) { // a plan body Jason cannot show: say so, do not lose the snapshot
            label = "";
            step = "?";
        }
        return cut(label + im.getTrigger().capply(im.getUnif()) + " <- " + step, maxChars);
    }

    private <T> List<T> bounded(List<T> items, int[] omitted) {
        if (items.size() <= maxItems)
            return List.copyOf(items);
        omitted[0] += items.size() - maxItems;
        return List.copyOf(items.subList(items.size() - maxItems, items.size())); // the newest
    }

    /** text, or its first maxChars characters with an ellipsis. */
    static String cut(String text, int maxChars) {
        return text.length() <= maxChars ? text : text.substring(0, maxChars - 1) + "…";
    }
}
