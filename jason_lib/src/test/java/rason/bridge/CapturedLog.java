package rason.bridge;

import java.util.ArrayList;
import java.util.List;
import java.util.logging.Handler;
import java.util.logging.LogRecord;
import java.util.logging.Logger;

import org.junit.jupiter.api.extension.AfterEachCallback;
import org.junit.jupiter.api.extension.ExtensionContext;

/**
 * The lines a java.util.logging logger writes while {@link #attach attached}, for tests that
 * check what was logged; detached after each test (register it with {@code @RegisterExtension}).
 */
public final class CapturedLog extends Handler implements AfterEachCallback {

    private final Logger logger;
    private final List<String> lines = new ArrayList<>(); // guarded by this

    public CapturedLog(String loggerName) {
        logger = Logger.getLogger(loggerName);
    }

    public void attach() {
        logger.addHandler(this);
    }

    /** Lines so far that contain text. */
    public synchronized long containing(String text) {
        return lines.stream().filter(l -> l.contains(text)).count();
    }

    public synchronized List<String> lines() {
        return new ArrayList<>(lines);
    }

    @Override
    public synchronized void publish(LogRecord r) {
        lines.add(r.getMessage());
    }

    @Override
    public void flush() {
    }

    @Override
    public void close() {
    }

    @Override
    public void afterEach(ExtensionContext context) {
        logger.removeHandler(this);
    }
}
