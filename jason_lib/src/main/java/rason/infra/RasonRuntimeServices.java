package rason.infra;

import java.util.Collection;

import jason.infra.local.BaseLocalMAS;
import jason.infra.local.LocalRuntimeServices;

import rason.bridge.Bridge;

/**
 * Jason's local runtime services, except that the agent names (what
 * {@code .all_names} answers) include the reachable agents of other rason_mas
 * processes.
 */
public class RasonRuntimeServices extends LocalRuntimeServices {

    public RasonRuntimeServices(BaseLocalMAS masRunner) {
        super(masRunner);
    }

    @Override
    public Collection<String> getAgentsNames() {
        return Bridge.get().allNames();
    }

    @Override
    public int getAgentsQty() {
        return getAgentsNames().size();
    }
}
