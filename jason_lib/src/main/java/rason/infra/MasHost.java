package rason.infra;

import rason.AgentHost;
import rason.core.LogQueue;

/** What Rason's Jason infrastructure needs of the process it runs in, beyond what its agents need. */
public interface MasHost extends AgentHost {

    /** Where Jason's log and the agents' .print lines go (to rosout, through the node). */
    LogQueue log();

    /**
     * .stopMAS: the node shuts down and exits with exitValue.
     *
     * @return false if no node runs this MAS
     */
    boolean requestStop(int exitValue);
}
