package rason.infra;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.io.InputStream;
import java.net.URL;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import jason.asSemantics.TransitionSystem;
import jason.runtime.SourcePath;
import jason.util.Config;

/** Jason's configuration under Rason is completed as Jason's runner completes it. */
class RasonConfigTest {

    @TempDir
    Path home;

    @Test
    void jasonJarIsTheJarJasonRunsFrom() throws Exception {
        Config config = RasonConfig.install();
        File jar = new File(TransitionSystem.class.getProtectionDomain().getCodeSource().getLocation().toURI());
        assertEquals(jar.getCanonicalFile(), config.getPackage(Config.JASON_JAR).getCanonicalFile());
        assertEquals(jar.getCanonicalFile(), new File(config.getJasonJar()).getCanonicalFile());
    }

    @Test
    void aJasonJarPathIsAFileInsideThatJar() throws Exception {
        RasonConfig.install();
        String url = new SourcePath().fixPath("$jasonJar/test/jason/inc/test_assert.asl");
        assertTrue(url.startsWith("jar:file:"), url);
        try (InputStream in = new URL(url).openStream()) {
            assertTrue(new String(in.readAllBytes(), StandardCharsets.UTF_8).contains("+!assert_equals"));
        }
    }

    @Test
    void jasonsDefaultsAreSetAndNoWebMindInspectorStartsByItself() {
        Config config = RasonConfig.install();
        assertTrue(config instanceof RasonConfig);
        assertEquals("true", config.getProperty(Config.SHORT_UNNAMED_VARS));
        assertEquals("2", config.getProperty(Config.NB_TH_SCH));
        assertEquals("false", config.getProperty(Config.START_WEB_MI));
        assertEquals(LoopbackMindInspector.class.getName(), config.getMindInspectorWebServerClassName());
    }

    @Test
    void renamedVariablesAreShortAsUnderJasonsRunner() throws Exception {
        String out = probe();
        assertTrue(out.matches("(?s).*renamed=_[0-9]+\\s.*"), out);
        assertTrue(out.contains("applied=true"), out);
    }

    @Test
    void theCheckSeesJasonTermsUsedBeforeTheConfiguration() throws Exception {
        String out = probe("late");
        assertTrue(out.matches("(?s).*renamed=_[0-9]+Named\\s.*"), out);
        assertTrue(out.contains("applied=false"), out);
    }

    /** Runs {@link UnnamedVarsProbe} in a JVM of its own, with no Jason settings files of the user's. */
    private String probe(String... args) throws Exception {
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        List<String> cmd = new ArrayList<>(List.of(java, "-Djava.awt.headless=true",
                "-Duser.home=" + home, "-cp", System.getProperty("java.class.path"),
                UnnamedVarsProbe.class.getName()));
        cmd.addAll(List.of(args));
        Process p = new ProcessBuilder(cmd).directory(home.toFile()).redirectErrorStream(true).start();
        byte[] out = p.getInputStream().readAllBytes();
        assertTrue(p.waitFor(60, TimeUnit.SECONDS), "the probe did not end");
        assertEquals(0, p.exitValue(), new String(out, StandardCharsets.UTF_8));
        return new String(out, StandardCharsets.UTF_8);
    }
}
