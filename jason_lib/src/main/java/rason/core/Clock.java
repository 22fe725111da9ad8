package rason.core;

/**
 * A source of time in nanoseconds that only goes forward. The wall clock measures
 * durations of this process (rate limits, presence silences, grace periods); ROS
 * time ({@link RosClock}) is what the node pushes. Classes take the clock they
 * need, so a test can move time instead of waiting for it.
 */
@FunctionalInterface
public interface Clock {

    long nanos();

    /** This machine's monotonic clock. */
    Clock WALL = System::nanoTime;
}
