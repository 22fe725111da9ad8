package rason.infra;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.logging.Handler;
import java.util.logging.LogRecord;
import java.util.logging.SimpleFormatter;

import rason.bridge.Bridge;

/**
 * Sends java.util.logging records (Jason's own log and the agents' .print) to
 * rosout, tagged with the agent's name. The agent's thread only queues the line;
 * the rospy process takes queued lines with {@link #drain} on a thread of its own,
 * so an agent that prints in every cycle never waits for Python.
 */
public class RosLogHandler extends Handler {

    /** One queued line: a java.util.logging level value, the agent ("" if none) and the text. */
    public record Line(int level, String agent, String message) {
    }

    /** Lines kept while nobody drains; beyond this, the oldest are dropped (and counted). */
    static final int MAX_QUEUED = 100_000;

    private static final ConcurrentLinkedQueue<Line> queue = new ConcurrentLinkedQueue<>();
    private static final AtomicInteger queued = new AtomicInteger();
    private static final AtomicInteger dropped = new AtomicInteger();

    private final SimpleFormatter formatter = new SimpleFormatter();

    @Override
    public void publish(LogRecord record) {
        if (record == null || !isLoggable(record))
            return;
        String message = formatter.formatMessage(record);
        if (record.getThrown() != null) {
            StringWriter trace = new StringWriter();
            record.getThrown().printStackTrace(new PrintWriter(trace));
            message = message + "\n" + trace;
        }
        String agent = agentOf(record.getLoggerName());
        if (!Bridge.get().isAttached()) { // no rospy node (yet, or any more)
            System.err.println((agent.isEmpty() ? "" : "[" + agent + "] ") + message);
            return;
        }
        queue.add(new Line(record.getLevel().intValue(), agent, message));
        if (queued.incrementAndGet() > MAX_QUEUED && queue.poll() != null) {
            queued.decrementAndGet();
            dropped.incrementAndGet();
        }
    }

    /** Takes up to max queued lines, oldest first (empty if none). */
    public static Line[] drain(int max) {
        List<Line> out = new ArrayList<>();
        Line l;
        while (out.size() < max && (l = queue.poll()) != null) {
            queued.decrementAndGet();
            out.add(l);
        }
        return out.toArray(new Line[0]);
    }

    /** Lines dropped because nobody drained them in time, since the last call. */
    public static int takeDropped() {
        return dropped.getAndSet(0);
    }

    /** Jason names its per-agent loggers "<class>.<agent>"; anything else has no agent. */
    static String agentOf(String loggerName) {
        if (loggerName == null)
            return "";
        String last = loggerName.substring(loggerName.lastIndexOf('.') + 1);
        return Bridge.get().registry().names().contains(last) ? last : "";
    }

    @Override
    public void flush() {
    }

    @Override
    public void close() {
    }
}
