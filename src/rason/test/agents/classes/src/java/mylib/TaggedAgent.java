package mylib;

import jason.asSemantics.Agent;
import jason.asSyntax.Literal;

/** Jason's agent, starting with the belief made_by(tagged_agent). */
public class TaggedAgent extends Agent {

    @Override
    public void initAg() {
        super.initAg();
        addInitialBel(Literal.parseLiteral("made_by(tagged_agent)"));
    }
}
