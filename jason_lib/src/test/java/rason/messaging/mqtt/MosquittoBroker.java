package rason.messaging.mqtt;

import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;

/**
 * A mosquitto broker of a test on 127.0.0.1, on a free port, with a configuration of its own
 * (anonymous clients, no persistence); the test is skipped if mosquitto is not installed.
 */
public final class MosquittoBroker implements AutoCloseable {

    private static final List<String> PLACES = List.of("/usr/sbin/mosquitto", "/usr/bin/mosquitto",
            "/usr/local/sbin/mosquitto");
    private static final long START_MS = 10_000;
    private static final int PORT_ATTEMPTS = 3;
    /** What mosquitto logs once its listeners are open: the port is this broker's, not another's. */
    private static final String RUNNING = " running";

    private final Process process;
    private final int port;

    private MosquittoBroker(Process process, int port) {
        this.process = process;
        this.port = port;
    }

    /** The binary, or null if there is none. */
    static Path binary() {
        for (String p : PLACES)
            if (Files.isExecutable(Path.of(p)))
                return Path.of(p);
        return null;
    }

    /**
     * Starts a broker (its configuration and log in dir) on a free port and waits until it takes
     * connections. make test runs other suites beside JUnit, with brokers and clients of their
     * own, so the port found free may be taken before mosquitto binds it: then it is tried again
     * on another.
     */
    public static MosquittoBroker start(Path dir) throws IOException, InterruptedException {
        return startOnAFreePort(dir, "allow_anonymous true\n");
    }

    private static MosquittoBroker startOnAFreePort(Path dir, String access) throws IOException, InterruptedException {
        for (int attempt = 1; ; attempt++) {
            try {
                return start(dir, freePort(), access);
            } catch (PortTaken e) {
                if (attempt == PORT_ATTEMPTS)
                    throw e;
            }
        }
    }

    /** A port of 127.0.0.1 nobody listens on now. */
    public static int freePort() throws IOException {
        try (ServerSocket s = new ServerSocket(0, 1, java.net.InetAddress.getLoopbackAddress())) {
            return s.getLocalPort();
        }
    }

    /** The same, on the given port (a broker that comes back where it was). */
    public static MosquittoBroker start(Path dir, int port) throws IOException, InterruptedException {
        return start(dir, port, "allow_anonymous true\n");
    }

    /**
     * A broker with TLS (a certificate for 127.0.0.1 that is its own authority, written to
     * dir/ca.pem) that takes user with password only.
     */
    public static MosquittoBroker startTls(Path dir, String user, String password)
            throws IOException, InterruptedException {
        run(dir, "openssl", "req", "-x509", "-newkey", "rsa:2048", "-nodes", "-keyout", "key.pem", "-out", "ca.pem",
                "-days", "1", "-subj", "/CN=127.0.0.1", "-addext", "subjectAltName=IP:127.0.0.1");
        run(dir, "mosquitto_passwd", "-c", "-b", "passwords", user, password);
        return startOnAFreePort(dir, "allow_anonymous false\npassword_file " + dir.resolve("passwords")
                + "\ncertfile " + dir.resolve("ca.pem") + "\nkeyfile " + dir.resolve("key.pem") + "\n");
    }

    private static void run(Path dir, String... command) throws IOException, InterruptedException {
        Process p;
        try {
            p = new ProcessBuilder(command).directory(dir.toFile()).redirectErrorStream(true)
                    .redirectOutput(dir.resolve(command[0] + ".log").toFile()).start();
        } catch (IOException e) {
            assumeTrue(false, command[0] + " is not installed: test skipped");
            throw e;
        }
        if (!p.waitFor(60, TimeUnit.SECONDS) || p.exitValue() != 0)
            throw new IllegalStateException(String.join(" ", command) + " failed: "
                    + Files.readString(dir.resolve(command[0] + ".log")));
    }

    private static MosquittoBroker start(Path dir, int port, String access) throws IOException, InterruptedException {
        Path bin = binary();
        assumeTrue(bin != null, "mosquitto is not installed (apt-get install -y mosquitto): MQTT tests skipped");
        Path conf = dir.resolve("mosquitto.conf");
        Files.writeString(conf, "listener " + port + " 127.0.0.1\n" + access + "persistence false\nset_tcp_nodelay true\n"
                // as this user: one started by root would become user mosquitto, who cannot read the test's files
                + "user " + System.getProperty("user.name") + "\n"
                + "log_dest stderr\nlog_type error\nlog_type warning\nlog_type notice\nlog_type information\n");
        Process p = new ProcessBuilder(bin.toString(), "-c", conf.toString())
                .redirectErrorStream(true).redirectOutput(dir.resolve("mosquitto.log").toFile()).start();
        MosquittoBroker broker = new MosquittoBroker(p, port);
        long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(START_MS);
        Path log = dir.resolve("mosquitto.log");
        while (!(Files.readString(log).contains(RUNNING) && broker.takesConnections())) {
            if (!p.isAlive() || System.nanoTime() > deadline) {
                broker.close();
                String said = Files.readString(log);
                if (said.contains("Address already in use"))
                    throw new PortTaken("port " + port + " was taken before mosquitto bound it: " + said);
                throw new IllegalStateException("mosquitto did not start on port " + port + ": " + said);
            }
            Thread.sleep(10); // polling the port, with the deadline above
        }
        return broker;
    }

    private boolean takesConnections() {
        try (Socket s = new Socket()) {
            s.connect(new InetSocketAddress("127.0.0.1", port), 200);
            return true;
        } catch (IOException e) {
            return false;
        }
    }

    /** Another process bound the port first. */
    static final class PortTaken extends IllegalStateException {
        PortTaken(String message) {
            super(message);
        }
    }

    public int port() {
        return port;
    }

    public String url() {
        return "tcp://127.0.0.1:" + port;
    }

    @Override
    public void close() throws InterruptedException {
        process.destroy();
        if (!process.waitFor(5, TimeUnit.SECONDS))
            process.destroyForcibly().waitFor(5, TimeUnit.SECONDS);
    }
}
