package rason.infra;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.jar.JarEntry;
import java.util.jar.JarOutputStream;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import jason.JasonException;
import jason.asSemantics.Agent;
import jason.asSemantics.Unifier;
import jason.asSyntax.ASSyntax;
import jason.util.Config;

import rason.bridge.Bridge;
import rason.core.Protocol;

/**
 * Includes resolve as a project means them, whatever the working directory
 * (Maven runs these tests in jason_lib/, never in the project's directory):
 * next to the including file, then the .mas2j's directory, then its source paths.
 */
class ProjectIncludeTest {

    private final Bridge bridge = new Bridge();

    @TempDir
    Path dir;

    private RasonLocalMAS mas;

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

    private void write(String relative, String text) throws Exception {
        Path p = dir.resolve(relative);
        Files.createDirectories(p.getParent());
        Files.writeString(p, text);
    }

    private Agent load(String mas2j) throws Exception {
        write("p.mas2j", mas2j);
        bridge.attach();
        mas = bridge.newMas();
        mas.load(dir.resolve("p.mas2j").toString());
        mas.create();
        return mas.getAg("a").getTS().getAg();
    }

    private static boolean believes(Agent ag, String literal) throws Exception {
        return ag.believes(ASSyntax.parseLiteral(literal), new Unifier());
    }

    @Test
    void theWorkingDirectoryIsNotTheProjects() {
        assertNotEquals(dir.toAbsolutePath().normalize(), Path.of("").toAbsolutePath().normalize());
    }

    @Test
    void aFileNextToTheIncludingOneIsFoundFirst() throws Exception {
        write("robots/a.asl", "{ include(\"common.asl\") }");
        write("robots/common.asl", "next_to_it.");
        write("common.asl", "in_project_dir.");
        Agent ag = load("MAS p { agents: a ./robots/a.asl; }");
        assertTrue(believes(ag, "next_to_it"));
        assertTrue(!believes(ag, "in_project_dir"));
    }

    @Test
    void thenTheProjectDirectoryThenItsSourcePaths() throws Exception {
        write("robots/a.asl", "{ include(\"top.asl\") } { include(\"lib.asl\") } { include(\"sub/deep.asl\") }");
        write("top.asl", "from_project_dir.");
        write("src/asl/lib.asl", "from_source_path.");
        write("src/asl/sub/deep.asl", "{ include(\"sibling.asl\") } from_subdirectory.");
        write("src/asl/sub/sibling.asl", "included_by_an_included_file.");
        Agent ag = load("MAS p { agents: a ./robots/a.asl; aslSourcePath: \"src/asl\"; }");
        for (String b : new String[] { "from_project_dir", "from_source_path", "from_subdirectory",
                "included_by_an_included_file" })
            assertTrue(believes(ag, b), b);
    }

    @Test
    void anAgentsOwnSourceMayBeInASourcePath() throws Exception {
        write("src/asl/a.asl", "own_source.");
        Agent ag = load("MAS p { agents: a; aslSourcePath: \"src/asl\"; }");
        assertTrue(believes(ag, "own_source"));
    }

    @Test
    void anIncludeIntoANamespaceKeepsItsNamespace() throws Exception {
        write("robots/a.asl", "{ include(\"counter.asl\", cnt) }");
        write("robots/counter.asl", "value(3).");
        Agent ag = load("MAS p { agents: a ./robots/a.asl; }");
        assertTrue(believes(ag, "cnt::value(3)"));
        assertTrue(!believes(ag, "value(3)"));
    }

    @Test
    void theIncludeActionResolvesTheSameWay() throws Exception {
        write("robots/a.asl", "!load. +!load <- .include(\"later.asl\"); +loaded.");
        write("robots/later.asl", "from_later.");
        Agent ag = load("MAS p { agents: a ./robots/a.asl; }");
        mas.start();
        long deadline = System.currentTimeMillis() + 10_000;
        while (!believes(ag, "loaded") && System.currentTimeMillis() < deadline)
            Thread.sleep(5);
        assertTrue(believes(ag, "loaded"));
        assertTrue(believes(ag, "from_later"));
    }

    @Test
    void aMissingIncludeStopsTheProjectNamingEveryPathTried() throws Exception {
        write("robots/a.asl", "{ include(\"nowhere.asl\") } +!g <- true.");
        write("p.mas2j", "MAS p { agents: a ./robots/a.asl; aslSourcePath: \"lib\"; }");
        mas = bridge.newMas();
        Exception e = assertThrows(JasonException.class, () -> {
            mas.load(dir.resolve("p.mas2j").toString());
            mas.create();
        });
        String real = dir.toRealPath().toString();
        for (String p : new String[] { "agent 'a'", "'nowhere.asl' not found", real + "/robots/nowhere.asl",
                real + "/nowhere.asl", real + "/lib/nowhere.asl" })
            assertTrue(e.getMessage().contains(p), e.getMessage() + " should say " + p);
    }

    private static boolean hasPlanFor(Agent ag, String trigger) throws Exception {
        return ag.getPL().hasCandidatePlan(ASSyntax.parseTrigger(trigger));
    }

    @Test
    void aJasonJarPathIsReadFromJasonsJar() throws Exception {
        write("a.asl", "{ include(\"$jasonJar/test/jason/inc/test_assert.asl\") }");
        Agent ag = load("MAS p { agents: a; }");
        assertTrue(hasPlanFor(ag, "+!assert_equals(1,1)"), "test_assert.asl's plans are missing");
    }

    @Test
    void aSourcePathInJasonsJarIsSearchedForIncludesAndAgents() throws Exception {
        write("a.asl", "{ include(\"test_assert.asl\") }");
        Agent ag = load("MAS p { agents: a; mock_agent; aslSourcePath: \"lib\"; \"$jasonJar/test/jason/inc\"; }");
        assertTrue(hasPlanFor(ag, "+!assert_equals(1,1)"), "test_assert.asl's plans are missing");
        Agent mock = mas.getAg("mock_agent").getTS().getAg();
        assertTrue(hasPlanFor(mock, "+jag_sleeping"), "mock_agent.asl was not loaded from Jason's jar");
    }

    @Test
    void aFileIncludedFromAJarIncludesItsNeighboursInTheJar() throws Exception {
        Path jar = dir.resolve("lib.jar");
        try (JarOutputStream out = new JarOutputStream(Files.newOutputStream(jar))) {
            out.putNextEntry(new JarEntry("asl/outer.asl"));
            out.write("{ include(\"inner.asl\") } from_outer.".getBytes(StandardCharsets.UTF_8));
            out.putNextEntry(new JarEntry("asl/inner.asl"));
            out.write("from_inner.".getBytes(StandardCharsets.UTF_8));
        }
        write("a.asl", "{ include(\"jar:file:" + jar.toRealPath() + "!/asl/outer.asl\") }");
        Agent ag = load("MAS p { agents: a; }");
        assertTrue(believes(ag, "from_outer"));
        assertTrue(believes(ag, "from_inner"));
    }

    @Test
    void aMissingFileInJasonsJarStopsTheProjectNamingWhereItLooked() throws Exception {
        write("a.asl", "{ include(\"$jasonJar/test/jason/inc/no_such.asl\") }");
        write("p.mas2j", "MAS p { agents: a; }");
        mas = bridge.newMas();
        Exception e = assertThrows(JasonException.class, () -> {
            mas.load(dir.resolve("p.mas2j").toString());
            mas.create();
        });
        String jar = Config.get().getPackage("jasonJar").getAbsolutePath();
        for (String p : new String[] { "agent 'a'", "'$jasonJar/test/jason/inc/no_such.asl' not found",
                "jar:file:" + jar + "!/test/jason/inc/no_such.asl" })
            assertTrue(e.getMessage().contains(p), e.getMessage() + " should say " + p);
    }

    @Test
    void aSourceTheWorkingDirectoryNamesTooKeepsItsNameAsWritten() throws Exception {
        // Jason's runner, run in the project's folder, shows sources as the program names them
        Path inWorkingDir = Files.createTempDirectory(Path.of("target"), "cwd");
        try {
            Path relative = Path.of("").toAbsolutePath().relativize(inWorkingDir.toAbsolutePath());
            Files.writeString(inWorkingDir.resolve("a.asl"), "{ include(\"common.asl\") }");
            Files.writeString(inWorkingDir.resolve("common.asl"), "next_to_it.");
            String cwd = Path.of("").toAbsolutePath().toString();
            Agent ag = load("MAS p { agents: a ./" + relative + "/a.asl; aslSourcePath: \"" + cwd + "\"; }");
            assertEquals("file:./" + relative + "/a.asl", ag.getASLSrc());
            assertTrue(believes(ag, "next_to_it"), "the include next to it is found from the working directory");
        } finally {
            for (String f : new String[] { "a.asl", "common.asl" })
                Files.deleteIfExists(inWorkingDir.resolve(f));
            Files.deleteIfExists(inWorkingDir);
        }
    }

    @Test
    void aSourceTheWorkingDirectoryDoesNotNameGetsItsFullPath() throws Exception {
        write("robots/a.asl", "x.");
        Agent ag = load("MAS p { agents: a ./robots/a.asl; }");
        assertEquals("file:" + dir.toRealPath().resolve("robots/a.asl"), ag.getASLSrc());
    }
}
