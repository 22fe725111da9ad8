package rason.bridge;

/**
 * ROS time as the rospy node last pushed it (wall or simulated, whatever
 * /use_sim_time says). Java never asks Python for the time: the node pushes it
 * with every tick, and 0 means "not known yet".
 */
public final class RosClock {

    private volatile long nowNanos = 0;

    public long now() {
        return nowNanos;
    }

    void set(long nanos) {
        nowNanos = nanos;
    }
}
