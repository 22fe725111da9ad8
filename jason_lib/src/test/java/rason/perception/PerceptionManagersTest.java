package rason.perception;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.NullSource;
import org.junit.jupiter.params.provider.ValueSource;

import jason.runtime.Settings;

class PerceptionManagersTest {

    // an empty column is an option the agent does not give (null)
    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
            "                                      |     |         | per_source",
            "accumulate                            |     |         | accumulate",
            "per_source                            | 5   |         | rate_limit(5.0/s) over per_source",
            "                                      |     | robot/4 | selective[robot/4] over per_source",
            "rason.perception.AccumulatePerception | 2.5 | a/1     | selective[a/1] over rate_limit(2.5/s) over accumulate",
            "rason.perception.PluginPerception     | 2   | a/1     | selective[a/1] over rate_limit(2.0/s) over plugin",
    })
    void chainFromOptions(String manager, String rate, String perceive, String expected) {
        assertEquals(expected, PerceptionManagers.forAgent(manager, rate, perceive, "per_source").toString());
    }

    @Test
    void defaultStrategyAppliesWhenTheAgentNamesNone() {
        assertEquals("accumulate", PerceptionManagers.forAgent(null, null, null, "accumulate").toString());
    }

    @Test
    void chainFromTheAgentsSettings() {
        Settings settings = new Settings();
        settings.getUserParameters().put(PerceptionManagers.PERCEIVE_OPTION, "\"robot/4\"");
        settings.getUserParameters().put(PerceptionManagers.RATE_OPTION, "5");
        assertEquals("selective[robot/4] over rate_limit(5.0/s) over accumulate",
                PerceptionManagers.forAgent(settings, "accumulate").toString());
    }

    @ParameterizedTest
    @NullSource
    @ValueSource(strings = { "", "   " })
    void noNameIsPerSource(String spec) {
        assertInstanceOf(PerSourcePerception.class, PerceptionManagers.create(spec));
    }

    @Test
    void namesMayBeSurroundedBySpaces() {
        assertInstanceOf(AccumulatePerception.class, PerceptionManagers.create(" accumulate "));
        assertInstanceOf(PluginPerception.class, PerceptionManagers.create(" rason.perception.PluginPerception "));
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', quoteCharacter = '"', value = {
            "fancy                                  |       |       | perception_manager | perception_manager: perception manager 'fancy' is neither",
            "java.lang.String                       |       |       | perception_manager | does not implement rason.perception.PerceptionManager",
            "rason.perception.RateLimitedPerception |       |       | perception_manager | public constructor without arguments",
            "                                       | fast  |       | perception_rate    | perception_rate: 'fast' is not a number",
            "                                       | 0     |       | perception_rate    | perception_rate: a perception rate must be a positive",
            "                                       |       | robot | perceive           | perceive: 'robot' is not functor/arity",
    })
    void badOptionsAreRefusedWithTheOptionNamed(String manager, String rate, String perceive, String option, String why) {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> PerceptionManagers.forAgent(manager, rate, perceive, "per_source"));
        assertTrue(e.getMessage().contains(why), e.getMessage());
        assertTrue(e.getMessage().startsWith(option + ": "), e.getMessage());
    }
}
