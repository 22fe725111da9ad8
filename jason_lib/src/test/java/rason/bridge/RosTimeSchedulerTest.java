package rason.bridge;

import rason.core.RosClock;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/** The scheduler Jason's timing runs on: delays in ROS time, or the wall clock's. No ROS, no agents. */
class RosTimeSchedulerTest {

    private static final long MS = 1_000_000L;
    private static final long START = 100_000 * MS; // ROS time 100 s

    private final RosClock clock = new RosClock();
    private final RosTimeScheduler scheduler = new RosTimeScheduler(clock);
    private final List<String> ran = new CopyOnWriteArrayList<>();

    @AfterEach
    void stop() {
        scheduler.shutdownNow();
    }

    private RosTimeScheduler onRosTime() {
        scheduler.useRosTime(true);
        scheduler.advance(START);
        return scheduler;
    }

    private static void await(CountDownLatch latch) throws InterruptedException {
        assertTrue(latch.await(RunningAgents.WAIT_MS, TimeUnit.MILLISECONDS), "the task ran");
    }

    @Test
    void aDelayedTaskRunsOnceTheRosClockPassesItsDueTime() throws Exception {
        CountDownLatch done = new CountDownLatch(1);
        ScheduledFuture<?> f = onRosTime().schedule(done::countDown, 400, TimeUnit.MILLISECONDS);
        assertEquals(400, f.getDelay(TimeUnit.MILLISECONDS));
        scheduler.advance(START + 399 * MS);
        assertEquals(1, scheduler.waitingTasks(), "not due 1 ms early, however long the wall clock ran");
        assertEquals(1, done.getCount());
        scheduler.advance(START + 400 * MS);
        await(done);
        assertEquals(0, scheduler.waitingTasks());
        assertEquals(START + 400 * MS, clock.nanos(), "advance moves the bridge's clock too");
    }

    @Test
    void theEarliestTaskRunsAtItsTimeWhileTheLaterOnesWaitForTheirs() throws Exception {
        CountDownLatch early = new CountDownLatch(1);
        CountDownLatch all = new CountDownLatch(3);
        // the pool has several threads: tasks handed over together may run in any order, so
        // the later ones are only made due once the early one has run
        onRosTime().schedule(() -> { ran.add("late"); all.countDown(); }, 300, TimeUnit.MILLISECONDS);
        scheduler.schedule(() -> { ran.add("early"); early.countDown(); all.countDown(); }, 100, TimeUnit.MILLISECONDS);
        scheduler.schedule(() -> { ran.add("late2"); all.countDown(); }, 300, TimeUnit.MILLISECONDS);
        scheduler.advance(START + 100 * MS);
        await(early);
        assertEquals(2, scheduler.waitingTasks());
        assertEquals(List.of("early"), ran);
        scheduler.advance(START + 1000 * MS);
        await(all);
        assertEquals(List.of("late", "late2"), ran.subList(1, 3).stream().sorted().toList());
    }

    @Test
    void aCancelledTaskLeavesTheQueueAndNeverRuns() throws Exception {
        ScheduledFuture<?> f = onRosTime().schedule(() -> ran.add("cancelled"), 50, TimeUnit.MILLISECONDS);
        assertTrue(f.cancel(false));
        assertEquals(0, scheduler.waitingTasks());
        CountDownLatch after = new CountDownLatch(1);
        scheduler.schedule(after::countDown, 60, TimeUnit.MILLISECONDS);
        scheduler.advance(START + 100 * MS);
        await(after);
        assertEquals(List.of(), ran);
    }

    @Test
    void aNonPositiveDelayIsDueAtOnceAndACallableGivesItsValue() throws Exception {
        ScheduledFuture<String> f = onRosTime().schedule(() -> "now", 0, TimeUnit.MILLISECONDS);
        assertEquals("now", f.get(RunningAgents.WAIT_MS, TimeUnit.MILLISECONDS));
        CountDownLatch past = new CountDownLatch(1);
        scheduler.schedule(past::countDown, -5, TimeUnit.SECONDS);
        await(past);
    }

    @Test
    void aPeriodicTaskRunsOncePerPeriodOfRosTimeUntilCancelled() throws Exception {
        CountDownLatch three = new CountDownLatch(3);
        ScheduledFuture<?> f = onRosTime().scheduleAtFixedRate(three::countDown, 100, 100, TimeUnit.MILLISECONDS);
        for (int step = 1; step <= 3; step++) {
            long target = 3 - step;
            scheduler.advance(START + step * 100 * MS);
            long deadline = System.currentTimeMillis() + RunningAgents.WAIT_MS;
            while (three.getCount() > target && System.currentTimeMillis() < deadline)
                Thread.sleep(1);
            assertEquals(target, three.getCount(), "one run per period reached");
        }
        f.cancel(false);
        assertEquals(0, scheduler.waitingTasks());
        assertFalse(f.isDone() && !f.isCancelled());
    }

    @Test
    void aClockGoingBackDelaysWhatWaitsButNeverRunsItEarly() throws Exception {
        CountDownLatch done = new CountDownLatch(1);
        onRosTime().schedule(done::countDown, 200, TimeUnit.MILLISECONDS);
        scheduler.advance(10 * MS); // the simulator restarted
        assertEquals(1, scheduler.waitingTasks());
        scheduler.advance(START + 200 * MS);
        await(done);
    }

    @Test
    void onTheWallClockDelaysAreWallDelaysAndNothingWaitsForRosTime() throws Exception {
        CountDownLatch done = new CountDownLatch(1);
        scheduler.advance(START);
        scheduler.schedule(done::countDown, 20, TimeUnit.MILLISECONDS);
        assertEquals(0, scheduler.waitingTasks());
        await(done); // the ROS clock never moved
    }

    @Test
    void backToTheWallClockWhatWaitedRunsAfterTheRosTimeItStillHad() throws Exception {
        CountDownLatch done = new CountDownLatch(1);
        onRosTime().schedule(done::countDown, 30, TimeUnit.MILLISECONDS);
        scheduler.useRosTime(false);
        assertEquals(0, scheduler.waitingTasks());
        await(done);
    }

    @Test
    void installedInJasonItIsTheSchedulerEveryAgentGets() throws Exception {
        var before = RosTimeScheduler.jasonScheduler();
        try {
            RosTimeScheduler.installInJason(scheduler);
            assertSame(scheduler, RosTimeScheduler.jasonScheduler());
        } finally {
            RosTimeScheduler.installInJason(before);
        }
    }
}
