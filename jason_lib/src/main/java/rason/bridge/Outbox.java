package rason.bridge;

import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;

import rason.action.ActionSink;

/**
 * The one way from the agents' threads to ROS: agents queue what they want
 * published and return at once; a thread of the rospy node takes it with
 * {@link #take}, blocking in Java (JPype lets the other Python threads run
 * meanwhile). So an agent thread never calls into Python nor waits for ROS.
 */
public final class Outbox implements ActionSink {

    private final BlockingQueue<Outbound> queue = new LinkedBlockingQueue<>();
    private volatile boolean open = false;

    /**
     * Queues one item for the node.
     *
     * @return false if no node takes items (not started, or stopped)
     */
    public boolean offer(Outbound item) {
        return open && queue.offer(item);
    }

    @Override
    public boolean action(String agent, int actionId, String action, String[] parameters) {
        return offer(new Outbound.Action(agent, actionId, action, parameters));
    }

    @Override
    public boolean cancel(String agent, int actionId, String reason) {
        return offer(new Outbound.Cancel(agent, actionId, reason));
    }

    /** The next item, waiting at most timeoutMillis; null if none came. */
    public Outbound take(long timeoutMillis) throws InterruptedException {
        return queue.poll(timeoutMillis, TimeUnit.MILLISECONDS);
    }

    /** The next item if one is queued, else null. */
    public Outbound poll() {
        return queue.poll();
    }

    void open() {
        open = true;
    }

    void close() {
        open = false;
    }

    public int size() {
        return queue.size();
    }
}
