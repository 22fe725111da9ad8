package rason.messaging;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class SentAsksTest {

    @Test
    void onlyTheAskedAgentAnswersAndOnlyOnce() {
        SentAsks asks = new SentAsks();
        asks.sent("mid7", "carol");
        assertFalse(asks.answeredBy("mid7", "mallory"), "someone else claiming to answer");
        assertFalse(asks.answeredBy("mid8", "carol"), "an id we never sent");
        assertFalse(asks.answeredBy("", "carol"));
        assertFalse(asks.answeredBy(null, "carol"));
        assertTrue(asks.answeredBy("mid7", "carol"));
        assertFalse(asks.answeredBy("mid7", "carol"), "a second answer is no answer");
    }

    @Test
    void aBroadcastAskIsAnsweredByAnyone() {
        SentAsks asks = new SentAsks();
        asks.sent("mid1", "");
        assertTrue(asks.answeredBy("mid1", "carol"));
        assertTrue(asks.answeredBy("mid1", "dave"));
    }

    @Test
    void theOldestAsksAreForgottenFirst() {
        SentAsks asks = new SentAsks(3);
        for (int i = 1; i <= 5; i++)
            asks.sent("mid" + i, "carol");
        assertEquals(3, asks.size());
        assertFalse(asks.answeredBy("mid1", "carol"));
        assertFalse(asks.answeredBy("mid2", "carol"));
        assertTrue(asks.answeredBy("mid5", "carol"));
    }
}
