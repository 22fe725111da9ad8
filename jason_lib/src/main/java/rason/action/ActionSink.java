package rason.action;

/**
 * Where an agent's actions and cancels go on their way to the robot (jason/action).
 * Called on the agent's thread: an implementation only queues, never blocks.
 */
public interface ActionSink {

    /** @return false if nothing takes actions now (no node) */
    boolean action(String agent, int actionId, String action, String[] parameters);

    /** A cancel of an action the agent no longer waits for; it never overtakes that action. */
    boolean cancel(String agent, int actionId, String reason);
}
