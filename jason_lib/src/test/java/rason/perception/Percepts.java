package rason.perception;

import java.util.ArrayList;
import java.util.Collection;
import java.util.HashSet;
import java.util.List;
import java.util.Set;

import jason.asSyntax.Literal;

/** Shorthands shared by the perception tests: literals from text, sorted texts, selections and time units. */
final class Percepts {

    static final long S = 1_000_000_000L;
    static final long MS = 1_000_000L;

    private Percepts() {
    }

    /** One message's literals, parsed as the bridge parses them. */
    static List<Literal> lits(String... texts) {
        List<Literal> out = new ArrayList<>();
        for (String t : texts)
            out.add(Perceptions.parse(t));
        return out;
    }

    /** The literals' texts, sorted; null stays null (a manager's "nothing changed"). */
    static List<String> texts(Collection<Literal> literals) {
        if (literals == null)
            return null;
        List<String> out = new ArrayList<>();
        for (Literal l : literals)
            out.add(l.toString());
        out.sort(null);
        return out;
    }

    /** A mutable selection of functor/arity entries. */
    static Set<String> selection(String... entries) {
        return new HashSet<>(List.of(entries));
    }
}
