package rason.messaging;

/**
 * How this process reaches the other processes of the fleet: agent messages out, and
 * word that our presence changed. What arrives comes in through {@link FleetPort}.
 * Called on agents' threads: an implementation only queues, never blocks. Messages
 * are signed end to end ({@link FleetAuth}), so no channel has to be trusted.
 */
public interface FleetChannel {

    /**
     * Sends an agent message of ours (m.senderMas() is this process; m.receiverMas() empty:
     * every other process).
     *
     * @return false if the channel takes nothing now (no node, or stopped)
     */
    boolean send(WireMessage m);

    /** Our agents or their directory registrations changed: announce our presence now, not at the next period. */
    boolean announceNow();
}
