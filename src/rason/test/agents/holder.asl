/* Plans */

// the test publishes the percept go once it listens to rosout
+go <- !hold.

// the agent notes the bridge's clock around the action, so a test can time the
// timeout as the bridge does, whatever the load on rosout
+!hold <- rason.ros_time_ms(T0); +holdingSince(T0); .print("holding"); hold(1); .print("hold finished").
-!hold[timeout] <- ?holdingSince(T0); rason.ros_time_ms(T1); .print("hold timed out after ", T1 - T0, " ms").
-!hold[no_decomposer] <- .print("hold has no decomposer").
-!hold[shutdown] <- .print("hold stopped by shutdown").
-!hold[R|Rest] <- .print("hold failed ", [R|Rest]).
