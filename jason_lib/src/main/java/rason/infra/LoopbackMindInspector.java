package rason.infra;

import java.lang.reflect.Field;
import java.lang.reflect.Method;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.logging.Level;
import java.util.logging.Logger;

import com.sun.net.httpserver.HttpServer;

import jason.architecture.MindInspectorWeb;
import jason.architecture.MindInspectorWebImpl;

/**
 * Jason's web mind inspector, served on the loopback address on a port the system
 * picks, instead of on every interface from port 3272 up: several robots' processes
 * on one machine never clash, and nobody on the network reads an agent's mind.
 * Everything else (pages, histories) is Jason's: its server is made here and handed to
 * Jason's implementation, whose fields and page registrations are private.
 */
public class LoopbackMindInspector extends MindInspectorWebImpl {

    private static final Logger logger = Logger.getLogger("rason.infra");
    private ExecutorService pool;

    @Override
    public synchronized String startHttpServer() {
        try {
            HttpServer server = HttpServer.create(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0), 0);
            pool = Executors.newCachedThreadPool(r -> {
                Thread t = new Thread(r, "rason_mind_inspector");
                t.setDaemon(true); // never holds the JVM open
                return t;
            });
            server.setExecutor(pool);
            Field field = MindInspectorWebImpl.class.getDeclaredField("httpServer");
            field.setAccessible(true);
            field.set(this, server);
            httpServerPort = server.getAddress().getPort();
            String url = "http://127.0.0.1:" + httpServerPort;
            httpServerURL = url; // Jason's pages are registered under it
            for (String page : new String[] { "registerRootBrowserView", "registerAgentsBrowserView" }) {
                Method m = MindInspectorWebImpl.class.getDeclaredMethod(page);
                m.setAccessible(true);
                m.invoke(this);
            }
            Method agView = MindInspectorWebImpl.class.getDeclaredMethod("registerAgView", String.class);
            agView.setAccessible(true);
            agView.invoke(this, "no_ag");
            server.start();
            logger.info("Jason's mind inspector is on " + url + " (loopback only)");
            return url;
        } catch (Exception e) {
            httpServerURL = null;
            logger.log(Level.SEVERE, "Jason's mind inspector could not start: " + e);
            return null;
        }
    }

    @Override
    public void stoptHttpServer() {
        httpServerURL = null;
        super.stoptHttpServer();
        if (pool != null)
            pool.shutdownNow();
    }

    /** Where the inspector of this process is served, "" when no agent asked for it. */
    public static String url() {
        String url = MindInspectorWeb.getURL(); // Jason keeps the one inspector of the process
        return url == null ? "" : url;
    }
}
