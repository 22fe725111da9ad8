/* A scout that greets the scouts of other robots as they come and go:
   presence, achieve and askOne between rason_mas processes. */

/* Initial beliefs and rules */

battery(90).

// a scout of another robot (same program, other prefix)
other_scout(A) :- .my_name(Me) & A \== Me & .substring("scout", A).

/* Plans */

// the bridge keeps present(Name) for every reachable agent
+present(A) : other_scout(A) <- .print(A, " joined"); .my_name(Me); .send(A, achieve, greet(Me)).
-present(A) : other_scout(A) <- .print(A, " left").

// another robot's scout asks to be greeted; source(S) is that scout
+!greet(_)[source(S)] <- .send(S, askOne, battery(_), battery(B)); .print(S, " says hello; its battery is at ", B).
-!greet(_)[source(S), error(E)] <- .print("could not greet ", S, ": ", E).
