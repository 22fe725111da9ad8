package rason.messaging;

import java.util.Collection;
import java.util.List;

/** What the agents need to hear of the fleet ({@link Fleet}). */
public interface FleetListener {
    /** The set of reachable agents changed (present/1 beliefs). */
    void reachableChanged();

    /** These agents' processes ended: answers they owe will never come. */
    void receiversLost(Collection<String> names);

    /** This process must not go on (it duplicates an earlier one's agent in the same namespace). */
    void mustStop(String why);

    /**
     * Subscribers of the directory facilitator must hear of providers that came or went
     * (called under the directory's lock, in order: only queue them for the agents).
     */
    default void providersChanged(List<FleetDirectory.Notice> notices) {
    }
}
