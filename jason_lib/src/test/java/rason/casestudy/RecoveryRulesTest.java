package rason.casestudy;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.Iterator;
import java.util.List;

import org.junit.jupiter.api.Test;

import jason.architecture.AgArch;
import jason.asSemantics.Agent;
import jason.asSemantics.TransitionSystem;
import jason.asSemantics.Unifier;
import jason.asSyntax.ASSyntax;
import jason.asSyntax.Literal;
import jason.asSyntax.LogicalFormula;
import jason.asSyntax.NumberTerm;
import jason.asSyntax.directives.DirectiveProcessor;
import rason.infra.ProjectInclude;

/**
 * The rules of the case study's recovery plans (src/rason/agents/case_study: poses.asl,
 * faulty_recovery.asl), evaluated by Jason itself on the files the robots run.
 */
class RecoveryRulesTest {

    private static final Path AGENTS = Path.of("..", "src", "rason", "agents", "case_study").toAbsolutePath().normalize();
    private static final double EPS = 1e-9;

    private static Agent load(String... files) throws Exception {
        // as rason_mas does: includes are found next to the including file
        DirectiveProcessor.registerDirective("include", ProjectInclude.class);
        ((ProjectInclude) DirectiveProcessor.getDirective("include")).setProject(AGENTS.toFile(), List.of());
        Agent ag = new Agent();
        new TransitionSystem(ag, null, null, new AgArch());
        ag.initAg();
        for (String f : files) {
            ag.setASLSrc(AGENTS.resolve(f).toString());
            ag.parseAS(AGENTS.resolve(f).toFile());
        }
        ((ProjectInclude) DirectiveProcessor.getDirective("include")).loaded();
        ag.addInitialBelsInBB();
        return ag;
    }

    /** The first answer to query, or null. */
    private static Unifier ask(Agent ag, String query) throws Exception {
        LogicalFormula f = ASSyntax.parseFormula(query);
        Iterator<Unifier> answers = f.logicalConsequence(ag, new Unifier());
        return answers.hasNext() ? answers.next() : null;
    }

    private static double number(Unifier u, String var) throws Exception {
        return ((NumberTerm) u.get(var)).solve();
    }

    @Test
    void composeTurnsTheSecondPoseIntoTheFirstOnesFrame() throws Exception {
        Agent ag = load("poses.asl");
        // 1 m ahead of a robot at (2, 3) facing +y is (2, 4)
        Unifier u = ask(ag, "compose(pose(2, 3, math.pi / 2), pose(1, 0, 0), pose(X, Y, T))");
        assertEquals(2.0, number(u, "X"), EPS);
        assertEquals(4.0, number(u, "Y"), EPS);
        assertEquals(Math.PI / 2, number(u, "T"), EPS);
        // 1 m to its left is (1, 3)
        u = ask(ag, "compose(pose(2, 3, math.pi / 2), pose(0, 1, 0), pose(X, Y, _))");
        assertEquals(1.0, number(u, "X"), EPS);
        assertEquals(3.0, number(u, "Y"), EPS);
    }

    @Test
    void aPoseComposedWithItsInverseIsTheOrigin() throws Exception {
        Agent ag = load("poses.asl");
        Unifier u = ask(ag, "inverse(pose(1.5, -0.7, 2.1), I) & compose(pose(1.5, -0.7, 2.1), I, pose(X, Y, T))");
        assertEquals(0.0, number(u, "X"), EPS);
        assertEquals(0.0, number(u, "Y"), EPS);
        assertEquals(0.0, number(u, "T"), EPS);
    }

    @Test
    void relativeSaysWhereAPoseIsSeenFromAnother() throws Exception {
        Agent ag = load("poses.asl");
        // seen from (1, 1) facing +y, the point (1, 3) is 2 m ahead
        Unifier u = ask(ag, "relative(pose(1, 1, math.pi / 2), pose(1, 3, 0), pose(F, L, _))");
        assertEquals(2.0, number(u, "F"), EPS);
        assertEquals(0.0, number(u, "L"), EPS);
        u = ask(ag, "distance(pose(0, 0, 0), pose(3, 4, 1), D)");
        assertEquals(5.0, number(u, "D"), EPS);
    }

    @Test
    void theMissionGoalIsOneMetreAheadOfTheStart() throws Exception {
        Agent ag = load("faulty.asl");
        ag.addBel(Literal.parseLiteral("missionStart(pose(0.5, -1, " + (-Math.PI / 2) + "))"));
        Unifier u = ask(ag, "missionGoal(pose(X, Y, _))");
        assertEquals(0.5, number(u, "X"), EPS);
        assertEquals(-2.0, number(u, "Y"), EPS);
    }

    @Test
    void theCurvatureSeenIsTheHeadingChangeOverTheDistance() throws Exception {
        Agent ag = load("faulty.asl");
        // seen straight ahead at 1.5 m, then 0.2 m further, having turned 23 degrees clockwise
        ag.addBel(Literal.parseLiteral("seenMove(0, 1.5, 10, 0, 1.7, 33)"));
        Unifier u = ask(ag, "curvatureSeen(K)");
        assertEquals(Math.toRadians(23) / 0.2, number(u, "K"), 1e-6);
    }

    @Test
    void noCurvatureFromAMoveTooShortToMeasure() throws Exception {
        Agent ag = load("faulty.asl");
        ag.addBel(Literal.parseLiteral("seenMove(0, 1.5, 10, 0, 1.51, 33)"));
        assertEquals(null, ask(ag, "curvatureSeen(K)"));
    }

    @Test
    void eachProposalOrRefusalIsOneAnswer() throws Exception {
        Agent ag = load("faulty.asl");
        String task = "reach(faulty, 1, 0)";
        assertTrue(ask(ag, ".count(answer(" + task + ", _), 0)") != null);
        ag.addBel(Literal.parseLiteral("propose(" + task + ", 2.5)[source(helper)]"));
        ag.addBel(Literal.parseLiteral("refuse(" + task + ")[source(scout)]"));
        assertTrue(ask(ag, ".count(answer(" + task + ", _), 2)") != null);
        assertFalse(ask(ag, ".count(answer(reach(faulty, 2, 0), _), 0)") == null);
    }

    @Test
    void theHelperTellsWhichSideOfTheRobotItIsOnForItsDetour() throws Exception {
        Agent ag = load("helper.asl");
        assertEquals(1.0, number(ask(ag, "signOf(0.3, S)"), "S"), EPS);
        assertEquals(-1.0, number(ask(ag, "signOf(-0.3, S)"), "S"), EPS);
    }
}
