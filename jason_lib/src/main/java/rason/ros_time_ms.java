package rason;

/**
 * {@code rason.ros_time_ms(T)}: T is ROS time in milliseconds, as the bridge last heard
 * it from its node: simulated time under {@code /use_sim_time}, else the wall clock since
 * the epoch; 0 before the node's first tick. The time of perceptions that carry a ROS
 * stamp (a camera frame's {@code cameraFrame(N, T)}), so an agent can tell a frame taken
 * after something it did from one taken before. Reading it never blocks: the node pushes
 * the time to Java.
 */
public class ros_time_ms extends ClockReading {

    @Override
    double nowMillis(jason.asSemantics.TransitionSystem ts) {
        RosAgArch arch = RosAgArch.of(ts);
        return arch == null ? 0 : arch.rosNanos() / 1e6;
    }
}
