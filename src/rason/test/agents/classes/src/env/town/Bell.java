package town;

import jason.asSyntax.Literal;
import jason.asSyntax.Structure;
import jason.environment.Environment;

/** An environment whose ring action answers rang(N), N its first argument in the .mas2j. */
public class Bell extends Environment {

    private String times = "0";

    @Override
    public void init(String[] args) {
        if (args.length > 0)
            times = args[0];
    }

    @Override
    public boolean executeAction(String agName, Structure action) {
        if (!action.getFunctor().equals("ring"))
            return false;
        addPercept(agName, Literal.parseLiteral("rang(" + times + ")"));
        return true;
    }
}
