package rason.messaging.mqtt;

import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLongArray;
import java.util.concurrent.locks.LockSupport;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import rason.core.Clock;
import rason.messaging.FleetKeys;
import rason.messaging.WireMessage;

/**
 * {@code java -cp ... rason.messaging.mqtt.SimulatedFleet --url tcp://HOST:PORT --key-file F
 * --robots N}: N {@link SimulatedRobot}s in one JVM (mas ids {@code /sim/robotI/rason_mas},
 * agents {@code simI}), driven by lines on stdin, answering on stdout; times are ms on this
 * machine's monotonic clock (the clock of {@code rason.time_ms}).
 * <ul>
 * <li>{@code ready N} once all are connected;</li>
 * <li>{@code kill I J ...}: those robots' connections end as a dead process's would (the broker
 *     sends their wills); {@code killed I T} for each, T taken right before;</li>
 * <li>{@code load MAS AGENT RATE SECONDS}: robot 0 sends {@code achieve echo(Run, Seq)} to AGENT
 *     of MAS at RATE a second for SECONDS (on a fixed schedule), and times each answer
 *     {@code achieve echoed(Run, Seq)} from the time its message was due:
 *     {@code load RUN RATE SENT SEND_SECONDS ms ms ...} (unanswered ones left out);</li>
 * <li>{@code leave}: every robot leaves cleanly, then {@code left} and the program ends.</li>
 * </ul>
 * For benchmarks of the fleet channel (rason_bench's fleet part).
 */
public final class SimulatedFleet {

    /** How long answers are awaited after the last message of a load run. */
    static final long ANSWER_GRACE_NANOS = 3_000_000_000L;
    private static final Pattern ECHOED = Pattern.compile("echoed\\((\\d+),\\s*(\\d+)\\)");

    private final List<SimulatedRobot> robots = new ArrayList<>();
    private final PrintStream out;
    private volatile LoadRun load;
    private int runs = 0;

    /** One load run's schedule and answers (ns on the wall clock, -1 while unanswered). */
    private record LoadRun(int run, long[] due, AtomicLongArray answered) {
    }

    SimulatedFleet(PrintStream out) {
        this.out = out;
    }

    public static void main(String[] args) throws Exception {
        Map<String, String> a = options(args);
        MqttSettings settings = new MqttSettings(a.getOrDefault("url", MqttSettings.DEFAULT_URL),
                a.getOrDefault("prefix", MqttSettings.DEFAULT_PREFIX),
                Long.parseLong(a.getOrDefault("ttl", "" + MqttSettings.DEFAULT_TTL_SECONDS)),
                (long) (Double.parseDouble(a.getOrDefault("period", "0.5")) * 1e9), "", "", "");
        FleetKeys keys = FleetKeys.load(Path.of(required(a, "key-file")));
        int n = Integer.parseInt(a.getOrDefault("robots", "1"));
        PrintStream out = new PrintStream(System.out, true, StandardCharsets.UTF_8);
        SimulatedFleet fleet = new SimulatedFleet(out);
        ScheduledExecutorService ticker = Executors.newScheduledThreadPool(2, r -> {
            Thread t = new Thread(r, "sim-heartbeats");
            t.setDaemon(true);
            return t;
        });
        for (int i = 0; i < n; i++) {
            final int index = i;
            fleet.robots.add(new SimulatedRobot("/sim/robot" + i + "/rason_mas", "sim" + i, keys, settings, ticker,
                    m -> fleet.received(index, m)));
        }
        CompletableFuture.allOf(fleet.robots.stream().map(SimulatedRobot::start).toArray(CompletableFuture[]::new))
                .get(60, TimeUnit.SECONDS);
        out.println("ready " + n);
        BufferedReader in = new BufferedReader(new InputStreamReader(System.in, StandardCharsets.UTF_8));
        String line;
        while ((line = in.readLine()) != null) {
            if (!fleet.command(line.trim().split("\\s+")))
                break;
        }
        CompletableFuture.allOf(fleet.robots.stream().map(SimulatedRobot::leave).toArray(CompletableFuture[]::new))
                .get(10, TimeUnit.SECONDS);
        out.println("left");
        System.exit(0);
    }

    /** --name value pairs. */
    static Map<String, String> options(String[] args) {
        Map<String, String> a = new HashMap<>();
        for (int i = 0; i + 1 < args.length; i += 2) {
            if (!args[i].startsWith("--"))
                throw new IllegalArgumentException("expected --name value, got " + args[i]);
            a.put(args[i].substring(2), args[i + 1]);
        }
        return a;
    }

    private static String required(Map<String, String> a, String name) {
        String v = a.get(name);
        if (v == null)
            throw new IllegalArgumentException("--" + name + " is required");
        return v;
    }

    /** One command; false to stop. */
    boolean command(String[] words) {
        switch (words[0]) {
        case "kill" -> {
            for (int i = 1; i < words.length; i++) {
                int k = Integer.parseInt(words[i]);
                out.println("killed " + k + " " + millis(Clock.WALL.nanos()));
                robots.get(k).abandon();
            }
        }
        case "load" -> load(words[1], words[2], Double.parseDouble(words[3]), Double.parseDouble(words[4]));
        case "leave" -> {
            return false;
        }
        case "" -> {
        }
        default -> out.println("unknown command " + words[0]);
        }
        return true;
    }

    private void load(String mas, String agent, double rate, double seconds) {
        int count = Math.max(1, (int) Math.round(rate * seconds));
        long period = (long) (1e9 / rate);
        LoadRun run = new LoadRun(++runs, new long[count], new AtomicLongArray(count));
        for (int i = 0; i < count; i++)
            run.answered().set(i, -1);
        long start = Clock.WALL.nanos();
        for (int i = 0; i < count; i++)
            run.due()[i] = start + i * period;
        load = run;
        SimulatedRobot sender = robots.get(0);
        for (int i = 0; i < count; i++) {
            long wait = run.due()[i] - Clock.WALL.nanos();
            if (wait > 0)
                LockSupport.parkNanos(wait);
            sender.send(mas, agent, "achieve", "echo(" + run.run() + "," + i + ")", "");
        }
        long sendEnd = Clock.WALL.nanos();
        long deadline = sendEnd + ANSWER_GRACE_NANOS;
        while (Clock.WALL.nanos() < deadline && unanswered(run) > 0)
            LockSupport.parkNanos(10_000_000L);
        StringBuilder line = new StringBuilder(String.format(Locale.ROOT, "load %d %s %d %.3f", run.run(),
                rate, count, (sendEnd - start) / 1e9));
        for (int i = 0; i < count; i++) {
            long t = run.answered().get(i);
            if (t >= 0)
                line.append(' ').append(String.format(Locale.ROOT, "%.3f", (t - run.due()[i]) / 1e6));
        }
        out.println(line);
    }

    private static int unanswered(LoadRun run) {
        int n = 0;
        for (int i = 0; i < run.answered().length(); i++)
            if (run.answered().get(i) < 0)
                n++;
        return n;
    }

    /** An agent message reached robot index: an answer of the current load run is timed. */
    void received(int index, WireMessage m) {
        long now = Clock.WALL.nanos();
        LoadRun run = load;
        Matcher e = ECHOED.matcher(m.content());
        if (run == null || !e.matches() || Integer.parseInt(e.group(1)) != run.run())
            return;
        int seq = Integer.parseInt(e.group(2));
        if (seq < run.answered().length())
            run.answered().compareAndSet(seq, -1, now);
    }

    private static String millis(long nanos) {
        return String.format(Locale.ROOT, "%.3f", nanos / 1e6);
    }
}
