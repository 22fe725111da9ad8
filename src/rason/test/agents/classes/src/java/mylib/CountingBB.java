package mylib;

import java.util.concurrent.atomic.AtomicInteger;

import jason.asSyntax.Literal;
import jason.bb.DefaultBeliefBase;

/** Jason's belief base, counting the seen/1 beliefs it takes. */
public class CountingBB extends DefaultBeliefBase {

    private final AtomicInteger seen = new AtomicInteger();

    @Override
    protected boolean add(Literal l, boolean addInEnd) {
        boolean added = super.add(l, addInEnd);
        if (added && l.getFunctor().equals("seen") && l.getArity() == 1)
            seen.incrementAndGet();
        return added;
    }

    public int seenAdds() {
        return seen.get();
    }
}
