package rason.bridge;

import java.lang.reflect.Field;
import java.util.PriorityQueue;
import java.util.concurrent.Callable;
import java.util.concurrent.Delayed;
import java.util.concurrent.Executors;
import java.util.concurrent.FutureTask;
import java.util.concurrent.RunnableScheduledFuture;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.ScheduledThreadPoolExecutor;
import java.util.concurrent.TimeUnit;

import jason.asSemantics.Agent;

import rason.core.RosClock;

/**
 * Jason's scheduler (the one behind {@code .wait(ms)}, {@code .wait(Event, ms)},
 * {@code .at}, plan deadlines and the timeouts of {@code .send} asks) on ROS
 * time. On the wall clock (ROS time is wall time) it is an ordinary
 * {@link ScheduledThreadPoolExecutor}. On ROS time (/use_sim_time) a delayed
 * task is due at ROS time now + delay and is handed to the pool when the
 * clock, pushed by the node with every /clock message, passes that time: a
 * {@code .wait(400)} lasts 400 ms of simulated time whatever the real-time
 * factor, and nothing is due while the clock stands still. A clock that goes
 * back (a simulator restarted) delays what is waiting; it never runs it early.
 *
 * Jason keeps its scheduler in a static field and offers no setter:
 * {@link #installInJason} puts this one there.
 */
public final class RosTimeScheduler extends ScheduledThreadPoolExecutor {

    /** Threads of the pool, as Jason's default (Config NB_TH_SCH). */
    static final int THREADS = 2;

    private final RosClock clock;
    private final PriorityQueue<RosTimeTask<?>> waiting = new PriorityQueue<>(); // guarded by itself
    private volatile boolean onRosTime = false;
    private long sequence = 0; // guarded by waiting: FIFO among tasks due at the same time

    public RosTimeScheduler(RosClock clock) {
        super(THREADS, Executors.defaultThreadFactory());
        this.clock = clock;
        setRemoveOnCancelPolicy(true);
    }

    /**
     * Puts {@code scheduler} in Jason's static scheduler field, so every later
     * {@code Agent.getScheduler()} returns it; tasks already given to the one
     * it replaces still run there.
     *
     * @throws IllegalStateException Jason has no such field (another Jason version)
     */
    public static void installInJason(ScheduledExecutorService scheduler) {
        try {
            Field f = Agent.class.getDeclaredField("scheduler");
            f.setAccessible(true);
            synchronized (Agent.class) { // Agent.getScheduler() is static synchronized
                f.set(null, scheduler);
            }
        } catch (ReflectiveOperationException | RuntimeException e) {
            throw new IllegalStateException("cannot replace Jason's scheduler (Agent.scheduler): " + e, e);
        }
    }

    /** The scheduler Jason uses now. */
    public static ScheduledExecutorService jasonScheduler() {
        return Agent.getScheduler();
    }

    /**
     * Delays from now on follow ROS time (true) or the wall clock (false).
     * Going back to the wall clock hands what waits to the pool with the ROS
     * time it still had to wait.
     */
    public void useRosTime(boolean on) {
        onRosTime = on;
        if (on)
            return;
        long now = clock.nanos();
        synchronized (waiting) {
            for (RosTimeTask<?> t; (t = waiting.poll()) != null;) {
                if (!t.isCancelled())
                    super.schedule(t, Math.max(0, t.due - now), TimeUnit.NANOSECONDS);
            }
        }
    }

    /** Tasks waiting for the ROS clock. */
    public int waitingTasks() {
        synchronized (waiting) {
            return waiting.size();
        }
    }

    /** The ROS clock moved to nowNanos: hands every task due by then to the pool, earliest first. */
    public void advance(long nowNanos) {
        clock.set(nowNanos);
        runDue(nowNanos);
    }

    private void runDue(long nowNanos) {
        while (true) {
            RosTimeTask<?> due;
            synchronized (waiting) {
                due = waiting.peek();
                if (due == null || due.due > nowNanos)
                    return;
                waiting.poll();
            }
            if (!due.isCancelled() && !isShutdown())
                super.schedule(due, 0, TimeUnit.NANOSECONDS);
        }
    }

    /** At once, on either clock (the pool's execute would come back through {@link #schedule}). */
    @Override
    public void execute(Runnable command) {
        super.schedule(command, 0, TimeUnit.NANOSECONDS);
    }

    @Override
    public ScheduledFuture<?> schedule(Runnable command, long delay, TimeUnit unit) {
        if (!onRosTime)
            return super.schedule(command, delay, unit);
        return enqueue(new RosTimeTask<Void>(command, null, unit.toNanos(delay), 0));
    }

    @Override
    public <V> ScheduledFuture<V> schedule(Callable<V> callable, long delay, TimeUnit unit) {
        if (!onRosTime)
            return super.schedule(callable, delay, unit);
        return enqueue(new RosTimeTask<V>(callable, unit.toNanos(delay)));
    }

    @Override
    public ScheduledFuture<?> scheduleAtFixedRate(Runnable command, long initialDelay, long period, TimeUnit unit) {
        if (!onRosTime)
            return super.scheduleAtFixedRate(command, initialDelay, period, unit);
        if (period <= 0)
            throw new IllegalArgumentException("period must be positive, got " + period);
        return enqueue(new RosTimeTask<Void>(command, null, unit.toNanos(initialDelay), unit.toNanos(period)));
    }

    @Override
    public ScheduledFuture<?> scheduleWithFixedDelay(Runnable command, long initialDelay, long delay, TimeUnit unit) {
        // on ROS time a task takes no simulated time to run: fixed delay is fixed rate
        if (!onRosTime)
            return super.scheduleWithFixedDelay(command, initialDelay, delay, unit);
        return scheduleAtFixedRate(command, initialDelay, delay, unit);
    }

    private <V> RosTimeTask<V> enqueue(RosTimeTask<V> task) {
        if (isShutdown())
            throw new java.util.concurrent.RejectedExecutionException("the scheduler is shut down");
        synchronized (waiting) {
            task.sequence = sequence++;
            waiting.add(task);
        }
        runDue(clock.nanos()); // a delay of 0 (or less) is due at once
        return task;
    }

    @Override
    public void shutdown() {
        synchronized (waiting) {
            waiting.clear();
        }
        super.shutdown();
    }

    /** A task due at a ROS time; a periodic one comes back with its next due time after each run. */
    private final class RosTimeTask<V> extends FutureTask<V> implements RunnableScheduledFuture<V> {
        private long due;
        private final long period;
        private long sequence;

        RosTimeTask(Runnable command, V result, long delayNanos, long periodNanos) {
            super(command, result);
            this.due = clock.nanos() + delayNanos;
            this.period = periodNanos;
        }

        RosTimeTask(Callable<V> callable, long delayNanos) {
            super(callable);
            this.due = clock.nanos() + delayNanos;
            this.period = 0;
        }

        @Override
        public boolean isPeriodic() {
            return period > 0;
        }

        @Override
        public void run() {
            if (!isPeriodic()) {
                super.run();
            } else if (runAndReset()) {
                due += period;
                synchronized (waiting) {
                    if (!isCancelled() && !isShutdown())
                        waiting.add(this);
                }
                runDue(clock.nanos());
            }
        }

        @Override
        public boolean cancel(boolean mayInterruptIfRunning) {
            boolean cancelled = super.cancel(mayInterruptIfRunning);
            synchronized (waiting) {
                waiting.remove(this);
            }
            return cancelled;
        }

        @Override
        public long getDelay(TimeUnit unit) {
            return unit.convert(due - clock.nanos(), TimeUnit.NANOSECONDS);
        }

        @Override
        public int compareTo(Delayed other) {
            if (other == this)
                return 0;
            if (other instanceof RosTimeTask<?> t) {
                int c = Long.compare(due, t.due);
                return c != 0 ? c : Long.compare(sequence, t.sequence);
            }
            return Long.compare(getDelay(TimeUnit.NANOSECONDS), other.getDelay(TimeUnit.NANOSECONDS));
        }
    }
}
