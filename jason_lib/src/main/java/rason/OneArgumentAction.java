package rason;

import jason.asSemantics.DefaultInternalAction;

/** An internal action that takes exactly one argument (Jason checks the count). */
abstract class OneArgumentAction extends DefaultInternalAction {

    @Override
    public int getMinArgs() {
        return 1;
    }

    @Override
    public int getMaxArgs() {
        return 1;
    }
}
