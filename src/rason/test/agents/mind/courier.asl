/* Initial beliefs */
charge(90).

/* Plans */

// the test answers deliver(P) as the robot would, and sends go(P) percepts
+go(P) <- !deliver(P).
+!deliver(P) <- !carry(P); +delivered(P); .print("delivered ", P).
+!carry(P) <- deliver(P).
-!deliver(P)[error(R)] <- +failed(P, R).

// started with this goal (courier_waiting.mas2j), it waits, as an intention, for a parcel
+!awaitParcel <- .wait({+go(_)}).
