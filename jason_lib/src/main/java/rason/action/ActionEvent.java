package rason.action;

import java.util.Arrays;

import rason.core.InputLimits;
import rason.core.Protocol;

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
        int actionId = actionId(eventType, text(parameters[needed - 1]));
        if (started)
            return new ActionEvent(true, actionId, null);
        String result = text(parameters[0]);
        if (result.isEmpty())
            throw new IllegalArgumentException(eventType + " with an empty result");
        return new ActionEvent(false, actionId, result);
    }

    /**
     * An action id as the bridge gives them: a whole number from 1 to 2^31 - 1, in
     * decimal. Read without BigInteger or exceptions, so a million digits cost one scan.
     */
    static int actionId(String eventType, String id) {
        int i = id.startsWith("-") || id.startsWith("+") ? 1 : 0;
        boolean digits = id.length() > i;
        for (int j = i; j < id.length() && digits; j++)
            digits = id.charAt(j) >= '0' && id.charAt(j) <= '9';
        if (!digits)
            throw new IllegalArgumentException(eventType + " with a non-integer action id '"
                    + InputLimits.abbreviate(id, 40) + "' (ids are 32-bit integers from 1)");
        String magnitude = id.substring(i).replaceFirst("^0+(?=.)", "");
        long value = magnitude.length() > 10 ? Long.MAX_VALUE : Long.parseLong(magnitude);
        if (id.startsWith("-"))
            value = -value;
        if (value < 1 || value > Integer.MAX_VALUE)
            throw new IllegalArgumentException(eventType + " with action id " + InputLimits.abbreviate(id, 40)
                    + " outside 1.." + Integer.MAX_VALUE + " (the bridge's ids are 32-bit integers from 1)");
        return (int) value;
    }

    private static String text(String s) {
        return s == null ? "" : s.strip();
    }
}
