package rason.infra;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static rason.bridge.RunningAgents.await;

import java.io.InputStream;
import java.lang.reflect.Field;
import java.net.HttpURLConnection;
import java.net.URL;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;

import com.sun.net.httpserver.HttpServer;

import jason.architecture.MindInspectorWeb;
import jason.architecture.MindInspectorWebImpl;
import rason.bridge.Bridge;
import rason.bridge.RunningAgents;

/** Jason's web mind inspector, asked for by the .mas2j option, served on loopback on a free port. */
class LoopbackMindInspectorTest {

    private final Bridge bridge = new Bridge();

    @RegisterExtension
    final RunningAgents agents = new RunningAgents(bridge);

    @TempDir
    Path dir;

    @Test
    void servesTheAgentOnLoopbackOnAFreePortAndStopsWithTheAgents() throws Exception {
        agents.start(dir, "inspected", "likes(tea).\n", "[mindinspector=\"web(cycle,html,no_history)\"]");
        await("the inspector runs", () -> !bridge.mind().inspectorUrl().isEmpty());
        String url = bridge.mind().inspectorUrl();
        assertTrue(url.startsWith("http://127.0.0.1:"), url);
        assertTrue(!url.endsWith(":3272"), "not Jason's fixed port: " + url);

        Field f = MindInspectorWebImpl.class.getDeclaredField("httpServer");
        f.setAccessible(true);
        HttpServer server = (HttpServer) f.get(MindInspectorWeb.get());
        assertTrue(server.getAddress().getAddress().isLoopbackAddress(), "bound to " + server.getAddress());

        await("the agent is listed", () -> get(url + "/agents").contains("inspected"));
        await("its beliefs are shown", () -> get(url + "/agent-mind/inspected").contains("likes"));

        agents.stop();
        assertEquals("", bridge.mind().inspectorUrl());
    }

    @Test
    void noOptionNoInspector() throws Exception {
        agents.start(dir, "plain", "ready.\n");
        await("started", () -> RunningAgents.believes(agents.arch("plain"), "ready"));
        assertEquals("", bridge.mind().inspectorUrl());
    }

    private static String get(String url) {
        try {
            HttpURLConnection c = (HttpURLConnection) new URL(url).openConnection();
            c.setConnectTimeout(2000);
            c.setReadTimeout(2000);
            try (InputStream in = c.getInputStream()) {
                return new String(in.readAllBytes(), StandardCharsets.UTF_8);
            }
        } catch (Exception e) {
            return "";
        }
    }
}
