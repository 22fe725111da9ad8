package rason.bridge;

import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import jason.JasonException;
import rason.infra.RasonLocalMAS;

/** A project with a misspelt class, a bad trust option or an agent Jason cannot create does not start. */
class ProjectChecksTest {

    private final Bridge bridge = new Bridge();

    @TempDir
    Path dir;

    private RasonLocalMAS mas;

    @AfterEach
    void stop() throws Exception {
        if (mas != null)
            mas.stopAgents(5000);
    }

    private String refusal(String agents) throws Exception {
        Files.writeString(dir.resolve("ok.asl"), "!start. +!start <- +started.");
        Files.writeString(dir.resolve("broken.asl"), "+!start <- .print(\"x\"");
        Files.writeString(dir.resolve("p.mas2j"), "MAS p { agents: " + agents + " }");
        mas = bridge.newMas();
        Exception e = assertThrows(JasonException.class, () -> {
            mas.load(dir.resolve("p.mas2j").toString());
            mas.create();
        });
        return e.getMessage();
    }

    private static void says(String message, String... parts) {
        for (String p : parts)
            assertTrue(message.contains(p), "'" + message + "' should say " + p);
    }

    @Test
    void aMisspeltArchitectureClassIsFatal() throws Exception {
        says(refusal("a ok.asl agentArchClass rason.RosAgArk;"), "agent 'a'", "agentArchClass rason.RosAgArk not found");
    }

    @Test
    void anArchitectureThatIsNoArchitectureIsFatal() throws Exception {
        says(refusal("a ok.asl agentArchClass java.lang.String;"), "java.lang.String is not a jason.architecture.AgArch");
    }

    @Test
    void aMisspeltAgentOrBeliefBaseClassIsFatal() throws Exception {
        says(refusal("a ok.asl agentClass my.Agnt;"), "agentClass my.Agnt not found");
        says(refusal("a ok.asl beliefBaseClass my.Base;"), "beliefBaseClass my.Base not found");
    }

    @Test
    void anUnknownOrMalformedTrustOptionIsFatal() throws Exception {
        says(refusal("a ok.asl [trust_tellhow=all];"), "trust_tellhow", "tellHow");
        says(refusal("a ok.asl [trust_achieve=\"faulty, Helper\"];"), "trust_achieve", "'Helper'");
    }

    @Test
    void anAgentJasonCannotCreateStopsTheProjectNamingIt() throws Exception {
        says(refusal("a ok.asl; b broken.asl;"), "agent b could not be created");
        says(refusal("c broken.asl #2;"), "agents c1, c2 could not be created");
    }
}
