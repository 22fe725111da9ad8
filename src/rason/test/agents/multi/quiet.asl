/* A test agent that takes no commands (it shares a robot with one that does): it only
   prints what other agents tell it and ask of it, so the test reads that on rosout. */
+hello(X)[source(S)] <- .print("told hello(", X, ") by ", S).
+!greet(X)[source(S)] <- .print("asked to greet ", X, " by ", S).
+herald::news(X)[source(S)] <- .print("herald::news ", X, " from ", S).
+bulletin(X)[source(S)] <- .print("bulletin ", X, " from ", S).
