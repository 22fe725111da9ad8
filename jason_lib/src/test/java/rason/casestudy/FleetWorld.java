package rason.casestudy;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.Predicate;

import rason.bridge.Bridge;
import rason.bridge.Outbound;
import rason.bridge.RunningAgents;
import rason.core.LogQueue;
import rason.core.Protocol;

/**
 * A small world for the fleet case study's tests: robots on a floor, each agent perceiving its
 * own robot (odometry pos/3, and with a camera, vision_synth's cameraFrame/2 and robot/4 of the
 * robots in view), and the actions done at once: turn, move (a faulty robot's move as its
 * fault makes it, and failed with the reason the motion decomposer gives) and goto (a robot
 * without a fault), report_diagnosis noted. The world steps every 10 ms of wall time, a camera frame every 5 steps (20 Hz, a
 * Kinect's rate is 30); ROS time runs with the wall, or faster
 * (as the simulator at rate 0). With a shared frame every robot also perceives mapPose/3, its
 * pose in the world.
 */
final class FleetWorld implements AutoCloseable {

    static final double HALF_FOV = 28.5;
    /** Degrees an actuator fault turns the robot in one move. */
    static final double FAULT_TURN = 25;
    private static final long STEP_MS = 10;

    /**
     * A robot: its agent's name, pose (x, y, heading counter-clockwise), camera, fault, and the
     * name the cameras see it by (its agent's, unless told).
     */
    static final class Robot {
        final String name;
        final double[] pose;
        final boolean camera;
        final String fault;
        final String seenAs;

        Robot(String name, double x, double y, double headingDeg, boolean camera, String fault) {
            this(name, x, y, headingDeg, camera, fault, name);
        }

        Robot(String name, double x, double y, double headingDeg, boolean camera, String fault, String seenAs) {
            this.name = name;
            this.pose = new double[] { x, y, Math.toRadians(headingDeg) };
            this.camera = camera;
            this.fault = fault;
            this.seenAs = seenAs;
        }
    }

    private final Bridge bridge;
    private final RunningAgents agents;
    private final Map<String, Robot> robots = new ConcurrentHashMap<>();
    private final Map<String, String> diagnoses = new ConcurrentHashMap<>();
    private final Set<String> cancelled = ConcurrentHashMap.newKeySet();
    private final List<Outbound.Action> parked = new ArrayList<>(); // guarded by this
    private final List<Outbound.Action> done = new ArrayList<>(); // guarded by this
    private volatile Predicate<Outbound.Action> park = a -> false;
    private volatile Throwable failure;
    private volatile boolean stopAsked = false;
    private final StringBuffer transcript = new StringBuffer();
    private volatile boolean running = true;
    private final Thread thread;
    private final long rosPerStep;
    private final boolean sharedFrame;
    private volatile boolean sideOnHidden = false;
    private static final long START = 100 * RunningAgents.SECOND;
    private long now = START;
    private static final int STEPS_PER_FRAME = 5;
    private int step = 0;
    private int frame = 0;

    /**
     * @param speed       ROS time per wall time (1: real time)
     * @param sharedFrame whether the robots perceive their poses in the world (mapPose/3)
     */
    FleetWorld(Bridge bridge, RunningAgents agents, List<Robot> robots, int speed, boolean sharedFrame) {
        this.bridge = bridge;
        this.rosPerStep = speed * STEP_MS * 1_000_000L;
        this.sharedFrame = sharedFrame;
        this.agents = agents;
        for (Robot r : robots)
            this.robots.put(r.name, r);
        thread = new Thread(this::run, "fleet world");
        thread.setDaemon(true);
    }

    void start() {
        thread.start();
    }

    /**
     * From now on a camera does not see a robot side-on, within {@link #SIDE_ON_DEG} of its left
     * or right (one cylinder behind the other: vision_synth never takes one for a robot).
     */
    void hideSideOn() {
        sideOnHidden = true;
    }

    static final double SIDE_ON_DEG = 15;

    /** Whether a camera at pose sees robot side-on. */
    static boolean sideOn(double[] pose, double[] robot) {
        double towardsCamera = Math.atan2(pose[1] - robot[1], pose[0] - robot[0]) - robot[2];
        return Math.abs(Math.cos(towardsCamera)) < Math.sin(Math.toRadians(SIDE_ON_DEG));
    }

    /** Actions that match are held, unanswered, until {@link #releaseParked}. */
    void park(Predicate<Outbound.Action> which) {
        park = which;
    }

    /** Holds nothing any more, and does the held actions not taken back meanwhile. */
    void releaseParked() {
        park = a -> false;
        List<Outbound.Action> held;
        synchronized (this) {
            held = new ArrayList<>(parked);
            parked.clear();
        }
        for (Outbound.Action a : held)
            if (!cancelled.contains(key(a.agent(), a.actionId())))
                perform(a);
    }

    /** The held actions (not taken back). */
    synchronized List<Outbound.Action> parked() {
        List<Outbound.Action> out = new ArrayList<>();
        for (Outbound.Action a : parked)
            if (!cancelled.contains(key(a.agent(), a.actionId())))
                out.add(a);
        return out;
    }

    boolean wasCancelled(Outbound.Action a) {
        return cancelled.contains(key(a.agent(), a.actionId()));
    }

    /** The robot's agent stopped: it is out of the world. */
    void remove(String name) {
        robots.remove(name);
    }

    /** The diagnosis the robot's agent reported, null if none yet. */
    String diagnosis(String name) {
        return diagnoses.get(name);
    }

    /** What the agents printed so far, one line each, after the ROS time (s since the start). */
    String transcript() {
        return transcript.toString();
    }

    /** A line of the test's own in the transcript. */
    void note(String line) {
        transcript.append("        [test] ").append(line).append('\n');
    }

    /** The number of the last camera frame. */
    synchronized int frame() {
        return frame;
    }

    /** An agent ran .stopMAS. */
    boolean stopAsked() {
        return stopAsked;
    }

    /** The actions done so far (answered), in order. */
    synchronized List<Outbound.Action> done() {
        return new ArrayList<>(done);
    }

    /** Rethrows what went wrong on the world's thread. */
    void check() {
        if (failure != null)
            throw new AssertionError("the world failed", failure);
    }

    @Override
    public void close() throws InterruptedException {
        running = false;
        thread.join(2000);
        check();
    }

    private void run() {
        try {
            while (running) {
                Outbound item;
                while ((item = bridge.outbox().poll()) != null) {
                    if (item instanceof Outbound.Action a) {
                        boolean hold = park.test(a);
                        if (hold) {
                            synchronized (this) {
                                parked.add(a);
                            }
                        } else {
                            perform(a);
                        }
                    } else if (item instanceof Outbound.Cancel c) {
                        cancelled.add(key(c.agent(), c.actionId()));
                    } else if (item instanceof Outbound.Stop) {
                        stopAsked = true;
                    }
                }
                LogQueue.Batch lines = bridge.log().drainBatch(1000);
                String text = lines.text();
                for (int i = 0; i < lines.ends().length; i++) // ends count code points
                    transcript.append(String.format(Locale.ROOT, "%7.2f ", (now - START) / 1e9))
                            .append(text, text.offsetByCodePoints(0, i == 0 ? 0 : lines.ends()[i - 1]),
                            text.offsetByCodePoints(0, lines.ends()[i])).append('\n');
                now += rosPerStep;
                bridge.tick(now);
                boolean cameras = step++ % STEPS_PER_FRAME == 0;
                if (cameras)
                    synchronized (this) {
                        frame++;
                    }
                for (Robot r : robots.values())
                    perceive(r, cameras);
                Thread.sleep(STEP_MS);
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } catch (Throwable t) {
            failure = t;
        }
    }

    private static String key(String agent, int id) {
        return agent + "#" + id;
    }

    private void perceive(Robot r, boolean camera) {
        if (agents.arch(r.name) == null)
            return;
        double[] p = r.pose;
        agents.perceive(r.name, "odom", now, String.format(Locale.ROOT, "pos(%.3f,%.3f,%.4f)", p[0], p[1], p[2]));
        if (sharedFrame)
            agents.perceive(r.name, "localisation", now,
                    String.format(Locale.ROOT, "mapPose(%.3f,%.3f,%.4f)", p[0], p[1], p[2]));
        if (!r.camera || !camera)
            return;
        List<String> seen = new ArrayList<>();
        seen.add("cameraFrame(" + frame() + "," + now / 1_000_000 + ")");
        for (Robot other : robots.values()) {
            if (other == r)
                continue;
            double[] v = CameraFrames.view(p, other.pose);
            if (v[1] > 0.2 && v[1] < 6 && Math.abs(v[0]) < HALF_FOV && !(sideOnHidden && sideOn(p, other.pose)))
                seen.add(String.format(Locale.ROOT, "robot(%s,%.2f,%.3f,%.2f)", other.seenAs, v[0], v[1], v[2]));
        }
        agents.perceive(r.name, "vision_synth_robots", now, seen.toArray(String[]::new));
    }

    /** Does the action and answers it, as the robot's decomposers would. */
    private void perform(Outbound.Action a) {
        Robot r = robots.get(a.agent());
        String result = Protocol.OK;
        if (r != null) {
            switch (a.action()) {
            case "turn" -> r.pose[2] -= Math.toRadians(Double.parseDouble(a.parameters()[0]));
            case "move" -> result = move(r, Double.parseDouble(a.parameters()[0]));
            case "goto" -> driveTo(r, Double.parseDouble(a.parameters()[0]), Double.parseDouble(a.parameters()[1]));
            case "report_diagnosis" -> diagnoses.put(r.name, a.parameters()[0]);
            default -> {
            }
            }
        }
        synchronized (this) {
            done.add(a);
        }
        bridge.actions().event(a.agent(), Protocol.ACTION_FEEDBACK, new String[] { result, "" + a.actionId() });
    }

    /** A robot without a fault at (x, y) of its odometry (the world's frame), facing the way it drove. */
    private static void driveTo(Robot r, double x, double y) {
        double[] p = r.pose;
        if (Math.hypot(x - p[0], y - p[1]) > 1e-6)
            p[2] = Math.atan2(y - p[1], x - p[0]);
        p[0] = x;
        p[1] = y;
    }

    private static String move(Robot r, double d) {
        double[] p = r.pose;
        switch (r.fault) {
        case "right_actuator": // the left wheel alone: it turns clockwise, either way
            p[2] -= Math.toRadians(FAULT_TURN);
            return "bad_move";
        case "left_actuator":
            p[2] += Math.toRadians(FAULT_TURN);
            return "bad_move";
        case "both_actuators":
            return "no_progress";
        case "odometry": // it moves, its encoders say it does not
            p[0] += d * Math.cos(p[2]);
            p[1] += d * Math.sin(p[2]);
            return "no_progress";
        default:
            p[0] += d * Math.cos(p[2]);
            p[1] += d * Math.sin(p[2]);
            return Protocol.OK;
        }
    }
}
