package rason.messaging.mqtt;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;

/**
 * A TCP proxy to a broker on 127.0.0.1 that can go quiet: after {@link #blackHole()} it drops
 * every byte both ways but keeps the connections open, as a link that fails without either end
 * seeing a close; after {@link #cut()} the connections are closed. {@link #stallAllBut} holds the bytes
 * instead, as a TCP stream stalls on a lost segment, except on the connections whose client id
 * contains a marker: one connection of a client stalls, another does not; {@link #heal} lets them on.
 */
public final class BlackHoleProxy implements AutoCloseable {

    private final ServerSocket server;
    private final int target;
    private final List<Socket> sockets = new CopyOnWriteArrayList<>();
    private volatile boolean dropping = false;
    private volatile String spared = null; // a client id part whose connections keep flowing
    private final Object stall = new Object();
    private volatile boolean stalled = false; // guarded by stall for the waits

    /** Whether one connection was opened by a client whose id contains the spared marker. */
    private static final class Link {
        volatile String firstBytes = "";
    }

    public BlackHoleProxy(int targetPort) throws IOException {
        this.target = targetPort;
        this.server = new ServerSocket(0, 50, InetAddress.getLoopbackAddress());
        Thread accept = new Thread(this::acceptLoop, "proxy-accept");
        accept.setDaemon(true);
        accept.start();
    }

    public String url() {
        return "tcp://127.0.0.1:" + server.getLocalPort();
    }

    /** From now on nothing passes, either way, on any connection. */
    public void blackHole() {
        dropping = true;
    }

    /** From now on what is sent waits, on every connection but those of a client id containing marker. */
    public void stallAllBut(String marker) {
        spared = marker;
        stalled = true;
    }

    /** What waited goes on, in order. */
    public void heal() {
        synchronized (stall) {
            stalled = false;
            stall.notifyAll();
        }
    }

    /** Closes every connection and takes no new one: both ends see the link end. */
    public void cut() throws IOException {
        close();
    }

    private void acceptLoop() {
        while (!server.isClosed()) {
            try {
                Socket in = server.accept();
                Socket out = new Socket(InetAddress.getLoopbackAddress(), target);
                sockets.add(in);
                sockets.add(out);
                Link link = new Link();
                pump(in, out, link, true);
                pump(out, in, link, false);
            } catch (IOException e) {
                return; // closed
            }
        }
    }

    private void pump(Socket from, Socket to, Link link, boolean fromClient) {
        Thread t = new Thread(() -> {
            byte[] buf = new byte[8192];
            try (InputStream i = from.getInputStream(); OutputStream o = to.getOutputStream()) {
                int n;
                while ((n = i.read(buf)) >= 0) {
                    if (fromClient && link.firstBytes.isEmpty()) // the CONNECT, with the client id
                        link.firstBytes = new String(buf, 0, n, java.nio.charset.StandardCharsets.ISO_8859_1);
                    String marker = spared;
                    if (stalled && !(marker != null && link.firstBytes.contains(marker)))
                        synchronized (stall) {
                            while (stalled)
                                stall.wait();
                        }
                    if (!dropping) {
                        o.write(buf, 0, n);
                        o.flush();
                    }
                }
            } catch (IOException e) {
                // one end closed
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }, "proxy-pump");
        t.setDaemon(true);
        t.start();
    }

    @Override
    public void close() throws IOException {
        server.close();
        for (Socket s : sockets)
            s.close();
    }
}
