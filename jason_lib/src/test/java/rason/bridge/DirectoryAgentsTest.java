package rason.bridge;

import rason.core.Protocol;
import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static rason.bridge.RunningAgents.await;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import jason.asSemantics.Agent;
import jason.asSemantics.Unifier;
import jason.asSyntax.ASSyntax;
import rason.infra.RasonLocalMAS;

/**
 * Real agents using Jason's .df_* actions: the directory facilitator runs
 * without a df agent (nothing called df is hosted or announced), registrations
 * are announced, and another robot's registrations reach .df_search and the
 * subscribers as provider(Agent, "service")[source(df)], told and untold.
 */
class DirectoryAgentsTest {

    private static final String KEY = "test-directory-key-0123456789abcdef0123456789abcdef";
    private static final String OTHER_MAS = "/robot7/rason_mas";

    private final Bridge bridge = new Bridge();
    private OtherRobot otherRobot;
    private RasonLocalMAS mas;

    @TempDir
    Path dir;

    @AfterEach
    void stop() throws Exception {
        bridge.shutdown(Protocol.SHUTDOWN);
        if (mas != null)
            mas.stopAgents(5000);
        bridge.detach();
        while (bridge.outbox().poll() != null) {
            // nothing of this test reaches the next one
        }
    }

    private void announceOtherRobot(boolean leaving, String[] dfAgents, String[] dfServices) {
        otherRobot.announce(new String[] { "far_painter" }, dfAgents, dfServices, leaving);
    }

    private Agent agent(String name) {
        return mas.getAg(name).getTS().getAg();
    }

    private boolean believes(String agent, String literal) {
        try {
            return agent(agent).believes(ASSyntax.parseLiteral(literal), new Unifier());
        } catch (Exception e) {
            throw new IllegalStateException(e);
        }
    }

    @Test
    void theFleetsRegistrationsReachSearchAndSubscribersWithoutADfAgent() throws Exception {
        bridge.fleet().setMasId("/robot6/rason_mas");
        otherRobot = new OtherRobot(bridge, OTHER_MAS, KEY);
        Files.writeString(dir.resolve("painter.asl"), "!start. +!start <- .df_register(\"paint_svc\").");
        Files.writeString(dir.resolve("boss.asl"), """
                !start.
                +!start <- .df_subscribe("paint_svc").
                +provider(A, S)[source(df)] <- .df_search("paint_svc", L); +found(L).
                -provider(A, S)[source(df)] <- +lost(A, S).
                """);
        Files.writeString(dir.resolve("p.mas2j"), "MAS p { agents: painter; boss; }");
        bridge.attach();
        mas = bridge.newMas();
        mas.load(dir.resolve("p.mas2j").toString());
        mas.create();
        mas.start();

        await("boss hears of painter", () -> believes("boss", "provider(painter, \"paint_svc\")[source(df)]"));
        await("the registration is announced", () -> bridge.outbox().poll() instanceof Outbound.Announce);
        assertArrayEquals(new String[] { "painter" }, bridge.rosChannel().announced().agents());
        assertArrayEquals(new String[] { "paint_svc" }, bridge.rosChannel().announced().services());
        List<String> hosted = List.of(bridge.agentNames());
        assertTrue(hosted.containsAll(List.of("boss", "painter")), hosted.toString());
        assertFalse(hosted.contains(rason.messaging.DirectoryFacilitator.DF_NAME), "no df among our agents: " + hosted);
        assertNull(mas.getAg(rason.messaging.DirectoryFacilitator.DF_NAME), "Jason's df agent was never made");
        assertFalse(bridge.fleet().names().allNames().contains(rason.messaging.DirectoryFacilitator.DF_NAME));

        announceOtherRobot(false, new String[] { "far_painter" }, new String[] { "paint_svc" });
        await("boss searches after hearing of far_painter", () -> believes("boss", "found([far_painter, painter])"));

        announceOtherRobot(true, new String[0], new String[0]);
        await("far_painter is untold", () -> believes("boss", "lost(far_painter, \"paint_svc\")"));
        assertFalse(believes("boss", "provider(far_painter, \"paint_svc\")"));
        assertTrue(believes("boss", "provider(painter, \"paint_svc\")[source(df)]"));
        assertTrue(bridge.fleet().directory().search("paint_svc").equals(List.of("painter")));
    }
}
