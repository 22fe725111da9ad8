/* The agent under hostile input (hostile_input rostest): answers pings with an action and
   says when the answer to it came back, and prints what it comes to believe, so the test
   sees what was kept and what was refused. */

+ping(N)[source(percept)] <- pong(N); .print("pong ", N, " done").

+kept(X)[source(percept)] <- .print("kept ", X).

// a perception must never make the agent believe someone said something
+said(N)[source(S)] <- .print("said ", N, " from ", S).
