package rason.infra;

import jason.asSyntax.Structure;
import jason.asSyntax.VarTerm;

/**
 * Run in a JVM of its own by {@link RasonConfigTest}: prints how Jason names a
 * renamed variable once Rason's infrastructure is loaded. With "late", a Jason
 * term is used first, as code that runs before Rason's would.
 */
public final class UnnamedVarsProbe {

    private UnnamedVarsProbe() {
    }

    public static void main(String[] args) throws Exception {
        if (args.length > 0 && args[0].equals("late")) {
            Structure early = new Structure("early");
            early.addTerm(new VarTerm("X"));
            early.makeVarsAnnon();
        }
        Class.forName(RasonLocalMAS.class.getName()); // as the node loads it
        Structure p = new Structure("p");
        p.addTerm(new VarTerm("Named"));
        p.makeVarsAnnon();
        System.out.println("renamed=" + p.getTerm(0));
        System.out.println("applied=" + RasonConfig.shortUnnamedVarsApplied());
    }
}
