package rason.action;

import java.util.Arrays;

import rason.bridge.Protocol;

/**
 * A decomposer's event about one action, read from the fields of a
 * rason_msgs/Event: its answer (action_feedback [result, action_id]) or that it
 * took the action (action_started [action_id]).
 *
 * @param result the feedback's result; null for action_started
 */
public record ActionEvent(boolean started, int actionId, String result) {

    /**
     * Reads an event's type and parameters.
     *
     * @throws IllegalArgumentException saying why it is not a usable action event
     */
    public static ActionEvent parse(String eventType, String[] parameters) {
        boolean started = Protocol.ACTION_STARTED.equals(eventType);
        if (!started && !Protocol.ACTION_FEEDBACK.equals(eventType))
            throw new IllegalArgumentException("unknown event type '" + eventType + "'");
        int needed = started ? 1 : 2;
        if (parameters == null || parameters.length < needed)
            throw new IllegalArgumentException(eventType + " needs parameters "
                    + (started ? "[action_id]" : "[result, action_id]") + ", got "
                    + (parameters == null ? "none" : Arrays.toString(parameters)));
        String id = text(parameters[needed - 1]);
        int actionId;
        try {
            actionId = Integer.parseInt(id);
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException(eventType + " with a non-integer action id '" + id
                    + "' (ids are 32-bit integers)");
        }
        if (started)
            return new ActionEvent(true, actionId, null);
        String result = text(parameters[0]);
        if (result.isEmpty())
            throw new IllegalArgumentException(eventType + " with an empty result");
        return new ActionEvent(false, actionId, result);
    }

    private static String text(String s) {
        return s == null ? "" : s.strip();
    }
}
