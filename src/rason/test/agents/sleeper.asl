/* Plans */

// the test publishes the percept go once it listens to rosout; it also drives /clock
+go <- !nap.

+!nap <- .print("asleep"); .wait(2000); .print("awake"); .wait(ready, 1000); .print("ready").
-!nap[error(wait_timeout)] <- .print("gave up waiting").
