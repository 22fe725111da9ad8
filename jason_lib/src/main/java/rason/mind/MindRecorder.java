package rason.mind;

/**
 * One agent's side of {@code jason/mind}: the events it handled and the
 * messages it exchanged lately, and snapshots of its state taken on its own
 * thread at the end of a reasoning cycle, at most once per period (wall clock)
 * while it runs and once more when it goes to sleep, so the last state before
 * a pause is never missed. A snapshot that differs from the one before only in
 * its cycle count is not news. The node's publishing thread reads
 * {@link #latest()} and {@link #version()}.
 */
public final class MindRecorder {

    /** Events and messages kept, and the length each is cut to. */
    public static final int RECENT = 20;
    public static final int RECENT_CHARS = 300;

    private final RecentItems events = new RecentItems(RECENT, RECENT_CHARS);
    private final RecentItems messages = new RecentItems(RECENT, RECENT_CHARS);
    private volatile AgentMind latest = null;
    private volatile long version = 0;
    private volatile boolean requested = false;
    private long lastReadNanos = 0; // wall clock; agent's thread only
    private boolean everRead = false;
    private boolean unread = false; // cycles ran since the last snapshot

    /** The agent handled this event (agent's thread). */
    public void event(String trigger) {
        events.add(trigger);
    }

    /** The agent received or sent this message (agent's thread). */
    public void message(String text) {
        messages.add(text);
    }

    /** Take a snapshot at the end of the next cycle, whatever the period (any thread). */
    public void request() {
        requested = true;
    }

    /** Whether a snapshot was asked for and not taken yet. */
    public boolean isRequested() {
        return requested;
    }

    /**
     * A reasoning cycle ended (agent's thread): a snapshot when the period has passed
     * since the last one, or one was requested.
     *
     * @param read makes the snapshot from the recent events and messages
     * @return whether a snapshot was taken
     */
    public boolean cycleEnded(long periodNanos, long wallNanos, Reader read) {
        if (requested || !everRead || wallNanos - lastReadNanos >= periodNanos)
            return take(wallNanos, read);
        unread = true;
        return false;
    }

    /** The agent goes to sleep (agent's thread): a snapshot if cycles ran since the last one. */
    public boolean goingToSleep(long wallNanos, Reader read) {
        return (unread || requested) && take(wallNanos, read);
    }

    private boolean take(long wallNanos, Reader read) {
        requested = false;
        unread = false;
        everRead = true;
        lastReadNanos = wallNanos;
        AgentMind mind = read.read(events, messages);
        if (!mind.sameStateAs(latest)) {
            latest = mind;
            version++;
        }
        return true;
    }

    /** The newest snapshot that changed something, null before the first. */
    public AgentMind latest() {
        return latest;
    }

    /** Grows by one with each snapshot that changed something. */
    public long version() {
        return version;
    }

    /** Reads the agent's state with its recent events and messages. */
    @FunctionalInterface
    public interface Reader {
        AgentMind read(RecentItems events, RecentItems messages);
    }
}
