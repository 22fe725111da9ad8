package rason.messaging;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Set;

import org.junit.jupiter.api.Test;

import rason.messaging.TrustPolicy.Group;
import rason.messaging.TrustPolicy.Rule;

class TrustPolicyTest {

    @Test
    void byDefaultOtherRobotsMayTellAskAndAchieveButNotTouchPlans() {
        TrustPolicy p = new TrustPolicy();
        for (String perf : new String[] { "tell", "untell", "signal", "achieve", "unachieve", "askOne", "askAll",
                "myOwnPerformative" })
            assertTrue(p.allows("alice", "bob", perf), perf);
        for (String perf : new String[] { "tellHow", "untellHow", "askHow" })
            assertFalse(p.allows("alice", "bob", perf), perf);
    }

    @Test
    void performativesFallInTheirGroups() {
        assertEquals(Group.TELL, Group.of("untell"));
        assertEquals(Group.ACHIEVE, Group.of("unachieve"));
        assertEquals(Group.ASK, Group.of("askAll"));
        assertEquals(Group.ASK_HOW, Group.of("askHow"));
        assertEquals(Group.TELL_HOW, Group.of("untellHow"));
        assertEquals(Group.OTHER, Group.of("cfp"));
        assertEquals("trust_tellHow", Group.TELL_HOW.option());
        assertEquals(Group.ASK_HOW, Group.byKey("askHow"));
    }

    @Test
    void rulesParseAllNoneAndNamesInAnyOfTheirSpellings() {
        assertEquals(Rule.ALL, Rule.parse("all"));
        assertEquals(Rule.ALL, Rule.parse("\"ALL\""));
        assertEquals(Rule.NONE, Rule.parse("none"));
        assertEquals(Rule.NONE, Rule.parse("[]"));
        assertEquals(Set.of("faulty", "helper"), Rule.parse("\"[faulty, helper]\"").names());
        assertEquals(Set.of("faulty", "helper"), Rule.parse("faulty helper").names());
        assertEquals("faulty, helper", Rule.parse("helper,faulty").toString());
        Rule r = Rule.parse("faulty");
        assertTrue(r.allows("faulty"));
        assertFalse(r.allows("helper"));
    }

    @Test
    void aRuleThatIsNotNamesIsRefusedSayingWhy() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> Rule.parse("faulty, Bad"));
        assertTrue(e.getMessage().contains("'Bad'"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> Rule.parse("source(x)"));
        IllegalArgumentException g = assertThrows(IllegalArgumentException.class, () -> Group.byKey("tellhow"));
        assertTrue(g.getMessage().contains("tellHow"), "names the groups there are: " + g.getMessage());
    }

    @Test
    void theAgentsParameterBeatsItsProgramWhichBeatsTheParameterForEveryAgent() {
        TrustPolicy p = new TrustPolicy();
        p.setParameterRule(TrustPolicy.EVERY_AGENT, Group.TELL_HOW, Rule.ALL);
        assertTrue(p.allows("alice", "mallory", "tellHow"), "'*' applies to every agent");
        p.setProgramRule("alice", Group.TELL_HOW, Rule.parse("carol"));
        assertTrue(p.allows("alice", "carol", "tellHow"));
        assertFalse(p.allows("alice", "mallory", "tellHow"), "the .mas2j option beats '*'");
        assertTrue(p.allows("bob", "mallory", "tellHow"), "other agents keep '*'");
        p.setParameterRule("alice", Group.TELL_HOW, Rule.NONE);
        assertFalse(p.allows("alice", "carol", "tellHow"), "the agent's parameter beats its .mas2j option");
        assertEquals(Rule.NONE, p.rule("alice", Group.TELL_HOW));
        p.forgetProgram("alice");
        assertEquals(Rule.NONE, p.rule("alice", Group.TELL_HOW));
    }

    @Test
    void aRuleForOneGroupLeavesTheOthersAlone() {
        TrustPolicy p = new TrustPolicy();
        p.setProgramRule("alice", Group.ACHIEVE, Rule.parse("carol"));
        assertFalse(p.allows("alice", "bob", "achieve"));
        assertFalse(p.allows("alice", "bob", "unachieve"));
        assertTrue(p.allows("alice", "bob", "tell"));
        assertFalse(p.allows("alice", "carol", "askHow"));
    }
}
