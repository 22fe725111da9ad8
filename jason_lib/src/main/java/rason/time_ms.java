package rason;

/**
 * {@code rason.time_ms(X)}: X is the time in milliseconds, with a fractional
 * part down to the microsecond, on the monotonic clock of this machine (Java's
 * {@code System.nanoTime}, Python's {@code time.monotonic} on Linux). Meant for
 * differences, as thesis Listing 5.4 uses its modified {@code .time}; Jason's
 * own {@code .time} gives hours, minutes and seconds only.
 */
public class time_ms extends ClockReading {

    /** Milliseconds on the monotonic clock, rounded to the microsecond. */
    @Override
    double nowMillis(jason.asSemantics.TransitionSystem ts) {
        return Math.rint(rason.core.Clock.WALL.nanos() / 1e3) / 1e3;
    }
}
