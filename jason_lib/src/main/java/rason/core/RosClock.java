package rason.core;

/**
 * ROS time as the rospy node last pushed it (wall or simulated, whatever
 * /use_sim_time says). Java never asks Python for the time: the node pushes it
 * with every tick, and 0 means "not known yet".
 */
public final class RosClock implements Clock {

    private volatile long nowNanos = 0;

    @Override
    public long nanos() {
        return nowNanos;
    }

    public void set(long nanos) {
        nowNanos = nanos;
    }
}
