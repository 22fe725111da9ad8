// Test agent of the wiring rostest. The test commands it with the percept cmd(Id, Command)
// and reads "Id ok" or "Id failed [reasons]"; drive(X, Y) and stop start and take back a goal.

/* Plans */

+cmd(N, C) <- !run(N, C).
+!run(N, C) <- !act(C); .print(N, " ok").
-!run(N, C)[R | Rest] <- .print(N, " failed ", [R | Rest]).

+!act(say(T)) <- say(T).
+!act(light(S)) <- light(S).
+!act(reset) <- reset.
+!act(calibrate) <- calibrate.
+!act(explode) <- explode.
+!act(goto(X, Y)) <- goto(X, Y).
+!act(dock) <- dock.
// a slow service call in an intention of its own while another action goes on
+!act(say_during_pause) <- !!pause; say("during pause").
+!pause <- pause; .print("pause over").

// a goal the test takes back
+drive(X, Y) <- !drive(X, Y).
+!drive(X, Y) <- goto(X, Y); .print("drive arrived").
-!drive(X, Y)[R | Rest] <- .print("drive failed ", [R | Rest]).
+stop <- .drop_intention(drive(_, _)); .print("drive dropped").

// the goal's feedback, as the generic decomposer publishes it
+at(X, Y) <- .print("at ", X, " ", Y).
-at(_, _) : not at(_, _) <- .print("no position").
