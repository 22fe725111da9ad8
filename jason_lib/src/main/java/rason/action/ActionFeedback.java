package rason.action;

import rason.bridge.Protocol;

/** A decomposer's answer to one action, read from the fields of a rason_msgs/Event. */
public record ActionFeedback(int actionId, String result) {

    /**
     * Reads an event's type and parameters ([result, action_id]).
     *
     * @throws IllegalArgumentException saying why it is not a usable action feedback
     */
    public static ActionFeedback parse(String eventType, String[] parameters) {
        if (!Protocol.ACTION_FEEDBACK.equals(eventType))
            throw new IllegalArgumentException("unknown event type '" + eventType + "'");
        if (parameters == null || parameters.length < 2)
            throw new IllegalArgumentException(Protocol.ACTION_FEEDBACK + " needs parameters [result, action_id], got "
                    + (parameters == null ? "none" : java.util.Arrays.toString(parameters)));
        String result = parameters[0] == null ? "" : parameters[0].strip();
        if (result.isEmpty())
            throw new IllegalArgumentException(Protocol.ACTION_FEEDBACK + " with an empty result");
        String id = parameters[1] == null ? "" : parameters[1].strip();
        try {
            return new ActionFeedback(Integer.parseInt(id), result);
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException(Protocol.ACTION_FEEDBACK + " with a non-integer action id '" + id
                    + "' (ids are 32-bit integers)");
        }
    }
}
