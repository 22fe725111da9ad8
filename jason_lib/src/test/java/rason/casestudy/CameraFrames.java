package rason.casestudy;

import rason.bridge.Bridge;
import rason.bridge.Outbound;

/** The case-study tests' camera: frames, one after the other, until the agent asks for an action. */
final class CameraFrames {

    private CameraFrames() {
    }

    /**
     * Runs frame (one camera frame) again and again until an action is queued, for at most
     * waitMs; that action, or null.
     */
    static Outbound.Action untilAction(Bridge bridge, Runnable frame, long waitMs) throws InterruptedException {
        long deadline = System.currentTimeMillis() + waitMs;
        while (System.currentTimeMillis() < deadline) {
            frame.run();
            Outbound item = bridge.outbox().take(20);
            if (item instanceof Outbound.Action action)
                return action;
        }
        return null;
    }
}
