package rason.casestudy;

import rason.bridge.Bridge;
import rason.bridge.Outbound;

/**
 * The case-study tests' camera: what it sees of a robot, and frames, one after the other,
 * until the agent asks for an action.
 */
final class CameraFrames {

    /**
     * Where the camera sits ahead of the helper's turning axis (m), as rason_sim mounts it
     * and helper.asl's cameraAhead says.
     */
    static final double CAMERA_AHEAD = 0.08;

    private CameraFrames() {
    }

    /**
     * What a helper at pose (x, y, heading CCW) sees of a robot at (x, y, heading CCW):
     * angle (degrees, clockwise), depth along the optical axis, yaw = heading relative to the
     * helper's (clockwise) + angle, in (-180, 180], as vision_synth reports them.
     */
    static double[] view(double[] pose, double[] robot) {
        double dx = robot[0] - pose[0], dy = robot[1] - pose[1];
        double ahead = dx * Math.cos(pose[2]) + dy * Math.sin(pose[2]);
        double left = -dx * Math.sin(pose[2]) + dy * Math.cos(pose[2]);
        double depth = ahead - CAMERA_AHEAD;
        double angle = Math.toDegrees(Math.atan2(-left, depth));
        double yaw = Math.toDegrees(pose[2] - robot[2]) + angle;
        return new double[] { angle, depth, yaw - 360 * Math.ceil((yaw - 180) / 360) };
    }

    /** Where (x, y, heading CCW) a robot is that a helper at the origin, heading 0, sees at v. */
    static double[] robotSeenAt(double[] v) {
        double angle = v[0], depth = v[1], yaw = v[2];
        return new double[] { CAMERA_AHEAD + depth, -depth * Math.tan(Math.toRadians(angle)),
                -Math.toRadians(yaw - angle) };
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

    /** {@link #untilAction}, failing the test when the agent asked for no action in time. */
    static Outbound.Action expectAction(Bridge bridge, Runnable frame, long waitMs) throws InterruptedException {
        Outbound.Action action = untilAction(bridge, frame, waitMs);
        if (action == null)
            throw new AssertionError("the helper asked for no action");
        return action;
    }
}
