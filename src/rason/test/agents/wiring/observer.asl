// Test agent of the synthesizer rostest: prints what generic_synthesizer makes it perceive.

+pos(X, Y, Yaw) <- .print("pos ", X, " ", Y, " ", Yaw).
+moving <- .print("moving").
-moving <- .print("still").
+battery(P) <- .print("battery ", P).
+battery_low <- .print("battery low").
