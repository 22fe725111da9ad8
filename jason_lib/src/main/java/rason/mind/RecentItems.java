package rason.mind;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.List;

/**
 * The last few items of a stream (events handled, messages in and out), oldest
 * first, each cut to a bounded length so one huge message cannot swell every
 * later snapshot. Used on the agent's thread only.
 */
public final class RecentItems {

    private final int capacity;
    private final int maxChars;
    private final ArrayDeque<String> items = new ArrayDeque<>();

    public RecentItems(int capacity, int maxChars) {
        if (capacity < 1 || maxChars < 1)
            throw new IllegalArgumentException("capacity and maxChars must be positive");
        this.capacity = capacity;
        this.maxChars = maxChars;
    }

    public void add(String item) {
        if (items.size() == capacity)
            items.removeFirst();
        items.addLast(MindReader.cut(item, maxChars));
    }

    /** A copy, oldest first. */
    public List<String> items() {
        return new ArrayList<>(items);
    }
}
