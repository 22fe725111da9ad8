package rason.infra;

import static org.junit.jupiter.api.Assertions.assertDoesNotThrow;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.io.ByteArrayInputStream;
import java.nio.charset.StandardCharsets;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

import jason.JasonException;
import jason.asSemantics.Agent;
import jason.mas2j.AgentParameters;
import jason.mas2j.MAS2JProject;

/**
 * What a .mas2j asks that rason_mas cannot give is refused before any agent runs, saying what
 * and why: another infrastructure, a window, a class that does not load from the class path.
 */
class ProjectCheckTest {

    private static MAS2JProject parse(String mas2j) throws Exception {
        MAS2JProject p = new jason.mas2j.parser.mas2j(
                new ByteArrayInputStream(mas2j.getBytes(StandardCharsets.UTF_8))).mas();
        p.setupDefault();
        return p;
    }

    private static String projectRefusal(String mas2j) throws Exception {
        MAS2JProject p = parse(mas2j);
        return assertThrows(JasonException.class, () -> ProjectCheck.checkProject(p)).getMessage();
    }

    private static AgentParameters agent(String declaration) throws Exception {
        MAS2JProject p = parse("MAS t { agents: " + declaration + "; }");
        ProjectCheck.checkProject(p);
        return p.getAgents().get(0);
    }

    private static String agentRefusal(String declaration) throws Exception {
        AgentParameters ap = agent(declaration);
        return assertThrows(JasonException.class, () -> ProjectCheck.checkAgent(ap)).getMessage();
    }

    @ParameterizedTest
    @ValueSource(strings = {
        "MAS t { agents: a; }",
        "MAS t { infrastructure: Local agents: a; }",
        "MAS t { infrastructure: Local(pool, 4) agents: a; }",
        "MAS t { executionControl: jason.control.ExecutionControl agents: a; }",
    })
    void what_jasons_local_infrastructure_runs_headless_passes(String mas2j) throws Exception {
        MAS2JProject p = parse(mas2j);
        assertDoesNotThrow(() -> ProjectCheck.checkProject(p));
        assertDoesNotThrow(() -> ProjectCheck.checkAgent(p.getAgents().get(0)));
    }

    @Test
    void another_infrastructure_is_refused_naming_it() throws Exception {
        assertEquals("infrastructure Jade is not supported: rason_mas runs Jason's Local infrastructure and reaches"
                + " the agents of other processes through its fleet (remove the infrastructure line)",
                projectRefusal("MAS t { infrastructure: Jade agents: a; }"));
    }

    @Test
    void an_environment_not_on_the_class_path_is_named_with_where_to_put_it() throws Exception {
        assertEquals("environment town.Bell not found (" + ProjectCheck.CLASS_PATH_HINT + ")",
                projectRefusal("MAS t { environment: town.Bell(7) agents: a; }"));
    }

    @Test
    void an_environment_class_that_is_no_environment_is_refused() throws Exception {
        assertEquals("environment java.lang.String is not a jason.environment.Environment",
                projectRefusal("MAS t { environment: java.lang.String agents: a; }"));
    }

    @Test
    void jasons_debugging_window_is_refused() throws Exception {
        assertEquals("executionControl jason.control.ExecutionControlGUI is a window, and rason_mas runs headless"
                + " (no display on a robot)",
                projectRefusal("MAS t { executionControl: jason.control.ExecutionControlGUI agents: a; }"));
    }

    @Test
    void a_missing_execution_control_is_named() throws Exception {
        assertEquals("executionControl my.Control not found (" + ProjectCheck.CLASS_PATH_HINT + ")",
                projectRefusal("MAS t { executionControl: my.Control agents: a; }"));
    }

    @Test
    void an_agents_missing_classes_are_named_with_the_agent() throws Exception {
        assertEquals("agent 'a': beliefBaseClass mylib.CountingBB not found (" + ProjectCheck.CLASS_PATH_HINT + ")",
                agentRefusal("a beliefBaseClass mylib.CountingBB"));
        assertEquals("agent 'a': agentClass mylib.TaggedAgent not found (" + ProjectCheck.CLASS_PATH_HINT + ")",
                agentRefusal("a agentClass mylib.TaggedAgent"));
        assertEquals("agent 'a': agentArchClass jason.asSemantics.Agent is not a jason.architecture.AgArch",
                agentRefusal("a agentArchClass jason.asSemantics.Agent"));
    }

    @Test
    void the_window_mind_inspector_is_refused_and_the_others_pass() throws Exception {
        assertEquals("agent 'a': mindinspector=\"gui(cycle,html)\" is a window, and rason_mas runs headless (no display"
                + " on a robot): use web(...), served on loopback, or file(...)",
                agentRefusal("a [mindinspector=\"gui(cycle,html)\"]"));
        AgentParameters web = agent("a [mindinspector=\"web(cycle,html,history)\"]");
        assertDoesNotThrow(() -> ProjectCheck.checkAgent(web));
        AgentParameters file = agent("a [mindinspector=\"file(cycle,xml,log)\"]");
        assertDoesNotThrow(() -> ProjectCheck.checkAgent(file));
    }

    private static Agent parsed(String asl) throws Exception {
        Agent ag = new Agent();
        ag.initAg();
        ag.parseAS(new ByteArrayInputStream(asl.getBytes(StandardCharsets.UTF_8)), "t.asl");
        ag.addInitialBelsInBB(); // rules too, as when Jason loads an agent
        return ag;
    }

    @Test
    void internal_actions_jason_could_not_load_are_named_from_bodies_contexts_and_rules() throws Exception {
        Agent ag = parsed("+!g : mylib.ok(1) <- .print(x); if (true) { mylib.nope(2) }; act(1).\n"
                + "r(X) :- other.rule(X).\n");
        assertEquals("agent 'a': internal actions mylib.nope, mylib.ok, other.rule not found ("
                + ProjectCheck.CLASS_PATH_HINT + ")",
                assertThrows(JasonException.class, () -> ProjectCheck.checkInternalActions("a", ag)).getMessage());
    }

    @Test
    void loaded_internal_actions_actions_lists_and_functions_pass() throws Exception {
        Agent ag = parsed("+!g(L) : .length(L, N) & N > 1 <- rason.time_ms(T); X = math.abs(-1) + 2.5;"
                + " move(1, [a, b, c]); .send(bob, tell, hi(\"a.b\")); !g([1, 2]).\n");
        assertDoesNotThrow(() -> ProjectCheck.checkInternalActions("a", ag));
    }
}
