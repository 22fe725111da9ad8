package rason;

import jason.architecture.AgArch;
import jason.runtime.RuntimeServices;

import rason.action.ActionPort;
import rason.core.Clock;
import rason.messaging.FleetPort;
import rason.mind.MindPort;
import rason.perception.PerceptionPort;

/**
 * What the process hosting an agent offers its architectures: one port per concern,
 * and the clocks. Jason creates architectures by reflection, so they find their host
 * through the infrastructure's runtime services, which hold it.
 */
public interface AgentHost {

    ActionPort actions();

    PerceptionPort perception();

    FleetPort fleet();

    MindPort mind();

    /** ROS time, as the node pushes it. */
    Clock rosClock();

    /** This process's monotonic clock. */
    Clock wallClock();

    /** Runtime services that know the host of the agents they serve. */
    interface Provider {
        AgentHost agentHost();
    }

    /**
     * The host of the agent arch belongs to.
     *
     * @throws IllegalStateException if the agent does not run on Rason's infrastructure
     */
    static AgentHost of(AgArch arch) {
        RuntimeServices services = arch.getRuntimeServices();
        if (services instanceof Provider p)
            return p.agentHost();
        throw new IllegalStateException(arch.getClass().getName() + " needs Rason's infrastructure (rason_mas), not "
                + (services == null ? "none" : services.getClass().getName()));
    }
}
