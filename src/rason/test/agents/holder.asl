/* Plans */

// the test publishes the percept go once it listens to rosout
+go <- !hold.

+!hold <- .print("holding"); hold(1); .print("hold finished").
-!hold[timeout] <- .print("hold timed out").
-!hold[no_decomposer] <- .print("hold has no decomposer").
-!hold[shutdown] <- .print("hold stopped by shutdown").
-!hold[R|Rest] <- .print("hold failed ", [R|Rest]).
