package rason.infra;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.util.function.Predicate;
import java.util.logging.Handler;
import java.util.logging.LogRecord;
import java.util.logging.SimpleFormatter;

import rason.core.LogQueue;

/**
 * Sends java.util.logging records (Jason's own log and the agents' .print) to
 * rosout, tagged with the agent's name: each becomes a line of the {@link LogQueue}
 * that the node drains on a thread of its own.
 */
public class RosLogHandler extends Handler {

    private final SimpleFormatter formatter = new SimpleFormatter();
    private final LogQueue lines;
    private final Predicate<String> hosted;

    /** @param hosted whether a name is one of this process's agents */
    public RosLogHandler(LogQueue lines, Predicate<String> hosted) {
        this.lines = lines;
        this.hosted = hosted;
    }

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
        lines.add(record.getLevel().intValue(), agentOf(record.getLoggerName()), message);
    }

    /** Jason names its per-agent loggers "<class>.<agent>"; anything else has no agent. */
    String agentOf(String loggerName) {
        if (loggerName == null)
            return "";
        String last = loggerName.substring(loggerName.lastIndexOf('.') + 1);
        return hosted.test(last) ? last : "";
    }

    @Override
    public void flush() {
    }

    @Override
    public void close() {
    }
}
