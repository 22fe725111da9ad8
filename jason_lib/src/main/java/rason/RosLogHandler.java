package rason;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.util.logging.Handler;
import java.util.logging.LogRecord;
import java.util.logging.SimpleFormatter;

/**
 * Sends java.util.logging records (Jason's own log and the agents' .print) to
 * rosout through the {@link RosConnector}, tagged with the agent's name.
 */
public class RosLogHandler extends Handler {

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
        RosConnector c = RasonHub.get().getConnector();
        if (c != null) {
            try {
                c.log(record.getLevel().intValue(), agent, message);
                return;
            } catch (Throwable t) {
                // Python side gone (shutdown): fall through to stderr
            }
        }
        System.err.println((agent.isEmpty() ? "" : "[" + agent + "] ") + message);
    }

    /** Jason names its per-agent loggers "<class>.<agent>"; anything else has no agent. */
    static String agentOf(String loggerName) {
        if (loggerName == null)
            return "";
        String last = loggerName.substring(loggerName.lastIndexOf('.') + 1);
        return RasonHub.get().hostedNames().contains(last) ? last : "";
    }

    @Override
    public void flush() {
    }

    @Override
    public void close() {
    }
}
