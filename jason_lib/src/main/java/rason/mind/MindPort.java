package rason.mind;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.Supplier;

/**
 * jason/mind for every hosted agent: while the node has a subscriber, each agent
 * records its recent events and messages and takes snapshots of its state on its
 * own thread ({@link MindRecorder}); the node's thread collects what changed.
 */
public final class MindPort {

    private record Recorded(MindRecorder recorder, Runnable wake) {
    }

    private final Map<String, Recorded> agents = new ConcurrentHashMap<>();
    private final Map<String, Long> published = new HashMap<>(); // guarded by itself
    private final Supplier<String> inspectorUrl;
    private volatile long periodNanos = 0;
    private volatile MindReader reader;

    /**
     * @param maxItems bounds of each snapshot: entries a list
     * @param maxChars and characters an entry
     * @param inspectorUrl where Jason's web mind inspector of this process is served ("" if nowhere)
     */
    public MindPort(int maxItems, int maxChars, Supplier<String> inspectorUrl) {
        this.reader = new MindReader(maxItems, maxChars);
        this.inspectorUrl = inspectorUrl;
    }

    /** A hosted agent's recorder; wake makes it run a cycle (for a snapshot asked for). */
    public MindRecorder join(String agent, Runnable wake) {
        MindRecorder r = new MindRecorder();
        agents.put(agent, new Recorded(r, wake));
        return r;
    }

    public void leave(String agent, MindRecorder recorder) {
        agents.computeIfPresent(agent, (name, rec) -> rec.recorder() == recorder ? null : rec);
    }

    /**
     * How often at most (wall clock) a running agent's state is read; 0 stops reading.
     * Turning it on has every agent read its state in its next cycle, and the next
     * {@link #changes()} returns them all.
     */
    public void setPeriodNanos(long t) {
        if (t < 0)
            throw new IllegalArgumentException("the mind period must be 0 (off) or more, not " + t + " ns");
        boolean turnedOn = periodNanos <= 0 && t > 0;
        periodNanos = t;
        if (turnedOn) {
            synchronized (published) {
                published.clear();
            }
            requestReads();
        }
    }

    /**
     * Has every agent read its state at the end of its next cycle, sleeping ones woken for it,
     * so that the state each ends in is published before the node stops; {@link #readsPending()}
     * says when they all have.
     */
    public void requestReads() {
        for (Recorded r : agents.values()) {
            r.recorder().request();
            r.wake().run();
        }
    }

    /** How many agents have not yet read the state asked for by {@link #requestReads()}. */
    public int readsPending() {
        int n = 0;
        for (Recorded r : agents.values())
            if (r.recorder().isRequested())
                n++;
        return n;
    }

    public long periodNanos() {
        return periodNanos;
    }

    /** Bounds of each snapshot: at most maxItems entries a list, maxChars characters an entry. */
    public void setLimits(int maxItems, int maxChars) {
        reader = new MindReader(maxItems, maxChars);
    }

    public MindReader reader() {
        return reader;
    }

    /** Where Jason's web mind inspector of this process is served (loopback), "" if no agent asked for it. */
    public String inspectorUrl() {
        return inspectorUrl.get();
    }

    /**
     * Every hosted agent's newest snapshot, sorted by name, when one of them changed or an
     * agent came or went since the last call; null when nothing did (the node's thread).
     */
    public AgentMind[] changes() {
        List<AgentMind> minds = new ArrayList<>();
        Map<String, Long> versions = new HashMap<>();
        for (Recorded r : agents.values()) {
            AgentMind m = r.recorder().latest();
            if (m != null) {
                minds.add(m);
                versions.put(m.name(), r.recorder().version());
            }
        }
        synchronized (published) {
            if (versions.equals(published))
                return null;
            published.clear();
            published.putAll(versions);
        }
        minds.sort(Comparator.comparing(AgentMind::name));
        return minds.toArray(new AgentMind[0]);
    }
}
