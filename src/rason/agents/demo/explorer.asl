// A small example agent: drives a square with the motion decomposer's move/turn
// actions, handles their failures, reports what its synthesizer perceives, then stops.

/* Initial goals */
!explore.

/* Plans */

+!explore <- .print("driving a square of 1 m sides"); !legs(4).

// one leg: move, then turn right; a failed action fails the leg (see -!legs)
+!legs(0) <- .print("square done"); !report.
+!legs(N) <- move(1); turn(90); .print("leg ", 5 - N, " done"); !legs(N - 1).

// the decomposer's reason (no_progress, bad_move, ...) is among the annotations
-!legs(N)[R | Rest] : .member(Reason, [no_progress, bad_move, timeout, no_decomposer]) & .member(Reason, [R | Rest])
<- .print("leg failed: ", Reason); !report.

+!report : robot(Name, Angle, Depth, _)
<- .print("I can see ", Name, " at ", Angle, " degrees and ", Depth, " m"); .stopMAS.
+!report <- .print("I see no robot"); .stopMAS.

// perceptions from the vision synthesizer come and go as the robot turns
+robot(Name, _, _, _)[source(percept)] <- .print(Name, " came into view").
