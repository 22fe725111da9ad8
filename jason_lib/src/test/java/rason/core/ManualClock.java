package rason.core;

import java.util.concurrent.atomic.AtomicLong;

/** A clock a test moves by hand: time passes only when the test says so. */
public final class ManualClock implements Clock {

    private final AtomicLong now;

    public ManualClock(long startNanos) {
        now = new AtomicLong(startNanos);
    }

    @Override
    public long nanos() {
        return now.get();
    }

    public void advance(long nanos) {
        now.addAndGet(nanos);
    }
}
